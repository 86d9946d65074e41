/* ----------------------------------------------------------------------
   hsrod - fix hele_shaw/drag: its keywords (see fix_hele_shaw_drag.h)

   fix ID group hele_shaw/drag keyword values ...
     channel L W H       channel size [m] (default: the box)
     origin x0 y0 z0     lower corner: inlet plane, side wall, lower gap wall [m] (default: box lo)
     pore R x            pore constriction: z-cylinders of radius R on both side walls at x [m]
     cylinder x y R      any other z-cylinder obstacle [m] (repeatable)
     viscosity mu        [Pa s], in [1e-6, 1e8] (default 1e-3)
     fluid_density rho   [kg/m3] (default 1000)
     mean_velocity U | flow_rate Q | reynolds Re    inflow (one required)
     model NAME|auto     a registered model (hydro/model_registry.h) or auto (default auto)
     window_cells c      twoway: grid cells per sphere diameter (default 4)
     window_reflection_cells c  twoway: cells per diameter of the window that carries the walls' reflection,
                         [1, window_cells] (default min(2, window_cells); window_cells: one scale)
     window_margin m     twoway: window reach beyond the rod [m] (default auto)
     window_fine m       twoway: reach of the window's fine zone beyond the rod [m] (default auto)
     window_grading g    twoway: growth ratio of the cells beyond the fine zone, (1, 2] (default 1.2 with one scale, 1.4 with two)
     window_update s     twoway: re-solve after a sphere moved s [m] (default d/2)
     window_every k      twoway: re-solve at least every k steps (default 0: by distance only)
     tolerance t         auto: accepted relative deflection error (default 0.01)
     coefficients file   confinement coefficient table (default: built-in)
     section S           spheres per rod cross-section (default 1)
     inertia yes|no      gap-averaged inertia in the background flow (default no)
     timestep_check yes|no  explicit mode: refuse dt above the drag limit (default yes)
     placement_check yes|no at each run's start refuse spheres outside the fluid (default yes)
     memory_limit B      largest dense level-3 model [bytes] (default 2e9)
------------------------------------------------------------------------- */

#include "fix_hele_shaw_drag.h"

#include "domain.h"
#include "error.h"
#include "keyword_parsing.h"

#include "hydro/rod_hydrodynamics.h"

#include <cstdio>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;

namespace {
const char *const kStyle = "fix hele_shaw/drag";
constexpr double kLowestViscosity = 1e-6;  // [Pa s], below any gas
constexpr double kHighestViscosity = 1e8;  // [Pa s], above any melt the model is meant for

// Gases ~1e-5, water 1e-3, glycerol 1.4, polymer melts up to ~1e6 Pa s:
// outside this range the drag over- or underflows the bonds.
double viscosity_in_range(LAMMPS_NS::Error *error, double viscosity) {
  if (!(viscosity >= kLowestViscosity && viscosity <= kHighestViscosity)) {
    char msg[256];
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: viscosity must be in [%g, %g] Pa s (got %g)",
                  kLowestViscosity, kHighestViscosity, viscosity);
    error->all(FLERR, msg);
  }
  return viscosity;
}
}

void FixHeleShawDrag::parse_keywords(int narg, char **arg, hsrod::SceneSpec &scene, hsrod::ModelSpec &model) {
  scene.length = domain->boxhi[0] - domain->boxlo[0];
  scene.width = domain->boxhi[1] - domain->boxlo[1];
  scene.gap_height = domain->boxhi[2] - domain->boxlo[2];
  scene.origin = Eigen::Vector3d(domain->boxlo[0], domain->boxlo[1], domain->boxlo[2]);
  scene.fluid.dynamic_viscosity = 1e-3;
  scene.fluid.density = 1000.0;
  bool have_inflow = false;

  int iarg = 3;
  auto need = [&](int n) {
    if (iarg + n >= narg) {
      char msg[256];
      std::snprintf(msg, sizeof(msg), "Illegal fix hele_shaw/drag command: keyword %s needs %d value(s)", arg[iarg], n);
      error->all(FLERR, msg);
    }
  };
  auto number = [&](int k) { return parse_number(error, kStyle, arg[iarg], arg[iarg + k]); };
  auto positive = [&](const char *key, double value, const char *unit) {
    if (!(value > 0.0)) {
      char msg[128];
      std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: %s must be > 0%s", key, unit);
      error->all(FLERR, msg);
    }
    return value;
  };
  while (iarg < narg) {
    const char *key = arg[iarg];
    int values = 1;
    if (strcmp(key, "channel") == 0) {
      need(values = 3);
      scene.length = number(1);
      scene.width = number(2);
      scene.gap_height = number(3);
    } else if (strcmp(key, "origin") == 0) {
      need(values = 3);
      scene.origin = Eigen::Vector3d(number(1), number(2), number(3));
    } else if (strcmp(key, "pore") == 0) {
      need(values = 2);
      scene.pore_radius = positive("pore radius R", number(1), " m (and < W/2)");
      scene.pore_x = number(2);
    } else if (strcmp(key, "cylinder") == 0) {
      need(values = 3);
      scene.cylinders.push_back({number(1), number(2), number(3)});
    } else if (strcmp(key, "viscosity") == 0) {
      need(1);
      scene.fluid.dynamic_viscosity = viscosity_in_range(error, number(1));
    } else if (strcmp(key, "fluid_density") == 0) {
      need(1);
      scene.fluid.density = positive(key, number(1), " kg/m3");
    } else if (strcmp(key, "mean_velocity") == 0 || strcmp(key, "flow_rate") == 0 || strcmp(key, "reynolds") == 0) {
      need(1);
      if (have_inflow) error->all(FLERR, "fix hele_shaw/drag: give only one of mean_velocity, flow_rate, reynolds");
      have_inflow = true;
      using Kind = hsrod::SceneSpec::InflowKind;
      scene.inflow_kind = strcmp(key, "mean_velocity") == 0 ? Kind::mean_velocity
                          : strcmp(key, "flow_rate") == 0   ? Kind::flow_rate
                                                            : Kind::reynolds;
      scene.inflow_value = positive(key, number(1), "");
    } else if (strcmp(key, "model") == 0) {
      need(1);
      model.name = arg[iarg + 1];
      if (model.name != "auto" && !hsrod::find_model(model.name)) {
        char msg[256];
        std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: unknown model '%s' (expected %s)", model.name.c_str(),
                      hsrod::valid_model_names("auto").c_str());
        error->all(FLERR, msg);
      }
    } else if (strcmp(key, "window_cells") == 0) {
      need(1);
      model.options.window.cells_per_diameter = number(1);
      const double cells = model.options.window.cells_per_diameter;
      if (!(cells >= 2.0 && cells <= 16.0))
        error->all(FLERR, "fix hele_shaw/drag: window_cells must be in [2, 16] cells per sphere diameter");
    } else if (strcmp(key, "window_reflection_cells") == 0) {
      need(1);
      model.options.window.reflection_cells_per_diameter = number(1);
      const double cells = model.options.window.reflection_cells_per_diameter;
      if (!(cells >= 1.0 && cells <= 16.0))
        error->all(FLERR, "fix hele_shaw/drag: window_reflection_cells must be in [1, window_cells] cells per sphere diameter");
    } else if (strcmp(key, "window_margin") == 0) {
      need(1);
      model.options.window.margin = positive(key, number(1), " m");
    } else if (strcmp(key, "window_fine") == 0) {
      need(1);
      model.options.window.fine_margin = positive(key, number(1), " m");
    } else if (strcmp(key, "window_grading") == 0) {
      need(1);
      model.options.window.grading = number(1);
      const double ratio = model.options.window.grading;
      if (!(ratio > 1.0 && ratio <= 2.0))
        error->all(FLERR, "fix hele_shaw/drag: window_grading must be in (1, 2] (cell growth ratio)");
    } else if (strcmp(key, "window_update") == 0) {
      need(1);
      model.options.window.update_distance = positive(key, number(1), " m");
    } else if (strcmp(key, "window_every") == 0) {
      need(1);
      model.options.window.update_every = parse_integer(error, kStyle, key, arg[iarg + 1]);
      if (model.options.window.update_every < 0)
        error->all(FLERR, "fix hele_shaw/drag: window_every must be >= 0 steps");
    } else if (strcmp(key, "tolerance") == 0) {
      need(1);
      model.tolerance = number(1);
      if (!(model.tolerance > 0.0 && model.tolerance < 1.0))
        error->all(FLERR, "fix hele_shaw/drag: tolerance must be in (0, 1)");
    } else if (strcmp(key, "coefficients") == 0) {
      need(1);
      model.coefficients_file = arg[iarg + 1];
    } else if (strcmp(key, "section") == 0) {
      need(1);
      model.spheres_per_section = parse_integer(error, kStyle, key, arg[iarg + 1]);
      if (model.spheres_per_section < 1) error->all(FLERR, "fix hele_shaw/drag: section must be >= 1");
    } else if (strcmp(key, "inertia") == 0) {
      need(1);
      scene.inertia = parse_yes_no(error, kStyle, key, arg[iarg + 1]);
    } else if (strcmp(key, "timestep_check") == 0) {
      need(1);
      timestep_check_ = parse_yes_no(error, kStyle, key, arg[iarg + 1]);
    } else if (strcmp(key, "placement_check") == 0) {
      need(1);
      placement_check_ = parse_yes_no(error, kStyle, key, arg[iarg + 1]);
    } else if (strcmp(key, "memory_limit") == 0) {
      need(1);
      model.limits.dense_memory_bytes = positive(key, number(1), " bytes");
    } else {
      char msg[512];
      std::snprintf(msg, sizeof(msg),
                    "Illegal fix hele_shaw/drag command: unknown keyword '%s' (expected channel, origin, pore, "
                    "cylinder, viscosity, fluid_density, mean_velocity, flow_rate, reynolds, model, tolerance, "
                    "coefficients, section, inertia, timestep_check, placement_check, memory_limit, window_cells, "
                    "window_reflection_cells, window_margin, window_fine, window_grading, window_update, window_every)", key);
      error->all(FLERR, msg);
    }
    iarg += 1 + values;
  }
  if (model.options.window.reflection_cells_per_diameter > model.options.window.cells_per_diameter)
    error->all(FLERR, "fix hele_shaw/drag: window_reflection_cells must be in [1, window_cells] cells per sphere diameter");
  if (!have_inflow)
    error->all(FLERR, "Illegal fix hele_shaw/drag command: missing inflow (mean_velocity, flow_rate or reynolds)");
  if (scene.pore_radius > 0.0 && !(scene.pore_radius < 0.5 * scene.width)) {
    char msg[256];
    std::snprintf(msg, sizeof(msg),
                  "fix hele_shaw/drag: pore radius R = %g m must be in (0, W/2) = (0, %g) m (the pore must stay open)",
                  scene.pore_radius, 0.5 * scene.width);
    error->all(FLERR, msg);
  }
}

/* ----------------------------------------------------------------------
   hsrod - fix hele_shaw/drag: its keywords (see fix_hele_shaw_drag.h)

   fix ID group hele_shaw/drag keyword values ...
     channel L W H       channel size [m] (default: the box)
     origin x0 y0 z0     lower corner: inlet plane, side wall, lower gap wall [m] (default: box lo)
     pore R x            pore constriction: z-cylinders of radius R on both side walls at x [m]
     cylinder x y R      any other z-cylinder obstacle [m] (repeatable)
     pillars R x0 x1 sx sy eps  tilted (DLD) pillar array: radius, x-range of the columns, column and
                         pillar spacings [m], row shift eps = lateral shift per column / sy in [0, 1)
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
     wall_reflection none|images|reflections  nonlocal: the walls' images (first, or with their
                         multiple reflections) in the coupling, with the near-wall law fitted on
                         top of them (hydro/wall_images.h; default none)
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

// One keyword at arg[iarg] and its values, read with the fix's checks.
struct Keyword {
  Error *error;
  int narg;
  char **arg;
  int iarg;

  bool is(const char *name) const { return strcmp(arg[iarg], name) == 0; }
  void need(int n) const {
    if (iarg + n >= narg) {
      char msg[256];
      std::snprintf(msg, sizeof(msg), "Illegal fix hele_shaw/drag command: keyword %s needs %d value(s)", arg[iarg], n);
      error->all(FLERR, msg);
    }
  }
  double number(int k) const { return parse_number(error, kStyle, arg[iarg], arg[iarg + k]); }
  double positive(const char *key, double value, const char *unit) const {
    if (!(value > 0.0)) {
      char msg[128];
      std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: %s must be > 0%s", key, unit);
      error->all(FLERR, msg);
    }
    return value;
  }
};

// Each group below reads its own keywords and returns how many values the
// keyword took, or 0 for a keyword of another group.

// The channel, its obstacles, the fluid and the inflow.
int scene_keyword(const Keyword &k, hsrod::SceneSpec &scene, bool &have_inflow) {
  const char *key = k.arg[k.iarg];
  int values = 1;
  if (k.is("channel")) {
    k.need(values = 3);
    scene.length = k.number(1);
    scene.width = k.number(2);
    scene.gap_height = k.number(3);
  } else if (k.is("origin")) {
    k.need(values = 3);
    scene.origin = Eigen::Vector3d(k.number(1), k.number(2), k.number(3));
  } else if (k.is("pore")) {
    k.need(values = 2);
    scene.pore_radius = k.positive("pore radius R", k.number(1), " m (and < W/2)");
    scene.pore_x = k.number(2);
  } else if (k.is("cylinder")) {
    k.need(values = 3);
    scene.cylinders.push_back({k.number(1), k.number(2), k.number(3)});
  } else if (k.is("pillars")) {
    k.need(values = 6);
    if (scene.pillars.radius > 0.0) k.error->all(FLERR, "fix hele_shaw/drag: pillars may be given only once");
    scene.pillars.radius = k.positive("pillars radius R", k.number(1), " m");
    scene.pillars.x_first = k.number(2);
    scene.pillars.x_last = k.number(3);
    scene.pillars.spacing_x = k.number(4);
    scene.pillars.spacing_y = k.number(5);
    scene.pillars.row_shift = k.number(6);
  } else if (k.is("viscosity")) {
    k.need(1);
    scene.fluid.dynamic_viscosity = viscosity_in_range(k.error, k.number(1));
  } else if (k.is("fluid_density")) {
    k.need(1);
    scene.fluid.density = k.positive(key, k.number(1), " kg/m3");
  } else if (k.is("mean_velocity") || k.is("flow_rate") || k.is("reynolds")) {
    k.need(1);
    if (have_inflow) k.error->all(FLERR, "fix hele_shaw/drag: give only one of mean_velocity, flow_rate, reynolds");
    have_inflow = true;
    using Kind = hsrod::SceneSpec::InflowKind;
    scene.inflow_kind = strcmp(key, "mean_velocity") == 0 ? Kind::mean_velocity
                        : strcmp(key, "flow_rate") == 0   ? Kind::flow_rate
                                                          : Kind::reynolds;
    scene.inflow_value = k.positive(key, k.number(1), "");
  } else if (k.is("inertia")) {
    k.need(1);
    scene.inertia = parse_yes_no(k.error, kStyle, key, k.arg[k.iarg + 1]);
  } else {
    values = 0;
  }
  return values;
}

// The model, its table and its resources.
int model_keyword(const Keyword &k, hsrod::ModelSpec &model) {
  const char *key = k.arg[k.iarg];
  if (k.is("model")) {
    k.need(1);
    model.name = k.arg[k.iarg + 1];
    if (model.name != "auto" && !hsrod::find_model(model.name)) {
      char msg[256];
      std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: unknown model '%s' (expected %s)", model.name.c_str(),
                    hsrod::valid_model_names("auto").c_str());
      k.error->all(FLERR, msg);
    }
  } else if (k.is("tolerance")) {
    k.need(1);
    model.tolerance = k.number(1);
    if (!(model.tolerance > 0.0 && model.tolerance < 1.0))
      k.error->all(FLERR, "fix hele_shaw/drag: tolerance must be in (0, 1)");
  } else if (k.is("coefficients")) {
    k.need(1);
    model.coefficients_file = k.arg[k.iarg + 1];
  } else if (k.is("section")) {
    k.need(1);
    model.spheres_per_section = parse_integer(k.error, kStyle, key, k.arg[k.iarg + 1]);
    if (model.spheres_per_section < 1) k.error->all(FLERR, "fix hele_shaw/drag: section must be >= 1");
  } else if (k.is("memory_limit")) {
    k.need(1);
    model.limits.dense_memory_bytes = k.positive(key, k.number(1), " bytes");
  } else if (k.is("wall_reflection")) {
    k.need(1);
    const std::string value = k.arg[k.iarg + 1];
    if (value != "none" && value != "images" && value != "reflections")
      k.error->all(FLERR, "fix hele_shaw/drag: wall_reflection must be none, images or reflections");
    model.options.wall_reflection = hsrod::wall_reflection_from_name(value);
  } else {
    return 0;
  }
  return 1;
}

// Level 4's (twoway) flow window.
int window_keyword(const Keyword &k, hsrod::TwoWayWindowOptions &window) {
  const char *key = k.arg[k.iarg];
  if (k.is("window_cells")) {
    k.need(1);
    window.cells_per_diameter = k.number(1);
    const double cells = window.cells_per_diameter;
    if (!(cells >= 2.0 && cells <= 16.0))
      k.error->all(FLERR, "fix hele_shaw/drag: window_cells must be in [2, 16] cells per sphere diameter");
  } else if (k.is("window_reflection_cells")) {
    k.need(1);
    window.reflection_cells_per_diameter = k.number(1);
    const double cells = window.reflection_cells_per_diameter;
    if (!(cells >= 1.0 && cells <= 16.0))
      k.error->all(FLERR, "fix hele_shaw/drag: window_reflection_cells must be in [1, window_cells] cells per sphere diameter");
  } else if (k.is("window_margin")) {
    k.need(1);
    window.margin = k.positive(key, k.number(1), " m");
  } else if (k.is("window_fine")) {
    k.need(1);
    window.fine_margin = k.positive(key, k.number(1), " m");
  } else if (k.is("window_grading")) {
    k.need(1);
    window.grading = k.number(1);
    const double ratio = window.grading;
    if (!(ratio > 1.0 && ratio <= 2.0))
      k.error->all(FLERR, "fix hele_shaw/drag: window_grading must be in (1, 2] (cell growth ratio)");
  } else if (k.is("window_update")) {
    k.need(1);
    window.update_distance = k.positive(key, k.number(1), " m");
  } else if (k.is("window_every")) {
    k.need(1);
    window.update_every = parse_integer(k.error, kStyle, key, k.arg[k.iarg + 1]);
    if (window.update_every < 0)
      k.error->all(FLERR, "fix hele_shaw/drag: window_every must be >= 0 steps");
  } else {
    return 0;
  }
  return 1;
}

// The fix's own checks: yes|no.
int check_keyword(const Keyword &k, bool &timestep_check, bool &placement_check) {
  bool *flag = k.is("timestep_check") ? &timestep_check : k.is("placement_check") ? &placement_check : nullptr;
  if (!flag) return 0;
  k.need(1);
  *flag = parse_yes_no(k.error, kStyle, k.arg[k.iarg], k.arg[k.iarg + 1]);
  return 1;
}
}  // namespace

void FixHeleShawDrag::parse_keywords(int narg, char **arg, hsrod::SceneSpec &scene, hsrod::ModelSpec &model) {
  scene.length = domain->boxhi[0] - domain->boxlo[0];
  scene.width = domain->boxhi[1] - domain->boxlo[1];
  scene.gap_height = domain->boxhi[2] - domain->boxlo[2];
  scene.origin = Eigen::Vector3d(domain->boxlo[0], domain->boxlo[1], domain->boxlo[2]);
  scene.fluid.dynamic_viscosity = 1e-3;
  scene.fluid.density = 1000.0;
  bool have_inflow = false;

  for (int iarg = 3; iarg < narg;) {
    const Keyword k{error, narg, arg, iarg};
    int values = scene_keyword(k, scene, have_inflow);
    if (values == 0) values = model_keyword(k, model);
    if (values == 0) values = window_keyword(k, model.options.window);
    if (values == 0) values = check_keyword(k, timestep_check_, placement_check_);
    if (values == 0) {
      char msg[512];
      std::snprintf(msg, sizeof(msg),
                    "Illegal fix hele_shaw/drag command: unknown keyword '%s' (expected channel, origin, pore, "
                    "cylinder, pillars, viscosity, fluid_density, mean_velocity, flow_rate, reynolds, model, tolerance, "
                    "coefficients, section, inertia, timestep_check, placement_check, memory_limit, wall_reflection, "
                    "window_cells, "
                    "window_reflection_cells, window_margin, window_fine, window_grading, window_update, window_every)",
                    arg[iarg]);
      error->all(FLERR, msg);
    }
    iarg += 1 + values;
  }
  if (model.options.wall_reflection != hsrod::WallReflection::none && model.name != "nonlocal")
    error->all(FLERR, "fix hele_shaw/drag: wall_reflection images|reflections needs model nonlocal (level 4 carries the walls "
                      "in its window; levels 1-2 and auto have no coupling to reflect)");
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

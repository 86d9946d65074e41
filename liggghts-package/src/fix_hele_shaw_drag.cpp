/* ----------------------------------------------------------------------
   hsrod - fix hele_shaw/drag (see fix_hele_shaw_drag.h)

   fix ID group hele_shaw/drag keyword values ...
     channel L W H       channel size [m] (default: the box)
     origin x0 y0 z0     lower corner: inlet plane, side wall, lower gap wall [m] (default: box lo)
     pore R x            pore constriction: z-cylinders of radius R on both side walls at x [m]
     cylinder x y R      any other z-cylinder obstacle [m] (repeatable)
     viscosity mu        [Pa s] (default 1e-3)
     fluid_density rho   [kg/m3] (default 1000)
     mean_velocity U | flow_rate Q | reynolds Re    inflow (one required)
     model isotropic|local|nonlocal|twoway|auto   (default auto)
     window_cells c      twoway: grid cells per sphere diameter (default 3)
     window_margin m     twoway: window margin around the rod [m] (default auto)
     window_update s     twoway: re-solve after a sphere moved s [m] (default d/2)
     window_every k      twoway: re-solve at least every k steps (default 0: by distance only)
     tolerance t         auto: accepted relative deflection error (default 0.01)
     coefficients file   confinement coefficient table (default: built-in)
     section S           spheres per rod cross-section (default 1)
     inertia yes|no      gap-averaged inertia in the background flow (default no)
     timestep_check yes|no  explicit mode: refuse dt above the drag limit (default yes)
------------------------------------------------------------------------- */

#include "fix_hele_shaw_drag.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "keyword_parsing.h"
#include "memory.h"
#include "update.h"

#include "fix_rod_bonds.h"
#include "modify.h"
#include "rod_gather.h"

#include "flow/make_background_flow.h"
#include "geometry/channel_geometry.h"
#include "geometry/pore_constriction.h"
#include "hydro/hydrodynamic_model.h"

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

using namespace LAMMPS_NS;
using namespace FixConst;


FixHeleShawDrag::FixHeleShawDrag(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg),
      model_name_("auto"),
      viscosity_(1e-3),
      fluid_density_(1000.0),
      gap_bottom_(0.0),
      tolerance_(0.01),
      section_size_(1),
      applied_by_integrator_(false),
      hydro_force_(nullptr),
      force_flag_(0),
      timestep_check_(true),
      explicit_limit_(0.0),
      limit_reported_(false) {
  if (strcmp(update->unit_style, "si") != 0) error->all(FLERR, "fix hele_shaw/drag requires 'units si'");
  if (!atom->radius_flag || !atom->omega_flag || !atom->torque_flag || !atom->molecule_flag)
    error->all(FLERR, "fix hele_shaw/drag requires atom_style hybrid granular molecular");

  double length = domain->boxhi[0] - domain->boxlo[0];
  double width = domain->boxhi[1] - domain->boxlo[1];
  double gap = domain->boxhi[2] - domain->boxlo[2];
  double origin[3] = {domain->boxlo[0], domain->boxlo[1], domain->boxlo[2]};
  double pore_radius = -1.0, pore_x = 0.0;
  std::vector<hsrod::ZCylinder> cylinders;
  enum { NONE, MEAN, RATE, REYNOLDS } inflow_kind = NONE;
  double inflow_value = 0.0;
  bool inertia = false;


  int iarg = 3;
  auto need = [&](int n) {
    if (iarg + n >= narg) {
      char msg[256];
      std::snprintf(msg, sizeof(msg), "Illegal fix hele_shaw/drag command: keyword %s needs %d value(s)", arg[iarg], n);
      error->all(FLERR, msg);
    }
  };
  while (iarg < narg) {
    const char *key = arg[iarg];
    if (strcmp(key, "channel") == 0) {
      need(3);
      length = parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 1]);
      width = parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 2]);
      gap = parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 3]);
      iarg += 4;
    } else if (strcmp(key, "origin") == 0) {
      need(3);
      for (int a = 0; a < 3; a++) origin[a] = parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 1 + a]);
      iarg += 4;
    } else if (strcmp(key, "pore") == 0) {
      need(2);
      pore_radius = parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 1]);
      pore_x = parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 2]);
      iarg += 3;
    } else if (strcmp(key, "cylinder") == 0) {
      need(3);
      cylinders.push_back({parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 1]), parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 2]),
                           parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 3])});
      iarg += 4;
    } else if (strcmp(key, "viscosity") == 0) {
      need(1);
      viscosity_ = parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 1]);
      if (!(viscosity_ > 0.0)) error->all(FLERR, "fix hele_shaw/drag: viscosity must be > 0 Pa s");
      iarg += 2;
    } else if (strcmp(key, "fluid_density") == 0) {
      need(1);
      fluid_density_ = parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 1]);
      if (!(fluid_density_ > 0.0)) error->all(FLERR, "fix hele_shaw/drag: fluid_density must be > 0 kg/m3");
      iarg += 2;
    } else if (strcmp(key, "mean_velocity") == 0 || strcmp(key, "flow_rate") == 0 || strcmp(key, "reynolds") == 0) {
      need(1);
      if (inflow_kind != NONE)
        error->all(FLERR, "fix hele_shaw/drag: give only one of mean_velocity, flow_rate, reynolds");
      inflow_kind = key[0] == 'm' ? MEAN : (key[0] == 'f' ? RATE : REYNOLDS);
      inflow_value = parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 1]);
      if (!(inflow_value > 0.0)) {
        char msg[128];
        std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: %s must be > 0", key);
        error->all(FLERR, msg);
      }
      iarg += 2;
    } else if (strcmp(key, "model") == 0) {
      need(1);
      model_name_ = arg[iarg + 1];
      if (model_name_ != "auto" && model_name_ != "isotropic" && model_name_ != "local" && model_name_ != "nonlocal" &&
          model_name_ != "twoway") {
        char msg[256];
        std::snprintf(msg, sizeof(msg),
                      "fix hele_shaw/drag: unknown model '%s' (expected isotropic, local, nonlocal, twoway or auto)",
                      model_name_.c_str());
        error->all(FLERR, msg);
      }
      iarg += 2;
    } else if (strcmp(key, "window_cells") == 0) {
      need(1);
      window_.cells_per_diameter = parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 1]);
      if (!(window_.cells_per_diameter >= 2.0 && window_.cells_per_diameter <= 16.0))
        error->all(FLERR, "fix hele_shaw/drag: window_cells must be in [2, 16] cells per sphere diameter");
      iarg += 2;
    } else if (strcmp(key, "window_margin") == 0 || strcmp(key, "window_update") == 0) {
      need(1);
      const double value = parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 1]);
      if (!(value > 0.0)) {
        char msg[128];
        std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: %s must be > 0 m", key);
        error->all(FLERR, msg);
      }
      if (key[7] == 'm') window_.margin = value;
      else window_.update_distance = value;
      iarg += 2;
    } else if (strcmp(key, "window_every") == 0) {
      need(1);
      window_.update_every = parse_integer(error, "fix hele_shaw/drag", key, arg[iarg + 1]);
      if (window_.update_every < 0) error->all(FLERR, "fix hele_shaw/drag: window_every must be >= 0 steps");
      iarg += 2;
    } else if (strcmp(key, "tolerance") == 0) {
      need(1);
      tolerance_ = parse_number(error, "fix hele_shaw/drag", key, arg[iarg + 1]);
      if (!(tolerance_ > 0.0 && tolerance_ < 1.0)) error->all(FLERR, "fix hele_shaw/drag: tolerance must be in (0, 1)");
      iarg += 2;
    } else if (strcmp(key, "coefficients") == 0) {
      need(1);
      coefficients_file_ = arg[iarg + 1];
      iarg += 2;
    } else if (strcmp(key, "section") == 0) {
      need(1);
      section_size_ = parse_integer(error, "fix hele_shaw/drag", key, arg[iarg + 1]);
      if (section_size_ < 1) error->all(FLERR, "fix hele_shaw/drag: section must be >= 1");
      iarg += 2;
    } else if (strcmp(key, "inertia") == 0 || strcmp(key, "timestep_check") == 0) {
      need(1);
      const bool yes = parse_yes_no(error, "fix hele_shaw/drag", key, arg[iarg + 1]);
      if (key[0] == 'i') inertia = yes;
      else timestep_check_ = yes;
      iarg += 2;
    } else {
      char msg[512];
      std::snprintf(msg, sizeof(msg),
                    "Illegal fix hele_shaw/drag command: unknown keyword '%s' (expected channel, origin, pore, "
                    "cylinder, viscosity, fluid_density, mean_velocity, flow_rate, reynolds, model, tolerance, "
                    "coefficients, section, inertia, timestep_check, window_cells, window_margin, window_update, "
                    "window_every)", key);
      error->all(FLERR, msg);
    }
  }
  if (inflow_kind == NONE)
    error->all(FLERR, "Illegal fix hele_shaw/drag command: missing inflow (mean_velocity, flow_rate or reynolds)");

  gap_bottom_ = origin[2];
  try {
    if (pore_radius >= 0.0) {
      auto pore = hsrod::make_pore_constriction(length, width, gap, pore_radius, pore_x, origin[0], origin[1]);
      for (const auto &c : pore.cylinders()) cylinders.push_back(c);
    }
    geometry_.reset(new hsrod::ChannelGeometry(length, width, gap, origin[0], origin[1], cylinders));
    const hsrod::FluidProperties fluid{viscosity_, fluid_density_};
    hsrod::Inflow inflow = hsrod::Inflow::mean_velocity(1.0);
    if (inflow_kind == MEAN) inflow = hsrod::Inflow::mean_velocity(inflow_value);
    else if (inflow_kind == RATE) inflow = hsrod::Inflow::flow_rate(inflow_value);
    else inflow = hsrod::Inflow::mean_velocity(hsrod::mean_velocity_for_channel_reynolds(inflow_value, *geometry_, fluid));
    hsrod::BackgroundFlowOptions options;
    options.grid.include_inertia = inertia;
    flow_ = hsrod::make_background_flow(*geometry_, fluid, inflow, options);
  } catch (const std::exception &e) {
    char msg[512];
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: %s", e.what());
    error->all(FLERR, msg);
  }
  if (comm->me == 0) {
    char msg[512];
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: background flow: %s\n", flow_->description().c_str());
    if (screen) fputs(msg, screen);
    if (logfile) fputs(msg, logfile);
  }

  vector_flag = 1;
  size_vector = 4;  // total hydrodynamic force x y z on the group [N], model level
  extvector = 1;
  global_freq = 1;
  peratom_flag = 1;
  size_peratom_cols = 3;
  peratom_freq = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(0);
  for (int i = 0; i < atom->nlocal; i++) hydro_force_[i][0] = hydro_force_[i][1] = hydro_force_[i][2] = 0.0;
  total_force_[0] = total_force_[1] = total_force_[2] = 0.0;
}

FixHeleShawDrag::~FixHeleShawDrag() {
  if (model_ && comm->me == 0) {
    const std::string work = model_->work_summary();
    if (!work.empty() && screen) fprintf(screen, "fix hele_shaw/drag: %s\n", work.c_str());
    if (!work.empty() && logfile) fprintf(logfile, "fix hele_shaw/drag: %s\n", work.c_str());
  }
  atom->delete_callback(id, 0);
  memory->destroy(hydro_force_);
}

int FixHeleShawDrag::setmask() { return POST_FORCE; }

void FixHeleShawDrag::init() {
  // One sphere diameter per group: beta = d / H.
  double dmin = 1e300, dmax = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    dmin = std::min(dmin, 2.0 * atom->radius[i]);
    dmax = std::max(dmax, 2.0 * atom->radius[i]);
  }
  double local[2] = {dmin, -dmax}, global[2];
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MIN, world);
  if (global[0] > 1e299) error->all(FLERR, "fix hele_shaw/drag: no spheres in the group");
  const double d = global[0];
  if (-global[1] > d * (1 + 1e-9))
    error->all(FLERR, "fix hele_shaw/drag: all spheres of the group must share one diameter");
  if (!model_) build_model(d);

  // Every sphere must start in the fluid (inside the planform and the gap).
  int outside = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double *x = atom->x[i];
    if (geometry_->signed_distance(x[0], x[1]) < 0.0 || x[2] < gap_bottom_ ||
        x[2] > gap_bottom_ + geometry_->gap_height())
      outside++;
  }
  int total_outside = 0;
  MPI_Allreduce(&outside, &total_outside, 1, MPI_INT, MPI_SUM, world);
  if (total_outside > 0) {
    char msg[256];
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: %d sphere centre(s) outside the channel planform or gap",
                  total_outside);
    error->all(FLERR, msg);
  }
}

void FixHeleShawDrag::build_model(double d) {
  const double gap = geometry_->gap_height();
  if (d >= gap) {
    char msg[256];
    std::snprintf(msg, sizeof(msg),
                  "fix hele_shaw/drag: sphere diameter %g m >= gap height %g m (beta = d/H must be < 1)", d, gap);
    error->all(FLERR, msg);
  }
  std::string name = model_name_;
  if (name == "auto") name = choose_auto_level(d);
  try {
    const hsrod::ConfinementTable table = coefficients_file_.empty()
                                              ? hsrod::ConfinementTable::default_table()
                                              : hsrod::ConfinementTable::read(coefficients_file_);
    model_ = hsrod::make_hydrodynamic_model(name, {viscosity_, gap, d}, table, window_);
    if (comm->me == 0) {
      char msg[512];
      std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: model %s (level %d), beta = %g, coefficients: %s\n",
                    name.c_str(), model_->level(), d / gap, table.source().c_str());
      if (screen) fputs(msg, screen);
      if (logfile) fputs(msg, logfile);
    }
  } catch (const std::exception &e) {
    char msg[512];
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: %s", e.what());
    error->all(FLERR, msg);
  }
}

// The cheapest level whose error against level 3 stays within the
// tolerance for this scene. Level 2 reproduces level 3's rigid-rod friction
// and drift (its coefficients are level 3's rigid rod), so it suffices
// unless the rod bends: the bending load level 3 adds (force per sphere on
// the rod held at its start, minus the rod mean, across the rod) times the
// compliance L^3 / (48 EI) estimates the deflection that level 2 misses.
std::string FixHeleShawDrag::choose_auto_level(double d) {
  FixRodBonds *bonds = nullptr;
  for (int f = 0; f < modify->nfix; f++)
    if (strcmp(modify->fix[f]->style, "rod/bonds") == 0) bonds = dynamic_cast<FixRodBonds *>(modify->fix[f]);
  RodGather gather(lmp);
  gather.gather(groupbit, nullptr);
  std::string choice = "local";
  double worst = 0.0;
  if (bonds) {
    const hsrod::ConfinementTable table = coefficients_file_.empty()
                                              ? hsrod::ConfinementTable::default_table()
                                              : hsrod::ConfinementTable::read(coefficients_file_);
    const auto level3 = hsrod::make_hydrodynamic_model("nonlocal", {viscosity_, geometry_->gap_height(), d}, table);
    const double bond_d = bonds->bond_radius_ratio() * d;
    const double ei = bonds->youngs_modulus() * 3.14159265358979323846 * std::pow(bond_d, 4) / 64.0;
    for (const auto &rod : gather.rods) {
      hsrod::RodGeometry g;
      g.sphere_diameter = d;
      g.spheres_per_section = section_size_;
      g.id = rod.first;
      for (const auto &s : rod.second) g.positions.push_back(s.position);
      hsrod::RodDrag drag;
      level3->evaluate(g, *flow_, drag);
      const int n = g.size();
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (const auto &f : drag.driving_force) mean += f / n;
      const auto tangents = g.section_tangents();
      double bending_load = 0.0;
      for (int k = 0; k < n; k++) {
        const Eigen::Vector3d t = tangents[g.section_of(k)];
        const Eigen::Vector3d excess = drag.driving_force[k] - mean;
        bending_load += (excess - t * t.dot(excess)).norm();
      }
      const double length = g.sections() * d;
      worst = std::max(worst, bending_load * std::pow(length, 3) / (48.0 * ei * section_size_) / length);
    }
    if (worst > tolerance_) choice = "nonlocal";
  }
  if (comm->me == 0) {
    char msg[512];
    if (bonds)
      std::snprintf(msg, sizeof(msg),
                    "fix hele_shaw/drag: auto: estimated deflection missed by a local model %.3g of L "
                    "(tolerance %.3g) -> %s\n", worst, tolerance_, choice.c_str());
    else
      std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: auto: no fix rod/bonds (rigid spheres) -> %s\n",
                    choice.c_str());
    if (screen) fputs(msg, screen);
    if (logfile) fputs(msg, logfile);
  }
  return choice;
}

// Explicit integration of the drag force is stable for dt < 2 m / zeta_max
// (velocity Verlet on m dv/dt = -zeta v); zeta_max bounds the largest
// eigenvalue of the rod's resistance (Gershgorin row sums when coupled).
void FixHeleShawDrag::check_explicit_limit() {
  RodGather gather(lmp);
  gather.gather(groupbit, nullptr);
  double limit = 1e300;
  for (const auto &rod : gather.rods) {
    hsrod::RodGeometry g;
    g.sphere_diameter = 2.0 * rod.second.front().radius;
    g.spheres_per_section = section_size_;
    g.id = rod.first;
    for (const auto &s : rod.second) g.positions.push_back(s.position);
    hsrod::RodDrag drag;
    model_->evaluate(g, *flow_, drag);
    for (int k = 0; k < g.size(); k++) {
      double zeta = 0.0;
      if (drag.coupled()) {
        for (int a = 0; a < 3; a++) zeta = std::max(zeta, drag.coupled_resistance.row(3 * k + a).cwiseAbs().sum());
      } else {
        zeta = drag.resistance[k].cwiseAbs().rowwise().sum().maxCoeff();
      }
      const double m = rod.second[k].mass;
      const double inertia = 0.4 * m * rod.second[k].radius * rod.second[k].radius;
      limit = std::min(limit, 2.0 * m / zeta);
      limit = std::min(limit, 2.0 * inertia / drag.rotational_resistance[k]);
    }
  }
  explicit_limit_ = limit;
  const bool first_report = !limit_reported_;
  limit_reported_ = true;
  if (comm->me == 0 && first_report) {
    char msg[512];
    std::snprintf(msg, sizeof(msg),
                  "fix hele_shaw/drag: explicit drag limit 2 m/zeta = %.4g s (timestep %.4g s)%s\n", limit,
                  update->dt, applied_by_integrator_ ? "; drag applied implicitly by fix rod/implicit" : "");
    if (screen) fputs(msg, screen);
    if (logfile) fputs(msg, logfile);
  }
  if (!applied_by_integrator_ && timestep_check_ && update->dt > limit) {
    char msg[512];
    std::snprintf(msg, sizeof(msg),
                  "fix hele_shaw/drag: timestep %g s exceeds the explicit drag stability limit %g s (2 m/zeta); "
                  "use fix rod/implicit, a smaller timestep, or 'timestep_check no'", update->dt, limit);
    error->all(FLERR, msg);
  }
}

void FixHeleShawDrag::setup(int vflag) {
  check_explicit_limit();
  if (!applied_by_integrator_) post_force(vflag);
}

void FixHeleShawDrag::post_force(int) {
  if (applied_by_integrator_) return;
  force_flag_ = 0;
  RodGather gather(lmp);
  gather.gather(groupbit, nullptr);
  double total[3] = {0, 0, 0};
  for (const auto &rod : gather.rods) {
    hsrod::RodGeometry g;
    g.sphere_diameter = 2.0 * rod.second.front().radius;
    g.spheres_per_section = section_size_;
    g.id = rod.first;
    const int n = static_cast<int>(rod.second.size());
    Eigen::VectorXd v(3 * n);
    for (int k = 0; k < n; k++) {
      g.positions.push_back(rod.second[k].position);
      v.segment<3>(3 * k) = rod.second[k].velocity;
    }
    hsrod::RodDrag drag;
    model_->evaluate(g, *flow_, drag);
    const Eigen::VectorXd forces = drag.forces(v);
    for (int k = 0; k < n; k++) {
      const int i = atom->map(rod.second[k].tag);
      if (i < 0 || i >= atom->nlocal) continue;
      const Eigen::Vector3d torque = drag.driving_torque[k] - drag.rotational_resistance[k] * rod.second[k].angular_velocity;
      for (int a = 0; a < 3; a++) {
        atom->f[i][a] += forces[3 * k + a];
        atom->torque[i][a] += torque[a];
        hydro_force_[i][a] = forces[3 * k + a];
        total[a] += forces[3 * k + a];
      }
    }
  }
  MPI_Allreduce(total, total_force_, 3, MPI_DOUBLE, MPI_SUM, world);
}

void FixHeleShawDrag::store_force(int i, const double *force) {
  for (int a = 0; a < 3; a++) hydro_force_[i][a] = force[a];
}

double FixHeleShawDrag::compute_vector(int n) {
  if (n == 3) return model_ ? model_->level() : 0;
  if (applied_by_integrator_ && force_flag_ == 0) {
    double local[3] = {0, 0, 0};
    for (int i = 0; i < atom->nlocal; i++)
      if (atom->mask[i] & groupbit)
        for (int a = 0; a < 3; a++) local[a] += hydro_force_[i][a];
    MPI_Allreduce(local, total_force_, 3, MPI_DOUBLE, MPI_SUM, world);
    force_flag_ = 1;
  }
  return total_force_[n];
}

double FixHeleShawDrag::memory_usage() { return 3.0 * atom->nmax * sizeof(double); }

void FixHeleShawDrag::grow_arrays(int nmax) {
  memory->grow(hydro_force_, nmax, 3, "hele_shaw/drag:hydro_force");
  array_atom = hydro_force_;
}

void FixHeleShawDrag::copy_arrays(int i, int j, int) {
  for (int a = 0; a < 3; a++) hydro_force_[j][a] = hydro_force_[i][a];
}

int FixHeleShawDrag::pack_exchange(int i, double *buf) {
  for (int a = 0; a < 3; a++) buf[a] = hydro_force_[i][a];
  return 3;
}

int FixHeleShawDrag::unpack_exchange(int nlocal, double *buf) {
  for (int a = 0; a < 3; a++) hydro_force_[nlocal][a] = buf[a];
  return 3;
}

/* ----------------------------------------------------------------------
   hsrod - fix hele_shaw/drag (see fix_hele_shaw_drag.h; keywords in
   fix_hele_shaw_drag_keywords.cpp, the explicit path in
   fix_hele_shaw_drag_explicit.cpp, checks of the scene and the spheres'
   placement in fix_hele_shaw_drag_checks.cpp)
------------------------------------------------------------------------- */

#include "fix_hele_shaw_drag.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "signal_handling.h"
#include "update.h"

#include "fix_rod_bonds.h"
#include "implicit_partners.h"
#include "neighbor_choice.h"
#include "rod_assembly.h"
#include "rod_gather.h"
#include "run_signals.h"

#include "hydro/rod_hydrodynamics.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <vector>
#include <cstring>
#include <stdexcept>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

FixHeleShawDrag::FixHeleShawDrag(LAMMPS *instance, int narg, char **arg)
    : Fix(instance, narg, arg),
      applied_by_integrator_(false),
      hydro_force_(nullptr),
      force_flag_(0),
      force_step_(-1),
      timestep_check_(true),
      placement_check_(true),
      explicit_limit_(0.0),
      limit_reported_(false) {
  if (strcmp(update->unit_style, "si") != 0) error->all(FLERR, "fix hele_shaw/drag requires 'units si'");
  if (!atom->radius_flag || !atom->omega_flag || !atom->torque_flag || !atom->molecule_flag)
    error->all(FLERR, "fix hele_shaw/drag requires atom_style hybrid granular molecular");

  hsrod::SceneSpec scene;
  hsrod::ModelSpec model;
  parse_keywords(narg, arg, scene, model);
  check_confinement_before_solve(scene, model);
  // Ctrl-C / SIGTERM during the background-flow solve: hsrod's
  // main installs LIGGGHTS' handler, which sets SignalHandler::request_quit;
  // the solve polls it (between phases, every 20 ms in the factorisation)
  // and stops. error->one: a rank that saw the signal must not wait for
  // ranks still solving.
  hsrod::SolveControl control;
  control.cancel_requested = [] { return SignalHandler::request_quit; };
  control.progress = [this](const std::string &line) {
    report(("fix hele_shaw/drag: background flow: " + line + "\n").c_str());
  };
  try {
    hydro_.reset(new hsrod::RodHydrodynamics(scene, model, control));
  } catch (const hsrod::FlowSolveCancelled &e) {
    char msg[512];
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: background flow solve interrupted (SIGINT/SIGTERM): %s",
                  e.what());
    // As error->one, but with the exit code a stopped run documents
    // (128 + signal; error->one's is 1). No waiting for ranks still solving.
    if (screen) std::fprintf(screen, "ERROR on proc %d: %s (%s:%d)\n", comm->me, msg, __FILE__, __LINE__);
    if (logfile) std::fprintf(logfile, "ERROR on proc %d: %s (%s:%d)\n", comm->me, msg, __FILE__, __LINE__);
    if (screen) std::fflush(screen);
    if (logfile) std::fflush(logfile);
    MPI_Abort(world, hsrod::quit_exit_code());
  } catch (const std::exception &e) {
    char msg[512];
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: %s", e.what());
    error->all(FLERR, msg);
  }
  report(("fix hele_shaw/drag: background flow: " + hydro_->flow().description() + "\n").c_str());
  warn_pillar_resolution(scene);

  vector_flag = 1;
  size_vector = 4;  // total hydrodynamic force x y z on the group [N] (extensive), model level (intensive)
  extvector = -1;
  extlist = new int[4]{1, 1, 1, 0};
  global_freq = 1;
  peratom_flag = 1;
  size_peratom_cols = N_LOAD_COLUMNS;  // total, driving, friction force; torque
  peratom_freq = 1;
  restart_global = 1;  // the model's per-rod state (level 4 windows), so that a restart continues identically
  grow_arrays(atom->nmax);
  atom->add_callback(0);
  for (int i = 0; i < atom->nlocal; i++) std::fill(hydro_force_[i], hydro_force_[i] + N_LOAD_COLUMNS, 0.0);
  total_force_[0] = total_force_[1] = total_force_[2] = 0.0;
}

FixHeleShawDrag::~FixHeleShawDrag() {
  if (hydro_) {
    const std::string work = hydro_->work_summary();
    if (!work.empty()) report(("fix hele_shaw/drag: " + work + "\n").c_str());
  }
  delete[] extlist;
  extlist = nullptr;
  atom->delete_callback(id, 0);
  memory->destroy(hydro_force_);
}

const hsrod::BackgroundFlow &FixHeleShawDrag::flow() const { return hydro_->flow(); }

void FixHeleShawDrag::report(const char *line) {
  if (comm->me != 0) return;
  if (screen) fputs(line, screen);
  if (logfile) fputs(line, logfile);
}

int FixHeleShawDrag::setmask() { return POST_FORCE; }

void FixHeleShawDrag::init() {
  // Whether a fix rod/implicit applies this drag in its step (decided here, every run).
  applied_by_integrator_ = implicit_integrator_of(modify, error, id) != nullptr;
  if (!hydro_->has_model()) choose_model();
  hsrod::choose_neighbor_style(lmp, "fix hele_shaw/drag");

  if (placement_check_) check_placement();
}

// One sphere diameter per group (beta = d / H); the facade builds the model,
// for `auto` from the rods' shapes and the bond set's bending stiffness.
void FixHeleShawDrag::choose_model() {
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

  // Every rod as it stands: `auto` chooses from their shapes, and the facade
  // checks each against the model's resources before anything is allocated.
  RodGather gather(lmp);
  gather.gather(groupbit, nullptr);
  std::vector<hsrod::RodGeometry> rods;
  for (const auto &rod : gather.rods) rods.push_back(rod_geometry(*hydro_, rod.first, rod.second, d));
  double bending_stiffness = 0.0;  // EI [N m^2]; 0: no bonds, rigid spheres
  for (int f = 0; f < modify->nfix; f++)
    if (strcmp(modify->fix[f]->style, "rod/bonds") == 0)
      bending_stiffness = dynamic_cast<FixRodBonds *>(modify->fix[f])->bond_set().bending_stiffness(d);
  try {
    const hsrod::ModelChoiceReport &choice = hydro_->choose_model(d, rods, bending_stiffness);
    char msg[512];
    if (!choice.note.empty()) report(("fix hele_shaw/drag: " + choice.note + "\n").c_str());
    if (choice.automatic) {
      // every level's expected error (cross-check record), the bending estimate, the choice
      const std::string line = "fix hele_shaw/drag: auto: " + choice.automatic_choice.summary +
                               (choice.automatic_choice.flexible ? "" : " (no fix rod/bonds: rigid spheres)") + "\n";
      report(line.c_str());
    }
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: model %s (level %d), beta = %g, coefficients: %s\n",
                  choice.name.c_str(), choice.level, choice.beta, choice.coefficients_source.c_str());
    report(msg);
  } catch (const std::exception &e) {
    char msg[512];
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: %s", e.what());
    error->all(FLERR, msg);
  }
}

// The explicit drag limit 2 m / zeta_max over all rods (the facade's).
void FixHeleShawDrag::check_explicit_limit() {
  RodGather gather(lmp);
  gather.gather(groupbit, nullptr);
  double limit = 1e300;
  for (const auto &rod : gather.rods) {
    std::vector<double> masses;
    for (const auto &s : rod.second) masses.push_back(s.mass);
    const hsrod::RodGeometry g = rod_geometry(*hydro_, rod.first, rod.second);
    try {
      limit = std::min(limit, hydro_->explicit_drag_limit(g, masses));
    } catch (const std::exception &e) {
      char msg[768];
      std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: rod %d at set-up: %s", rod.first, e.what());
      error->all(FLERR, msg);
    }
  }
  explicit_limit_ = limit;
  const bool first_report = !limit_reported_;
  limit_reported_ = true;
  if (first_report) {
    char msg[512];
    std::snprintf(msg, sizeof(msg),
                  "fix hele_shaw/drag: explicit drag limit 2 m/zeta = %.4g s (timestep %.4g s)%s\n", limit,
                  update->dt, applied_by_integrator_ ? "; drag applied implicitly by fix rod/implicit" : "");
    report(msg);
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

void FixHeleShawDrag::store_loads(int i, const Eigen::Vector3d &driving, const Eigen::Vector3d &total,
                                  const Eigen::Vector3d &torque) {
  for (int a = 0; a < 3; a++) {
    hydro_force_[i][TOTAL_X + a] = total[a];
    hydro_force_[i][DRIVING_X + a] = driving[a];
    hydro_force_[i][FRICTION_X + a] = total[a] - driving[a];
    hydro_force_[i][TORQUE_X + a] = torque[a];
  }
}

double FixHeleShawDrag::compute_vector(int n) {
  if (n == 3) return hydro_->has_model() ? hydro_->model().level() : 0;
  // Implicit mode: the integrator stores the loads each step; summed once per step.
  if (applied_by_integrator_ && (force_flag_ == 0 || force_step_ != update->ntimestep)) {
    double local[3] = {0, 0, 0};
    for (int i = 0; i < atom->nlocal; i++)
      if (atom->mask[i] & groupbit)
        for (int a = 0; a < 3; a++) local[a] += hydro_force_[i][a];
    MPI_Allreduce(local, total_force_, 3, MPI_DOUBLE, MPI_SUM, world);
    force_flag_ = 1;
    force_step_ = update->ntimestep;
  }
  return total_force_[n];
}

double FixHeleShawDrag::memory_usage() { return double(N_LOAD_COLUMNS) * atom->nmax * sizeof(double); }

void FixHeleShawDrag::grow_arrays(int nmax) {
  memory->grow(hydro_force_, nmax, N_LOAD_COLUMNS, "hele_shaw/drag:hydro_force");
  array_atom = hydro_force_;
}

void FixHeleShawDrag::copy_arrays(int i, int j, int) {
  for (int c = 0; c < N_LOAD_COLUMNS; c++) hydro_force_[j][c] = hydro_force_[i][c];
}

int FixHeleShawDrag::pack_exchange(int i, double *buf) {
  for (int c = 0; c < N_LOAD_COLUMNS; c++) buf[c] = hydro_force_[i][c];
  return N_LOAD_COLUMNS;
}

int FixHeleShawDrag::unpack_exchange(int nlocal, double *buf) {
  for (int c = 0; c < N_LOAD_COLUMNS; c++) hydro_force_[nlocal][c] = buf[c];
  return N_LOAD_COLUMNS;
}

// Global restart data: [kRestartFormat, simulated time, count, the facade's
// model state (count numbers)]. LIGGGHTS 3.8's restart files hold the step
// but not the simulated time (thermo's `time` would restart at 0 after
// read_restart): this fix carries it. Files of the first format,
// [count, state], start with a count >= 0 and are still read.
namespace {
constexpr double kRestartFormat = -2.0;
}

void FixHeleShawDrag::write_restart(FILE *fp) {
  if (comm->me != 0) return;
  std::vector<double> data = hydro_->save_state();
  const double time = update->atime + (update->ntimestep - update->atimestep) * update->dt;  // [s]
  data.insert(data.begin(), {kRestartFormat, time, static_cast<double>(data.size())});
  const int size = static_cast<int>(data.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(data.data(), sizeof(double), data.size(), fp);
}

void FixHeleShawDrag::restart(char *buf) {
  const double *list = reinterpret_cast<const double *>(buf);
  if (list[0] == kRestartFormat) {
    // The restored step (read_restart) is the time origin from here on;
    // Integrate::init keeps atime and moves atimestep to the step again.
    update->atime = list[1];
    update->atimestep = update->ntimestep;
    list += 2;
  }
  const std::size_t n = static_cast<std::size_t>(list[0]);
  try {
    hydro_->restore_state(std::vector<double>(list + 1, list + 1 + n));
  } catch (const std::exception &e) {
    char msg[512];
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: restart: %s", e.what());
    error->all(FLERR, msg);
  }
}

/* ----------------------------------------------------------------------
   hsrod - fix rod/implicit (see fix_rod_implicit.h)

   fix ID group rod/implicit bonds BONDS-ID drag DRAG-ID [walls yes|no]
                             [max_displacement f] [accuracy_guard yes|no]
                             [step_error f] [max_substeps N] [max_bond_strain f]
                             [adaptive yes|no] [tolerance f]
------------------------------------------------------------------------- */

#include "fix_rod_implicit.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_hele_shaw_drag.h"
#include "fix_rod_bonds.h"
#include "force.h"
#include "group.h"
#include "lmptype.h"
#include "modify.h"
#include "rod_accounting.h"
#include "rod_assembly.h"
#include "rod_gather.h"
#include "update.h"

#include "dynamics/implicit_conditioning.h"
#include "dynamics/overdamped_rod_step.h"
#include "hydro/rod_hydrodynamics.h"
#include "rod/rod_bond_set.h"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <set>
#include <string>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

FixRodImplicit::FixRodImplicit(LAMMPS *instance, int narg, char **arg)
    : Fix(instance, narg, arg),
      bonds_(nullptr),
      drag_(nullptr),
      walls_(true),
      wall_friction_(0.0),
      slip_velocity_(1e-6),
      friction_iterations_(hsrod::WallContactParameters().friction_iterations),
      friction_tolerance_(hsrod::WallContactParameters().friction_tolerance),
      max_displacement_(0.25),
      guard_(true),
      substeps_(0),
      unresolved_(0),
      substeps_taken_(0),
      trials_rejected_(0),
      unresolved_warned_(false),
      substeps_warned_(false),
      bond_strain_(0.0),
      bond_energy_(0.0),
      largest_displacement_(0.0),
      wall_force_(0.0),
      contacts_(0),
      warned_(false),
      bond_state_fresh_(true),
      rod_contact_(false),
      rod_friction_(-1.0),
      rod_interaction_(true),
      contact_capacitance_(false),
      rod_contacts_(0),
      rod_contact_force_(0.0),
      reported_(false),
      gather_(instance) {
  parse_keywords(narg, arg);
  if (bonds_id_.empty()) error->all(FLERR, "Illegal fix rod/implicit command: missing required keyword bonds");
  if (drag_id_.empty()) error->all(FLERR, "Illegal fix rod/implicit command: missing required keyword drag");
  if (rod_friction_ < 0.0) rod_friction_ = wall_friction_;  // the rods' material: the wall friction coefficient
  if (limits_.adaptive && !guard_)
    error->all(FLERR, "fix rod/implicit: adaptive yes needs accuracy_guard yes (the substeps are the guard's)");
  if (far_field_given_ && !apart() && comm->me == 0)
    error->warning(FLERR, "fix rod/implicit: rod_far_field has no effect here: it applies with rod_interaction lagged "
                          "or iterated only (with yes / joint, rods not linked within the reach are not coupled; "
                          "with no, no rod pair is coupled)");
  // The partners must exist now (a script error is reported at its line);
  // they are looked up again at every init() and decide there themselves
  // that this fix integrates their work (implicit_partners.h).
  resolve_partners();
  time_integrate = 1;
  limits_.max_displacement = max_displacement_;
  // Displacement, strain and wall failures refuse the run; an unresolved
  // Newton error at the finest substep is accepted with a warning and counted.
  limits_.refuse_unresolved_error = false;
  limits_.report_bond_state = false;  // on demand (refresh_bond_state)
  vector_flag = 1;
  // [1] largest displacement per step / d, [2] wall force [N], [3] rods touching walls,
  // [4] most substeps of the accuracy guard, [5] largest |bond axial strain|, [6] bond energy [J],
  // [7] substeps accepted with an unresolved Newton error (run total), [8] rods held at the box boundary,
  // [9] substeps taken (run total over rods), [10] trial substeps rejected (run total over rods),
  // [11] rods touching another rod (rod_contact), [12] sum of |rod-rod contact force| [N]
  size_vector = 12;
  extvector = 0;
  global_freq = 1;
  restart_global = 1;  // the rods' wall-contact records
}

int FixRodImplicit::setmask() { return INITIAL_INTEGRATE; }

void FixRodImplicit::init() {
  resolve_partners();
  if (!(std::isfinite(update->dt) && update->dt > 0.0)) {
    char msg[256];
    std::snprintf(msg, sizeof(msg), "fix rod/implicit: timestep %g s must be finite and > 0 s", update->dt);
    error->all(FLERR, msg);
  }
  if (force->pair && rod_contact_)
    error->all(FLERR, "fix rod/implicit: rod_contact hertz and a pair style would both act between the rods' "
                      "spheres (counted twice); remove the pair style or use rod_contact none");
  // No other integrator may move these atoms.
  for (int f = 0; f < modify->nfix; f++) {
    Fix *other = modify->fix[f];
    if (other == this || !other->time_integrate) continue;
    int shared = 0, any = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & groupbit) && (atom->mask[i] & other->groupbit)) shared = 1;
    MPI_Allreduce(&shared, &any, 1, MPI_INT, MPI_MAX, world);
    if (any) {
      char msg[256];
      std::snprintf(msg, sizeof(msg), "fix rod/implicit: fix %s (%s) also integrates atoms of this group; remove it",
                    other->id, other->style);
      error->all(FLERR, msg);
    }
  }
}

// The bonds against the drag over one step, dt k / zeta: beyond
// kMaxImplicitStiffnessRatio the solve cannot carry the rod's rigid motion
// in double precision (dynamics/implicit_conditioning.h): the rod would
// freeze or blow up, and the accuracy guard would blame the timestep.
double FixRodImplicit::check_conditioning() {
  const double bond_limit = bonds_->explicit_bond_limit_known(), drag_limit = drag_->explicit_drag_limit();
  if (!(bond_limit > 0.0 && drag_limit > 0.0 && drag_limit < 1e299)) return 0.0;  // no rods yet
  const double ratio = hsrod::implicit_stiffness_ratio(update->dt, drag_limit, bond_limit);
  if (ratio <= hsrod::kMaxImplicitStiffnessRatio) return ratio;
  const double modulus = bonds_->bond_set().youngs_modulus;
  char msg[1024];
  std::snprintf(msg, sizeof(msg),
                "fix rod/implicit: the bonds of fix %s (youngs_modulus %g Pa) are too stiff for the drag of fix %s "
                "(viscosity %g Pa s) at timestep %g s: dt k/zeta = %.3g exceeds %.0e, beyond which the implicit solve "
                "loses the rod's rigid motion to round-off (it would freeze or blow up); use youngs_modulus <= %.3g Pa "
                "(the rod is already rigid on this step's scale from dt k/zeta ~ 1e4) or timestep <= %.3g s",
                bonds_id_.c_str(), modulus, drag_id_.c_str(), drag_->hydrodynamics().viscosity(), update->dt, ratio,
                hsrod::kMaxImplicitStiffnessRatio, hsrod::largest_well_conditioned_modulus(modulus, ratio),
                update->dt / (ratio / hsrod::kMaxImplicitStiffnessRatio));
  error->all(FLERR, msg);
  return ratio;
}

hsrod::OverdampedSolverStatistics FixRodImplicit::solver_statistics() const {
  hsrod::OverdampedSolverStatistics sum;
  for (const auto &entry : work_by_rod_) hsrod::accumulate(sum, entry.second.solver.statistics());
  for (const auto &entry : solvers_by_cluster_) hsrod::accumulate(sum, entry.second.statistics());
  hsrod::accumulate(sum, retired_statistics_);
  return sum;
}

void FixRodImplicit::setup(int) {
  // f_bonds shows the bond state after this fix's steps; rods are gathered
  // whole on every processor, so rank 0 holds the energy.
  // (The fix rod/bonds may outlive this fix: the call then does nothing.)
  const std::weak_ptr<int> alive = lifetime_;
  bonds_->set_implicit_bond_state([this, alive](double &elastic_energy, double &max_strain) {
    if (alive.expired()) return;
    refresh_bond_state();
    elastic_energy = comm->me == 0 ? bond_energy_ : 0.0;
    max_strain = bond_strain_;
  });
  // Rods are counted afresh at each run's start: what the script deleted
  // between runs is its business; what goes missing during a run is an error.
  const double stiffness_ratio = check_conditioning();
  census_ = RodCensus();
  substeps_taken_ = trials_rejected_ = 0;
  rods_met_in_step_ = 0;
  cost_ = hsrod::StepCost();
  apart_sweeps_taken_ = 0;
  solver_statistics_at_setup_ = solver_statistics();
  if (reported_) return;
  reported_ = true;
  if (comm->me == 0) {
    char msg[512];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/implicit: overdamped linearly implicit step dt = %g s; bonds, drag and wall contacts "
                  "implicit (explicit bond limit%s %g s: dt is %.0f x larger; bonds against drag dt k/zeta = %.3g, "
                  "limit %.0e)\n",
                  update->dt, bonds_->bond_limit_damped() ? "" : " without bond damping",
                  bonds_->explicit_bond_limit_known(),
                  bonds_->explicit_bond_limit_known() > 0 ? update->dt / bonds_->explicit_bond_limit_known() : 0.0,
                  stiffness_ratio, hsrod::kMaxImplicitStiffnessRatio);
    if (screen) fputs(msg, screen);
    if (logfile) fputs(msg, logfile);
  }
  const double reach = rod_interaction_ && drag_->hydrodynamics().has_model() ? drag_->hydrodynamics().interaction_reach()
                                                                             : 0.0;
  if (comm->me == 0 && (rod_contact_ || reach > 0.0)) {
    char msg[512];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/implicit: rods are stepped together (one joint implicit solve) while their spheres are "
                  "within %s%s%s; rod_contact %s (friction %g)\n",
                  rod_contact_ ? "contact reach" : "",
                  rod_contact_ && reach > 0.0 ? " or " : "",
                  reach > 0.0 ? ("the drag model's interaction reach " + std::to_string(reach) + " m").c_str() : "",
                  rod_contact_ ? "hertz" : "none", rod_contact_ ? rod_friction_ : 0.0);
    if (screen) fputs(msg, screen);
    if (logfile) fputs(msg, logfile);
  }
  if (apart() && comm->me == 0) {
    char msg[400];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/implicit: rod_interaction %s: rods within the drag model's interaction reach %g m are "
                  "solved apart, each with the others' disturbance %s; rods farther apart %s\n",
                  rods_apart_ == RodsApart::lagged ? "lagged" : "iterated", drag_->hydrodynamics().interaction_reach(),
                  rods_apart_ == RodsApart::lagged ? "from their last obstruction forces (lagged)"
                                                   : "iterated rod by rod to the tolerance (Gauss-Seidel)",
                  far_field_ ? "by their far field (multipoles, rod_far_field yes)" : "uncoupled (rod_far_field no)");
    if (screen) fputs(msg, screen);
    if (logfile) fputs(msg, logfile);
  }
  if (force->pair && comm->me == 0)
    error->warning(FLERR, "fix rod/implicit: pair forces (rod-rod contacts) enter explicitly; keep the timestep "
                          "below the contact limit");
}

void FixRodImplicit::initial_integrate(int) {
  const Clock::time_point step_start = Clock::now();
  RodGather &gather = gather_;
  gather.gather(groupbit, bonds_);
  check_whole_rods(gather);
  const hsrod::WallContactParameters walls = wall_contact_parameters();
  stepped_rods_.clear();
  // Rods that touch or interact hydrodynamically are stepped together
  // (fix_rod_implicit_clusters.cpp, dynamics/rod_cluster.h), and so are
  // rods that meet within the step (fix_rod_implicit_step_contacts.cpp);
  // every proc holds every rod and finds the same clusters. A rod alone
  // takes its own step (fix_rod_implicit_rod_step.cpp).
  StepTotals totals;
  retire_stale_clusters(step_all(gather, walls, totals));
  ++cost_.steps;
  cost_.total_seconds += seconds_since(step_start);
  largest_displacement_ = totals.largest;
  wall_force_ = totals.wall_force;
  contacts_ = totals.contacts;
  substeps_ = totals.substeps;
  rod_contacts_ = totals.rod_contacts;
  rod_contact_force_ = totals.rod_contact_force;
  bond_state_fresh_ = false;
  bonds_->implicit_step_taken();
  if (!guard_ && totals.largest > max_displacement_ && !warned_ && comm->me == 0) {
    char msg[256];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/implicit: a sphere moved %.3g diameters in one step (> max_displacement %.3g): the step "
                  "is stable but may be inaccurate; reduce the timestep", totals.largest, max_displacement_);
    error->warning(FLERR, msg);
    warned_ = true;
  }
}

// The cost model of the run: time per step and per sphere-step, and where
// it went.
void FixRodImplicit::post_run() {
  if (cost_.steps == 0) return;
  cost_.solver = hsrod::difference(solver_statistics(), solver_statistics_at_setup_);
  if (comm->me != 0) return;
  std::string line = "fix rod/implicit cost: " + cost_.report() + "\n";
  if (rods_apart_ == RodsApart::iterated)
    line += "fix rod/implicit: rod_interaction iterated: " + std::to_string(apart_sweeps_taken_) + " sweeps over " +
            std::to_string(cost_.steps) + " steps\n";
  if (rods_met_in_step_ > 0)
    line += "fix rod/implicit: " + std::to_string(rods_met_in_step_) +
            " time(s) rods stepped apart met within a step: stepped again together, or held at a rod held "
            "at the box face\n";
  if (screen) fputs(line.c_str(), screen);
  if (logfile) fputs(line.c_str(), logfile);
}

double FixRodImplicit::compute_vector(int n) {
  if (n == 0) return largest_displacement_;
  if (n == 1) return wall_force_;
  if (n == 2) return contacts_;
  if (n == 3) return substeps_;
  if (n == 4 || n == 5) refresh_bond_state();
  if (n == 4) return bond_strain_;
  if (n == 5) return bond_energy_;
  if (n == 6) return unresolved_;
  if (n == 7) return static_cast<double>(held_rods_.size());
  if (n == 8) return static_cast<double>(substeps_taken_);
  if (n == 9) return static_cast<double>(trials_rejected_);
  if (n == 10) return rod_contacts_;
  return rod_contact_force_;
}

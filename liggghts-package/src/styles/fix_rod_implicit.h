/* ----------------------------------------------------------------------
   hsrod - fix rod/implicit: overdamped, linearly implicit integrator for
   rods (bonds, drag and wall contacts implicit; other forces explicit).
   Step in drag-models/dynamics/overdamped_rod_step.h; this fix gathers
   each rod, calls it, and scatters positions, velocities, orientations.
   Doc: doc/fix_rod_implicit.txt
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

FixStyle(rod/implicit,FixRodImplicit)

#else

#ifndef LMP_FIX_ROD_IMPLICIT_H
#define LMP_FIX_ROD_IMPLICIT_H

#include "fix.h"

#include "implicit_partners.h"
#include "rod_accounting.h"
#include "rod_assembly.h"
#include "rod_removal.h"

#include "dynamics/guarded_step.h"
#include "dynamics/overdamped_rod_step.h"
#include "dynamics/rod_cluster.h"
#include "dynamics/step_cost_report.h"
#include "hydro/cross_rod_disturbance.h"
#include "hydro/cross_rod_far_field.h"

#include <chrono>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {

// Wall-contact history of one rod (identical on every processor).
struct RodContactRecord {
  bool touching = false;        // in contact with a wall in the last step
  bool ever_touched = false;    // since the run started
  double wall_force = 0.0;      // last step, sum of |wall contact force| [N]
  double largest_wall_force = 0.0;  // over the run [N]
};

class FixRodImplicit : public Fix, public PartnerIntegrator, public RodRemovalListener {
 public:
  // Contact history of rod (molecule) `mol`, or null if unknown.
  const RodContactRecord *contact_record(int mol) const {
    auto it = contacts_by_rod_.find(mol);
    return it == contacts_by_rod_.end() ? nullptr : &it->second;
  }

  FixRodImplicit(class LAMMPS *, int, char **);
  // Whether this fix integrates the work of fix `fix_id` (its bonds or drag
  // fix); the partners ask at their init() (implicit_partners.h).
  bool names_partner(const char *fix_id) const override;
  // Rods deleted whole (fix rod/outflow): their census entry, solvers,
  // records and held state go (fix_rod_implicit_bookkeeping.cpp).
  void forget_rods(const std::vector<int> &molecules) override;
  int setmask();
  void init();
  void setup(int);
  void initial_integrate(int);
  void post_run();
  double compute_vector(int);
  void write_restart(FILE *);
  void restart(char *);

 private:
  std::string bonds_id_, drag_id_;  // the partner fixes, by ID
  class FixRodBonds *bonds_;        // resolved from the IDs at every init()
  class FixHeleShawDrag *drag_;
  bool walls_;                    // contacts with the scene's walls
  double wall_friction_;          // Coulomb wall friction coefficient mu_fr [-] (0: frictionless)
  double slip_velocity_;          // regularisation: below it friction is viscous [m/s]
  int friction_iterations_;       // repeats of a step to put wall friction at its end velocities [-]
  double friction_tolerance_;     // their relative friction-force tolerance [-]
  double max_displacement_;       // accuracy guard: largest displacement per (sub)step [d]
  bool guard_;                    // accuracy guard on (dynamics/guarded_step.h)
  hsrod::StepGuardLimits limits_; // its limits
  int substeps_;                  // last step, most substeps any rod took
  long unresolved_;               // run total of substeps accepted with an unresolved Newton error
  long substeps_taken_;           // run total of substeps (all rods)
  long trials_rejected_;          // run total of rejected trial substeps (all rods)
  bool unresolved_warned_;
  bool substeps_warned_;          // a fixed step needed kManySubsteps or more substeps (said once)
  // A fixed step (adaptive no) cut into this many substeps or more by the
  // accuracy guard is far above what the motion allows there: warned.
  static constexpr int kManySubsteps = 64;
  double bond_strain_;            // last step, largest |axial strain| [-]
  double bond_energy_;            // last step, elastic energy of all rods' bonds [J]
  double largest_displacement_;   // last step, max |dx| / d [-]
  double wall_force_;             // last step, sum of wall contact forces [N]
  int contacts_;                  // last step, number of rods touching a wall
  bool warned_;
  std::vector<int> stepped_rods_;  // rods stepped in the last step (their bond state on demand)
  bool bond_state_fresh_;          // bond_strain_, bond_energy_ are those of the last step
  std::shared_ptr<int> lifetime_ = std::make_shared<int>(0);  // expires with this fix (fix rod/bonds' callback)
  void refresh_bond_state();
  std::map<int, RodContactRecord> contacts_by_rod_;
  // Per rod (molecule ID): the step's workspace and LU analysis, kept
  // between steps so a long rod is not re-analysed every step. Not in
  // restart files: a fresh workspace gives the same step (tested), while
  // the contact records above are written (write_restart).
  // The step's structures per rod, rebuilt in place every step from the
  // gather (no allocation per step; no state: restarts need none).
  struct RodScratch {
    hsrod::OverdampedRod rod;
    hsrod::RodGeometry geometry, substep_geometry;
    hsrod::RodDrag drag;
    std::vector<Eigen::Vector3d> before;  // positions at the step's start [m]
    hsrod::GuardedStepReport report;      // guarded step
    hsrod::OverdampedStepResult result;   // unguarded step
    BondStiffnessCache stiffnesses;       // the bonds' stiffnesses while their inputs stay the same
  };
  // A rod's solver, its guard's scratch (no state) and step structures,
  // found by one hashed lookup per step (not a search of a tree of all rods).
  struct RodWork {
    RodScratch scratch;
    hsrod::OverdampedRodSolver solver;
    hsrod::GuardWorkspace guard;
  };
  std::unordered_map<int, RodWork> work_by_rod_;
  // Cost model of the current run (printed by post_run): wall times of the
  // whole integrator and of the drag model, the solvers' split from their
  // statistics at setup and at the end (dynamics/step_cost_report.h).
  hsrod::StepCost cost_;
  hsrod::OverdampedSolverStatistics solver_statistics_at_setup_;
  hsrod::OverdampedSolverStatistics solver_statistics() const;
  // Several rods: Hertz contact with regularised Coulomb friction
  // between spheres of different rods inside the implicit step, and the
  // model's hydrodynamic interaction between rods (level 3); rods that touch
  // or interact are stepped together (fix_rod_implicit_clusters.cpp).
  bool rod_contact_;              // rod_contact hertz (E, nu of the rods' material from fix rod/bonds)
  double rod_friction_;           // Coulomb coefficient between rods [-] (default: wall_friction)
  bool rod_interaction_;          // rod_interaction yes: the drag model couples nearby rods (one joint solve)
  // rod_interaction lagged / iterated N tol: level 3 between rods solved
  // rod by rod (hydro/cross_rod_disturbance.h; fix_rod_implicit_apart.cpp).
  enum class RodsApart { off, lagged, iterated };
  RodsApart rods_apart_ = RodsApart::off;
  int apart_sweeps_ = 1;           // iterated: most Gauss-Seidel sweeps per step
  double apart_tolerance_ = 0.0;   // iterated: accepted change of the obstruction forces between sweeps [-]
  std::map<int, hsrod::RodObstructionForces> obstruction_by_rod_;  // P^D, P^v, q per rod (kept: lagged)
  std::unordered_map<int, hsrod::RodGeometry> apart_geometry_;     // centres at the step's start [m]
  std::unordered_map<int, std::vector<int>> apart_neighbours_;     // rods within the interaction reach
  std::map<int, hsrod::UnitObstruction> unit_by_first_;            // the step's units, by first rod
  long apart_sweeps_taken_ = 0;    // run total
  // rod_far_field yes: the rods beyond the reach summed by their multipoles
  // (hydro/cross_rod_far_field.h), from the obstruction forces at each sweep's start.
  bool far_field_ = true;
  bool far_field_given_ = false;  // rod_far_field set in the command (warned about where it has no effect)
  hsrod::CrossRodFarField far_field_sum_;
  void build_far_field();
  bool apart() const { return rods_apart_ != RodsApart::off; }
  void prepare_rods_apart(const RodGather &gather);
  // The group's load with the other units' disturbance (at the step's start: q found and kept).
  void apart_loads(const std::vector<int> &molecules, const std::vector<hsrod::RodGeometry> &geometries,
                   hsrod::RodDrag &out, bool step_start);
  void update_obstruction(const std::vector<int> &molecules, const std::vector<Eigen::Vector3d> &velocities);
  double obstruction_change_since(const std::map<int, hsrod::RodObstructionForces> &before) const;
  void parse_rod_interaction(int narg, char **arg, int &iarg);
  void report_unconverged_sweeps(double change);
  bool contact_capacitance_;      // contact_solve capacitance: chains with off-band contacts by Woodbury, else the general LU
  int rod_contacts_;              // last step, rods touching another rod
  double rod_contact_force_;      // last step, sum of |rod-rod Hertz force| [N]
  std::map<std::vector<int>, hsrod::OverdampedRodSolver> solvers_by_cluster_;  // rods stepped together, by molecule IDs
  std::map<std::vector<int>, hsrod::GuardWorkspace> guards_by_cluster_;
  hsrod::OverdampedSolverStatistics retired_statistics_;  // of joint solvers dropped with their cluster
  double joint_strain_ = 0.0, joint_energy_ = 0.0;  // last step, bond state of the rods stepped jointly [-], [J]
  struct StepTotals {              // one step over all rods
    double largest = 0.0, wall_force = 0.0, strain = 0.0, energy = 0.0, rod_contact_force = 0.0;
    int contacts = 0, substeps = 1, rod_contacts = 0;
  };
  // A step taken and not yet scattered to the atoms: its spheres' paths are
  // first checked against the other rods' (contact detection within the
  // step: rods stepped apart that meet within it are stepped again
  // together, from the same start).
  struct PendingStep {
    std::vector<int> molecules;  // the rod alone, or the cluster's rods
    StepTotals totals;           // its share of the step's totals
    bool alone = true;           // the rod's scratch (below) holds the step; else the members below
    RodScratch *scratch = nullptr;  // the rod's, when alone (work_by_rod_)
    std::vector<GatheredSphere> spheres;
    hsrod::OverdampedRod rod;
    std::vector<Eigen::Vector3d> before;  // positions at the step's start [m]
    hsrod::OverdampedStepResult result;
    hsrod::RodDrag drag;
    double strain = 0.0, energy = 0.0;  // the cluster's bond state after the step [-], [J]
  };
  std::vector<PendingStep> pending_;
  long rods_met_in_step_ = 0;  // run total of groups stepped again together (printed by post_run)
  // Rounds of re-stepping rods that met within the step; a meeting left
  // after them is caught by the interpenetration check at the next step.
  static constexpr int kContactRounds = 4;
  // Groups of molecule IDs stepped together (each a rod alone, or a cluster
  // of rods within contact or hydrodynamic reach), the same on every proc.
  std::vector<std::vector<int>> step_clusters(const RodGather &gather) const;
  mutable std::vector<std::vector<Eigen::Vector3d>> cluster_positions_;  // step_clusters' buffers [m]
  // The all-sphere searches' buffers: the clusters at the step's start and
  // the meeting check (two lists: each is re-sorted from its last order).
  mutable hsrod::RodSearchBuffers cluster_search_, meeting_search_;
  // Every rod's step (clusters merged where rods meet within it), scattered
  // to the atoms; returns the groups finally stepped together.
  std::vector<std::vector<int>> step_all(const RodGather &gather, const hsrod::WallContactParameters &walls,
                                         StepTotals &totals);
  void step_group(const RodGather &gather, const std::vector<int> &molecules, const hsrod::WallContactParameters &walls);
  bool merge_rods_meeting_in_step(const RodGather &gather, const hsrod::WallContactParameters &walls);
  // A group whose step meets a rod held at a box face: held too, at its start.
  void hold_at_held_rod(const RodGather &gather, const PendingStep &step, int held_rod);
  // One group's step into `step`; false when it was held at a box face (scattered already).
  bool step_cluster(const RodGather &gather, const std::vector<int> &molecules,
                    const hsrod::WallContactParameters &walls, PendingStep &step);
  void retire_stale_clusters(const std::vector<std::vector<int>> &clusters);
  // A rod alone (fix_rod_implicit_rod_step.cpp).
  hsrod::WallContactParameters wall_contact_parameters() const;
  void evaluate_rod_drag(int molecule, RodScratch &scratch);
  bool step_rod_alone(int molecule, const std::vector<GatheredSphere> &spheres,
                      const hsrod::WallContactParameters &walls, StepTotals &totals);
  using Clock = std::chrono::steady_clock;
  static double seconds_since(Clock::time_point start);
  bool reported_;                // set-up report printed once, not per run
  void resolve_partners();
  double check_conditioning();  // bonds against drag over one step (dt k/zeta), at each run's start
  void parse_keywords(int narg, char **arg);  // fix_rod_implicit_keywords.cpp
  RodCensus census_;             // spheres per rod as first seen: lost atoms are an error
  RodGather gather_;             // the rods every step (its buffers kept between steps)
  std::set<int> held_rods_;      // rods held at the box boundary (their next step would leave the box)
  void check_whole_rods(const RodGather &gather);
  void hold_rod(const std::vector<GatheredSphere> &spheres);
  void hold_rod_at_face(const std::vector<GatheredSphere> &spheres, const std::vector<Eigen::Vector3d> &before,
                        const std::vector<Eigen::Vector3d> &after);
  // The step's new state back to the local atoms (positions by the step's
  // displacement from `before`, velocities, spins, orientations) and the
  // hydrodynamic loads at the new velocities to the drag fix.
  void account_guard_report(const std::string &who, const hsrod::GuardedStepReport &report, int &substeps);
  void report_held_at_face(const std::string &who, int face);
  void scatter_rod(const std::vector<GatheredSphere> &spheres, const hsrod::OverdampedRod &rod,
                   const std::vector<Eigen::Vector3d> &before, const hsrod::OverdampedStepResult &result,
                   const hsrod::RodDrag &drag);
};

}  // namespace LAMMPS_NS

#endif
#endif

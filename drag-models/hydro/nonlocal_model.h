// Level 3 of the fidelity ladder (hydrodynamic_model.h): the spheres of a rod interact
// through the depth-averaged Brinkman Green's function (brinkman_green.h).
//
// Each confined sphere's friction zeta(beta) = 3 pi mu d f(beta) is split
// into a film part zeta_f, friction with the gap walls that depends on the
// sphere's own velocity only, and an obstruction part zeta_o, the pressure
// force of the gap-averaged flow pushed around the sphere:
//     F_i = -zeta_f v_i + P_i,
//     P_i = zeta_o (c u_i + c sum_k G(x_i - x_k) (-P_k) - v_i),
// where c = 3/2 turns gap-averaged velocities into mid-plane ones and -P_k
// is the force sphere k exerts on the fluid. The split follows from the
// isolated sphere's force-free velocity lambda(beta) u: zeta_o = zeta
// lambda / c. Solving for P gives F = c R_o u - (zeta_f + R_o) v with
// R_o = zeta_o (I + c zeta_o G)^-1: one small dense solve per rod.
// For a rod across the flow the middle spheres are shielded from the flow
// going around the ends: the force per sphere is largest in the middle and
// a flexible rod bends into the C-shape (Cappello et al. 2019), which the
// local models cannot give.
//
// Spheres closer than a few gap heights interact as in 3-D Stokes flow, not
// through the depth-averaged G: their pair coupling c G is blended into a
// Rotne-Prager mobility with the walls' reflection (hydro/near_field_coupling.h),
// fitted to the resolved per-sphere loads (the built-in default). The held
// load has its own near field (NearFieldAtBeta): F = c R_o^D u - (zeta_f +
// R_o) v, R_o^D = zeta_o (I + c zeta_o G^D)^-1 with G^D blended with the
// driving's parameters.
//
// Walls that span the gap (side walls, pore cylinders) reflect the
// depth-averaged flow; with WallReflection::images M gains the images of
// every sphere's force in them (hydro/wall_images.h): M_ik += c G_image(x_i,
// x_k), the self-image included (i = k), symmetrised.
#pragma once

#include "hydro/local_models.h"
#include "hydro/near_field_coupling.h"

#include <map>

namespace hsrod {

struct UnitObstruction;        // hydro/cross_rod_disturbance.h
struct RodObstructionForces;   // hydro/cross_rod_disturbance.h
class CrossRodFarField;        // hydro/cross_rod_far_field.h

// What level 3 keeps between evaluations (ModelState; owned by the caller,
// e.g. RodHydrodynamics): per rod, the in-plane coupling inverses solved at
// the rod's shape of its last full evaluation. The pair couplings depend on
// the spheres' in-plane offsets only, through tensors that turn with them
// (G(Q r) = Q G(r) Q^T, and so the near field), so while the rod moves as a
// rigid body in the plane its inverses are the stored ones turned:
// Q_b R_o Q_b^T, Q_b = diag(Q, ..., Q). They are solved afresh once a centre
// is farther than NonlocalRodModel::kShapeTolerance from its rigidly carried
// place (the rod bent or stretched since).
struct NonlocalState : ModelState {
  struct Rod {
    std::vector<Eigen::Vector2d> reference;  // in-plane centres at the last full evaluation [m]
    Eigen::MatrixXd obstruction;             // zeta_o (I + zeta_o M)^-1 there, 2n x 2n [N s/m]
    Eigen::MatrixXd driving;                 // zeta_o (I + zeta_o M^D)^-1 [N s/m]; empty: the same as obstruction
    // The two turned to the rod's present orientation (scratch of the
    // evaluation, kept so that a reused step allocates nothing; not saved).
    Eigen::MatrixXd turned_obstruction, turned_driving;  // [N s/m]
  };
  std::map<int, Rod> rods;  // by RodGeometry::id (joined rods: a key of their own)
  long evaluations = 0;     // calls with this state
  long solves = 0;          // of which solved the coupling afresh
  std::string work_summary() const override;
};

// Sphere-centre distance [m] beyond which two spheres' coupling through the
// depth-averaged Brinkman flow, c zeta_o |G|, is below `tolerance` of a
// sphere's own obstruction (NonlocalRodModel::interaction_reach; level 4's
// window carries the same flow): gap height H [m], viscosity mu [Pa s],
// obstruction friction zeta_o [N s/m].
double depth_averaged_interaction_reach(double gap_height, double viscosity, double obstruction_friction,
                                        double tolerance);

// How level 3 treats the walls that span the gap: `none` (free-space G),
// `images` (hydro/wall_images.h) or `self_images` (each sphere's own image
// only, the diagonal blocks: what a per-sphere level could carry) or
// `reflections` (the images with their multiple reflections between the
// walls and cylinders, wall_images.h: reflected_force_images).
enum class WallReflection { none, images, self_images, reflections };
// "none" | "images" | "self_images" | "reflections"; throws std::invalid_argument naming the accepted values.
WallReflection wall_reflection_from_name(const std::string& name);

class NonlocalRodModel : public LocalDragBase {
 public:
  NonlocalRodModel(const HydrodynamicParameters& parameters, const ConfinementTable& table);
  NonlocalRodModel(const HydrodynamicParameters& parameters, const ConfinementTable& table,
                   const NearFieldAtBeta& near_field);
  std::string name() const override { return "nonlocal"; }
  int level() const override { return 3; }
  using HydrodynamicModel::evaluate;
  // With a state (make_state()), the coupling of a rod that has moved
  // rigidly since its last solve is reused turned (NonlocalState); without
  // one, solved at every call.
  void evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out, ModelState* state) const override;
  std::unique_ptr<ModelState> make_state() const override;
  std::vector<double> save_state(const ModelState& state) const override;
  void restore_state(ModelState& state, const std::vector<double>& data, const BackgroundFlow& flow) const override;
  // Largest distance [m, as a fraction of d] of a sphere centre from its
  // place carried rigidly from the last solve up to which the stored
  // coupling is reused. A centre off by delta changes a pair coupling at
  // distance r >= d by ~delta / r of itself: 1e-4 d keeps the loads within
  // ~1e-4 of the solved ones (tests/drag-models/hydro/test_nonlocal_model.cpp
  // measures it; tests/benchmarks/RESULTS.md the passage's change).
  static constexpr double kShapeTolerance = 1e-4;  // [-], of the sphere diameter
  // Dense 3n x 3n matrices against limits.dense_memory_bytes (hydro/dense_model_budget.h).
  std::string resource_problem(const RodGeometry& rod, const BackgroundFlow& flow,
                               const ResourceLimits& limits) const override;
  // Several rods: the same Green's function between the spheres of all of
  // them (the obstruction of one rod shields or drives the others), one
  // dense solve over all their spheres. Level 3 itself does not tell
  // spheres of one rod from those of another: two lone spheres are one
  // two-sphere rod without its bond.
  void evaluate_rods(const std::vector<RodGeometry>& rods, const BackgroundFlow& flow, RodDrag& out,
                     ModelState* state) const override;
  // Rods solved apart, coupled through their disturbances
  // (hydro/cross_rod_disturbance.h): the load of `rods` (one rod, or rods
  // stepped together) alone, as evaluate_rods gives it, and into `unit` its
  // in-plane obstruction resistances and lone driving.
  void evaluate_alone(const std::vector<RodGeometry>& rods, const BackgroundFlow& flow, RodDrag& out,
                      ModelState* state, UnitObstruction& unit) const;
  // The disturbance rod `source` of another unit makes at the spheres of
  // `target`: q_target += M_ts P_s, both channels (friction: velocity_*,
  // held load: driving_*), M_ts the pair mobilities (c G blended into the
  // near field) that couple the spheres of one rod, for every sphere pair.
  void add_disturbance(const RodGeometry& target, RodObstructionForces& target_forces, const RodGeometry& source,
                       const RodObstructionForces& source_forces) const;
  // The far field of the rods beyond interaction_reach() in this model's
  // fluid and gap (hydro/cross_rod_far_field.h).
  void set_far_field_scene(CrossRodFarField& far_field) const;
  // Beyond the screening length l = H / sqrt(12) the Green's function is
  // the Hele-Shaw potential dipole |G| = H / (24 pi mu r^2)
  // (brinkman_green.h), which decays only algebraically; the coupling of
  // two spheres relative to their own obstruction, c zeta_o |G|, falls
  // below kInteractionTolerance at
  //     r_c = max(10 l, sqrt(c zeta_o H / (24 pi mu kInteractionTolerance))).
  // Rods farther apart than r_c (nearest sphere centres) are evaluated
  // apart; the dropped coupling changes a load by ~1e-3 of itself at most.
  static constexpr double kInteractionTolerance = 1e-3;  // [-]
  double interaction_reach() const override;

  // Selected at run time; with images the coupling is solved at every
  // evaluation (it depends on where the rod is, not only on its shape).
  void set_wall_reflection(WallReflection reflection) { wall_reflection_ = reflection; }
  WallReflection wall_reflection() const { return wall_reflection_; }

  double film_friction() const { return film_friction_; }              // zeta_f [N s/m]
  double obstruction_friction() const { return obstruction_friction_; }  // zeta_o [N s/m]

 private:
  // zeta_o (I + zeta_o M)^-1 and, when the held load has its own near field,
  // zeta_o (I + zeta_o M^D)^-1 (else `driving` is left empty), 2n x 2n.
  // walls: whose images enter M (nullptr: none).
  void solve_coupling(const RodGeometry& rod, const ChannelGeometry* walls, Eigen::MatrixXd& obstruction,
                      Eigen::MatrixXd& driving) const;
  // M += the wall images (hydro/wall_images.h) in both coupling matrices
  // (coupling_driving empty: the friction's only).
  void add_wall_images(const RodGeometry& rod, const ChannelGeometry& walls, Eigen::MatrixXd& coupling,
                       Eigen::MatrixXd& coupling_driving) const;
  bool own_driving() const;
  // The pair mobility M_ik [m/(N s)] of two spheres at in-plane offset x_i -
  // x_k [m] (c G blended into the near field) for the friction and, when
  // `driving` is given, for the held load.
  void pair_mobility(const Eigen::Vector2d& offset, Eigen::Matrix2d& friction, Eigen::Matrix2d* driving) const;
  NonlocalState* own_state(ModelState* state) const;
  void evaluate_with(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out, NonlocalState* state,
                     int key, UnitObstruction* unit = nullptr) const;

  double film_friction_;
  double obstruction_friction_;
  NearFieldAtBeta near_field_;
  WallReflection wall_reflection_ = WallReflection::none;
};

}  // namespace hsrod

// One linearly implicit overdamped step of a rod, stable at steps far
// beyond the explicit limit of its stiff bonds and wall contacts.
//
// At the scales of a microfluidic rod the sphere inertia relaxes in
// m / zeta ~ 1 us, far below the steps of interest, so the rod moves in the
// overdamped (force-balance) limit, which the bond springs and wall
// contacts make stiff. Each step solves, for the displacements and rotation
// vectors dy = (dx_i, dphi_i) of all spheres,
//     (R / dt + K) dy = F_hyd(v = 0) + F_bonds(y_n) + F_walls(y_n) + F_ext,
// with R the hydrodynamic resistance (hydro/hydrodynamic_model.h), K the
// stiffness of the bonds and the wall contacts at y_n (bond Jacobian in
// closed form, rod/beam_bond_jacobian.h; wall contacts analytic); with wall
// friction also its secant resistance C about the previous velocities
// (R/dt + K + C/dt; dynamics/wall_contact.h). This is one
// Newton step of backward Euler: stable for any dt on the linear(ised)
// springs, so the step is set by accuracy, not by the 1e-9 s explicit limit.
// Bond dashpots are negligible next to the fluid friction here and are not
// applied in this integrator.
//
// The solve uses the structure of the matrix: a chain (every bond joins
// spheres i and i+1) with local drag is block-tridiagonal in 6x6 blocks and
// is factorised by block elimination (block Thomas algorithm, O(n), no
// pivoting across blocks: R/dt + K is close to symmetric positive definite),
// without allocation once the rod's size is known. Wall friction acts on
// one sphere (a 6x6 block on the diagonal) and keeps the band. Bonds that
// join spheres up to g <= 8 apart in the numbering (multi-sphere sections:
// g = spheres per section) make it block-tridiagonal in groups of g spheres
// (6g x 6g blocks, the same elimination with dense block LUs). Couplings
// off these bands (a self-contact of a folding rod between spheres further
// apart, wider bonds) take a sparse LU; a non-local (dense 3n x 3n) resistance takes a dense LU, which
// is then the step's O(n^3) cost: for a chain only of the translations it couples (the Schur
// complement, 2n x 2n for the depth-averaged models; dynamics/coupled_chain_solve.h), otherwise of
// the whole 6n x 6n matrix.
#pragma once

#include "dynamics/wall_contact.h"
#include "hydro/hydrodynamic_model.h"
#include "rod/beam_bond.h"
#include "rod/rod_layout.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <cstdint>
#include <vector>

namespace hsrod {

struct RodBond {
  int i = 0, j = 0;                // sphere indices within the rod
  BeamBondRest rest;
  BeamBondStiffness stiffness;
};

struct OverdampedRod {
  std::vector<Eigen::Vector3d> positions;         // [m]
  std::vector<Eigen::Quaterniond> orientations;   // body -> lab
  std::vector<double> radii;                      // [m]
  std::vector<RodBond> bonds;
  std::vector<Eigen::Vector3d> external_forces;   // other forces on the spheres (pairs, fixes) [N]
  std::vector<Eigen::Vector3d> external_torques;  // [N m]
  // Velocities of the previous step [m/s], [rad/s], about which wall friction
  // is linearised (dynamics/wall_contact.h). Empty: the solver's own last
  // step (rest before its first).
  std::vector<Eigen::Vector3d> velocities, angular_velocities;
  // Several rods stepped together (a cluster of rods in contact or in
  // hydrodynamic interaction, dynamics/rod_cluster.h): the rod each sphere
  // belongs to. Empty: all spheres are one rod. Spheres of different rods
  // touch when WallContactParameters::rod_contact is on; non-bonded spheres
  // of one rod when self_contact is.
  std::vector<int> rod_of_sphere;
  bool same_rod(int i, int j) const { return rod_of_sphere.empty() || rod_of_sphere[i] == rod_of_sphere[j]; }
  int size() const { return static_cast<int>(positions.size()); }
  // Sphere i's pose as a bond end (velocities zero: the step's bond loads
  // and strains depend on the configuration only).
  SphereState pose(int i) const {
    SphereState s;
    s.position = positions[i];
    s.orientation = orientations[i];
    return s;
  }
};

struct OverdampedStepResult {
  std::vector<Eigen::Vector3d> velocities;        // dx / dt [m/s]
  std::vector<Eigen::Vector3d> angular_velocities;  // dphi / dt [rad/s]
  std::vector<Eigen::Vector3d> hydrodynamic_forces;  // F_hyd at the new velocities [N]
  double largest_displacement = 0.0;              // max |dx| [m]
  bool wall_contact = false;
  bool self_contact = false;                      // non-bonded spheres touched (of one rod, or of two rods)
  bool rod_contact = false;                       // spheres of two different rods touched
  double rod_contact_force = 0.0;                 // sum of |Hertz force| between spheres of different rods [N]
  double wall_force = 0.0;                        // sum of |contact force| [N]
  std::vector<double> sphere_wall_force;          // per sphere, |wall contact force| [N] (which rod of a cluster touched)
  double friction_force = 0.0;                    // sum of |wall friction force| at the new velocities [N]
  // Wall friction at the end velocities (WallContactParameters::friction_iterations):
  // the largest relative mismatch |s_out - s| / s left between a rubbing
  // point's friction force and the law at the step's end velocities [-],
  // and the repeats of the step it took.
  double friction_mismatch = 0.0;
  int friction_repeats = 0;
};

// Where the time of a solver's steps went (wall time, steady clock).
struct OverdampedSolverStatistics {
  long steps = 0;                // steps taken
  long sphere_steps = 0;         // sum over steps of the rod's spheres
  double bond_seconds = 0.0;     // bond loads and Jacobians [s]
  double contact_seconds = 0.0;  // wall and self-contacts (search and Hertz laws) [s]
  double solve_seconds = 0.0;    // assembly, factorisation, substitution, update [s]
  long banded_steps = 0;         // steps solved block-tridiagonally (spheres or groups of spheres)
  long sparse_steps = 0;         // steps solved by the sparse LU
  long dense_steps = 0;          // steps solved by a dense LU (of the whole matrix, or of a chain's coupled translations)
  long friction_repeats = 0;     // steps repeated to put wall friction at the end velocities (counted in steps too)
  // Chains with pair contacts off the band (dynamics/chain_contact_solve.cpp):
  long capacitance_steps = 0;      // solved by the capacitance solve (counted in banded_steps)
  long capacitance_fallbacks = 0;  // refused by it, solved by the sparse LU (counted in sparse_steps)
  long capacitance_handovers = 0;  // coupled throughout (more than the dense size and the coupled
                                   // fraction), sent to the sparse LU without trying (counted in sparse_steps)
  long sparse_capacitance_steps = 0;  // of capacitance_steps, those with a sparse LU of the capacitance matrix
};

// A rod at rest in its layout (identity orientations), bonds from `material`.
OverdampedRod make_overdamped_rod(const RodLayout& layout, const BeamBondMaterial& material, double sphere_diameter);

// The step of one rod with its workspace kept between steps: the assembly
// buffers and the sparse LU's symbolic analysis (elimination tree, supernodes,
// memory) are built once and reused while the rod's sparsity pattern (bonds,
// self-contacts) stays the same. Building them from scratch every step is
// what made a 1000-sphere rod cost ~3x more per sphere than a 100-sphere one.
// Keep one solver per rod (it is tied to the rod's numbering).
class OverdampedRodSolver {
 public:
  // How the step's linear system is solved: by the cheapest method its
  // structure allows (automatic), or always by the general sparse or dense
  // LU (to check the structured paths against).
  enum class LinearSolver { automatic, sparse_lu, dense_lu };

  OverdampedRodSolver();
  ~OverdampedRodSolver();
  OverdampedRodSolver(OverdampedRodSolver&&) noexcept;
  OverdampedRodSolver& operator=(OverdampedRodSolver&&) noexcept;

  // Advances `rod` (positions, orientations) in place by dt [s].
  // `geometry` may be null (no scene walls), `walls` null (no contacts at all).
  OverdampedStepResult step(OverdampedRod& rod, const RodDrag& drag, double dt, const ChannelGeometry* geometry,
                            const WallContactParameters* walls);
  // The same, writing into `result` (its vectors keep their memory between steps).
  void step(OverdampedRod& rod, const RodDrag& drag, double dt, const ChannelGeometry* geometry,
            const WallContactParameters* walls, OverdampedStepResult& result);

  // One Newton iteration of the same backward-Euler step (for a step whose
  // contacts change within it): `rod` holds an iterate y* of the step that
  // started at (start_positions, start_orientations) = y0, and the step is
  // re-linearised about y* (bonds, wall and sphere contacts, their stiffness
  // and the set of touching spheres all evaluated at y*):
  //   (R/dt + K(y*) + C/dt) (y - y*) = F_drive + F_ext + F_bonds(y*) + F_contacts(y*) - (R + C) (y* - y0) / dt,
  // the residual of backward Euler at y* (C: the friction secant about the
  // previous velocities, as in step). `rod` is moved to y; the result holds
  // velocities (y - y0) / dt over the whole step. Iterated, this converges to
  // the backward-Euler state that the single linearised step only
  // approximates, e.g. a sphere that the step carried into a wall it did not
  // touch at y0 (no contact stiffness there) stops on the wall instead of
  // ending deep in it.
  void iterate(OverdampedRod& rod, const std::vector<Eigen::Vector3d>& start_positions,
               const std::vector<Eigen::Quaterniond>& start_orientations, const RodDrag& drag, double dt,
               const ChannelGeometry* geometry, const WallContactParameters* walls, OverdampedStepResult& result);

  // Times the factorisation's structure was analysed (a test hook: once for a
  // rod whose pattern does not change): for a chain, its band (sizes of the
  // block storage); otherwise the sparse LU's pattern.
  int pattern_analyses() const;

  // The simplified-Newton correction of the last step (an error estimate
  // that reuses the step's factorisation): `rod` is the state the
  // last step produced, `drag` the drag it used. Evaluates the
  // backward-Euler residual at the new state y1,
  //   r = F_drive + F_ext + F_bonds(y1) + F_contacts(y1) - (R + C) dy / dt
  // (dy, dt of the last step; C the wall friction's secant resistance), and
  // solves (R/dt + K + C/dt) delta = r with the last step's factors: one
  // more Newton iteration of backward Euler without a new factorisation
  // (one bond and contact evaluation and a back substitution), co-rotated
  // with each sphere's rotation in the step: delta = Q (R/dt + K)^-1 Q^T r,
  // Q_i = Exp(dphi_i), as the stiffness of a turned rod is Q K Q^T. `delta`:
  // 6n (dx_i [m], dphi_i [rad]). Returns false (delta untouched) when the
  // last step's factors are not kept (multi-sphere sections' grouped blocks)
  // or belong to a rod of another size.
  bool newton_correction(const OverdampedRod& rod, const RodDrag& drag, const ChannelGeometry* geometry,
                         const WallContactParameters* walls, Eigen::VectorXd& delta);

  // Moves `rod` by dy (6n: dx_i [m], dphi_i [rad]) as the step does:
  // orientations by Exp(dphi_i), positions by dx_i with every bond's
  // rotation taken as a finite rotation (dynamics/finite_rotation_update.h).
  // For applying newton_correction's delta.
  void displace(OverdampedRod& rod, const Eigen::VectorXd& dy);

  const OverdampedSolverStatistics& statistics() const;
  void set_linear_solver(LinearSolver method);
  // Chains with pair contacts off the band (contact clusters of rods, a
  // folded rod) with local drag: by the band elimination and capacitance
  // solve of dynamics/chain_contact_solve.cpp (true, the default), or by the
  // general dense / sparse LU (false, to check it against).
  void set_chain_contact_capacitance(bool on);

 private:
  // One linearised step (step() repeats it while it iterates wall friction).
  void step_once(OverdampedRod& rod, const RodDrag& drag, double dt, const ChannelGeometry* geometry,
                 const WallContactParameters* walls, OverdampedStepResult& result);
  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
};

// One step with a fresh workspace (convenient for one-off steps and tests;
// a time loop should keep an OverdampedRodSolver).
OverdampedStepResult overdamped_rod_step(OverdampedRod& rod, const RodDrag& drag, double dt,
                                         const ChannelGeometry* geometry, const WallContactParameters* walls);

// Whether the contact law acts between non-bonded spheres i and j of `rod`:
// self_contact for spheres of one rod, rod_contact for spheres of two rods.
inline bool sphere_pair_contact_on(const OverdampedRod& rod, const WallContactParameters& walls, int i, int j) {
  return rod.same_rod(i, j) ? walls.self_contact : walls.rod_contact;
}
// Whether any sphere pair of `rod` can be in contact under `walls`.
inline bool sphere_pair_search_on(const OverdampedRod& rod, const WallContactParameters& walls) {
  return rod.size() > 1 && (walls.self_contact || (walls.rod_contact && !rod.rod_of_sphere.empty()));
}

// A sphere of the pair search in its cell of the plane (rod_pair_search.cpp).
struct PairSearchCell {
  std::int64_t cx, cy;
  int sphere;
};
// The pair search's cell list, kept by a caller that searches every step:
// `cells` in cell order from the previous call (re-sorted when the same
// spheres come again), and the counting sort's buffers.
struct PairSearchCells {
  std::vector<PairSearchCell> cells, sorting;
  std::vector<int> cell_start;
};

// nearby_sphere_pairs with its cell list and pairs in the caller's buffers
// (kept by a solver: the cells of the previous call of the same rod are
// re-sorted, not sorted anew). With sort_pairs false the pairs come in cell order.
void find_nearby_pairs(const std::vector<Eigen::Vector3d>& positions, double reach, PairSearchCells& cells,
                       std::vector<std::pair<int, int>>& pairs, bool sort_pairs);

// Pairs (i < j) of spheres of the rod whose centres are within `reach` [m]
// of each other in x and in y (a superset of the touching pairs), in
// lexicographic order (sorted false: in cell order), found through a cell
// list: O(n), not O(n^2).
std::vector<std::pair<int, int>> nearby_sphere_pairs(const std::vector<Eigen::Vector3d>& positions, double reach,
                                                     bool sorted = true);

}  // namespace hsrod

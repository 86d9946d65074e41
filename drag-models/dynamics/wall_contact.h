// Sphere-wall contact with the scene's walls: the planform walls (side walls
// and obstacles, from ChannelGeometry's signed distance) and the two gap
// walls z = gap_bottom and z = gap_bottom + H. Hertz normal force of an
// elastic sphere on a rigid wall (Johnson 1985, eq. 4.22),
//     F = 4/3 E* sqrt(r) delta^(3/2),  E* = E / (1 - nu^2),
// with its stiffness dF/d delta = 2 E* sqrt(r delta) for implicit steps.
// Tangential wall friction: regularised Coulomb (wall_friction below);
// contacts between spheres of one rod are frictionless.
#pragma once

#include "geometry/channel_geometry.h"

#include <Eigen/Core>

#include <array>

namespace hsrod {

struct WallContactParameters {
  double youngs_modulus = 0.0;  // E of the spheres [Pa]
  double poisson_ratio = 0.3;   // nu [-]
  double gap_bottom = 0.0;      // z of the lower gap wall [m]
  bool planform_walls = true;   // side walls and obstacles
  bool gap_walls = true;        // the two walls bounding the gap
  bool self_contact = true;     // non-bonded spheres of one rod touch (a folding rod)
  // Hertz contact between spheres of different rods of one step (a cluster
  // of rods solved together: OverdampedRod::rod_of_sphere); off: rods of a
  // cluster pass through each other (fix rod/implicit refuses overlaps then).
  bool rod_contact = false;
  // Coulomb friction between touching spheres (other rods, and non-bonded
  // spheres of one rod) mu_rr [-]; 0 = frictionless. Regularised with slip_velocity.
  double rod_friction_coefficient = 0.0;
  double friction_coefficient = 0.0;  // Coulomb wall friction mu_fr [-] (paper Table 1: 0.5); 0 = frictionless
  double slip_velocity = 1e-6;        // v_s of the regularised law [m/s]: below it friction is viscous
  // Wall friction at the step's end velocities (backward Euler).
  // The step takes each rubbing point's secant about the previous step's
  // slip; where that leaves a point's friction off the law at the step's
  // end velocities by more than friction_tolerance mu F_n, the contacts'
  // friction forces are solved for with the step's own factorisation (the
  // Delassus operator of the contacts, OverdampedRodSolver::step) and the
  // step repeated with them, up to friction_iterations times
  // (OverdampedStepResult::friction_mismatch says what is left; the
  // accuracy guard rejects a step left off by more than max_step_error).
  // 0: the secant about the previous slip only, which can exceed the
  // Coulomb bound mu F_n many times over in the step a contact starts to
  // slide, and stops a sliding sphere over a number of steps rather than a
  // time.
  int friction_iterations = 30;       // [-]
  double friction_tolerance = 1e-3;   // relative friction-force mismatch [-]
  double effective_modulus() const { return youngs_modulus / (1.0 - poisson_ratio * poisson_ratio); }
};

// One wall touched by a sphere: the unit normal into the fluid and the
// magnitude of the Hertz normal force.
struct WallContactPoint {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // [-]
  double normal_force = 0.0;                          // [N]
};

struct WallContact {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();       // on the sphere [N]
  Eigen::Matrix3d stiffness = Eigen::Matrix3d::Zero();   // -dF/dx [N/m]
  bool touching = false;
  int points = 0;                                        // walls touched (planform + two gap walls)
  std::array<WallContactPoint, 3> point;                 // the first `points` are valid
};

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

// Regularised Coulomb friction of a sphere of radius r on a wall, in the form
// the implicit step needs. The slip velocity of the contact point (at r_c = -r n
// from the centre) for sphere velocity u = (v, omega) is
//     v_t = G u,   G = [ (I - n n^T)   r [n]x ]   (3x6),
// and the law is F_t = -mu F_n v_t / max(|v_t|, v_s): Coulomb sliding above the
// slip velocity v_s, a viscous stick (coefficient mu F_n / v_s) below it, so a
// sphere under a tangential load T < mu F_n creeps at T v_s / (mu F_n) < v_s.
// Force and torque on the sphere are G^T F_t. The step linearises it about
// the previous velocity u0 by its secant (lagged coefficient):
//     loads = -c G^T G u,   c = mu F_n / max(|G u0|, v_s)   [N s/m],
// exact at u = u0 and for every u while |v_t| < v_s; c G^T G (symmetric,
// positive semi-definite) enters the step's matrix as c G^T G / dt. Unlike a
// Newton tangent, whose slope along the slip direction vanishes and lets the
// velocity overshoot through zero (stick-slip chatter), the secant law only
// dissipates, so the implicit step stays stable at any dt.
// Returns the 6x6 resistance c G^T G [N s/m, N s, N m s] (zero when mu or
// F_n is zero).
Matrix6d wall_friction_resistance(const WallContactPoint& contact, double radius, double friction_coefficient,
                                  double slip_velocity, const Vector6d& previous_velocity);
// The same secant about a given slip speed `slip` [m/s] (c = mu F_n / max(slip, v_s)).
Matrix6d wall_friction_resistance_at_slip(const WallContactPoint& contact, double radius, double friction_coefficient,
                                          double slip_velocity, double slip);
// |v_t| = |G u|, the slip speed of the contact point for sphere velocity u = (v, omega) [m/s].
double wall_slip_speed(const WallContactPoint& contact, double radius, const Vector6d& velocity);
// v_t = G u, the slip velocity of the contact point [m/s].
Eigen::Vector3d wall_slip(const WallContactPoint& contact, double radius, const Vector6d& velocity);
// The law's friction force on the sphere at the contact point for a slip
// velocity w: -mu F_n w / max(|w|, v_s) [N].
Eigen::Vector3d wall_friction_force(const WallContactPoint& contact, double friction_coefficient,
                                    double slip_velocity, const Eigen::Vector3d& slip);
// G = [ (I - n n^T)  r [n]x ] (3x6): the slip velocity of the contact point
// is G u for sphere velocity u = (v, omega); G^T f the loads of a contact force f.
Eigen::Matrix<double, 3, 6> wall_slip_operator(const WallContactPoint& contact, double radius);

// Hertz contact between two spheres of one rod (E* = E / (2 (1 - nu^2)),
// R* = r_i r_j / (r_i + r_j)): the force on sphere i (on j: minus it) and the
// stiffness -dF_i/dx_i. Zero when they do not overlap.
WallContact sphere_contact(const WallContactParameters& parameters, const Eigen::Vector3d& centre_i, double radius_i,
                           const Eigen::Vector3d& centre_j, double radius_j);

using Matrix12d = Eigen::Matrix<double, 12, 12>;
using Vector12d = Eigen::Matrix<double, 12, 1>;

// The same regularised Coulomb law between two touching spheres i and j,
// `contact.normal` the unit normal from j to i and `contact.normal_force`
// the Hertz force magnitude. The contact point is at -r_i n from i and
// +r_j n from j; the slip of i's surface over j's for u = (v_i, omega_i,
// v_j, omega_j) is
//     v_t = G u,  G = [ (I - n n^T)  r_i [n]x  -(I - n n^T)  r_j [n]x ]  (3x12),
// the friction force on i is F_t = -mu F_n v_t / max(|v_t|, v_s) (on j:
// -F_t), and the loads on (i, j) are G^T F_t. Secant about the previous
// velocities u0 as for a wall: returns c G^T G, c = mu F_n / max(|G u0|, v_s),
// symmetric positive semi-definite (it only dissipates; a rod resting on
// another sticks below mu F_n and slides at mu F_n above).
Matrix12d sphere_friction_resistance(const WallContactPoint& contact, double radius_i, double radius_j,
                                     double friction_coefficient, double slip_velocity,
                                     const Vector12d& previous_velocity);

WallContact wall_contact(const ChannelGeometry& geometry, const WallContactParameters& parameters,
                         const Eigen::Vector3d& centre, double radius);

}  // namespace hsrod

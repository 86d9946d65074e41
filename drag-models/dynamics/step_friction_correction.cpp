// Wall friction at the step's end velocities (backward Euler's friction):
// how far the step's secant friction is off the law, and the correction
// loads from the contacts' Delassus operator that step() repeats it with.
#include "dynamics/contact_friction_problem.h"
#include "dynamics/overdamped_rod_step_internal.h"

#include <algorithm>
#include <cmath>

namespace hsrod {

namespace {

// A rubbing wall-contact point: contact `contact`'s k-th point on `sphere`,
// its slip operator G (slip = G (v, omega)), tangent basis, mu F_n [N] and
// secant coefficient [N s/m].
struct RubbingPoint {
  int contact, k, sphere;
  Eigen::Matrix<double, 3, 6> g;
  Eigen::Matrix<double, 3, 2> basis;
  double sliding, secant;
};

std::vector<RubbingPoint> rubbing_points(const std::vector<SphereWallContact>& wall_contacts,
                                         const OverdampedRod& rod, double mu) {
  std::vector<RubbingPoint> points;
  for (std::size_t m = 0; m < wall_contacts.size(); ++m) {
    const SphereWallContact& c = wall_contacts[m];
    if (!c.rubbing) continue;
    for (int k = 0; k < c.points; ++k) {
      const double sliding = mu * c.point[k].normal_force;
      if (!(sliding > 0.0)) continue;
      const Eigen::Vector3d& n = c.point[k].normal;
      Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
      Eigen::Matrix<double, 3, 2> basis;
      basis << t1, t2;
      points.push_back({static_cast<int>(m), k, c.sphere, wall_slip_operator(c.point[k], rod.radii[c.sphere]), basis,
                        sliding, c.secant[k]});
    }
  }
  return points;
}

}  // namespace

// Sphere i's displacement (dx, dphi) in the step's linear system, over the
// whole step from its start: in a Newton iteration (iterate()) the
// iterate's offset plus dy. (Not the finite-rotation position update, which
// changes the slip, a small difference of v and r omega for a rolling
// sphere, by more than v_s.)
Vector6d OverdampedRodSolver::Workspace::step_displacement(int i) const {
  Vector6d moved = step_dy.segment<6>(6 * i);
  if (origin_positions) moved += origin_offset.segment<6>(6 * i);
  return moved;
}

// The largest relative mismatch |law - applied| / (mu F_n) of a rubbing
// sphere's tangential wall friction at the step's end velocities.
double OverdampedRodSolver::Workspace::friction_mismatch(const OverdampedRod& rod, double dt,
                                                         const WallContactParameters& walls) const {
  const double mu = walls.friction_coefficient, v_s = walls.slip_velocity;
  double mismatch = 0.0;
  for (const SphereWallContact& c : wall_contacts) {
    if (!c.rubbing) continue;
    Vector6d u = step_displacement(c.sphere);
    u /= dt;
    // The correction's force at each point is spread over the sphere's
    // points below; judge the sphere's total tangential friction.
    Eigen::Vector3d law = Eigen::Vector3d::Zero(), applied = c.friction_load.head<3>();
    double sliding = 0.0;
    for (int k = 0; k < c.points; ++k) {
      const Eigen::Vector3d slip = wall_slip(c.point[k], rod.radii[c.sphere], u);
      law += wall_friction_force(c.point[k], mu, v_s, slip);
      applied -= c.secant[k] * slip;
      sliding += mu * c.point[k].normal_force;
    }
    if (sliding > 0.0) mismatch = std::max(mismatch, (law - applied).norm() / sliding);
  }
  return mismatch;
}

// The slips the step's secants were taken about, for its repeat.
void OverdampedRodSolver::Workspace::keep_abouts() {
  given_slip.assign(3 * wall_contacts.size(), Eigen::Vector3d::Zero());
  for (std::size_t m = 0; m < wall_contacts.size(); ++m)
    for (int k = 0; k < wall_contacts[m].points; ++k) given_slip[3 * m + k] = wall_contacts[m].about[k];
}

// The correction loads g (given_load, point_load) that put the rubbing
// points' friction at the step's end slips, with the step's secants kept
// (given_slip). False when there is nothing to correct or the factors
// cannot be re-solved.
bool OverdampedRodSolver::Workspace::set_friction_correction(const OverdampedRod& rod, double dt,
                                                             const WallContactParameters& walls) {
  const std::vector<RubbingPoint> points = rubbing_points(wall_contacts, rod, walls.friction_coefficient);
  const int unknowns = 2 * static_cast<int>(points.size());
  if (unknowns == 0) return false;
  friction_columns.resize(6 * rod.size(), unknowns);
  Eigen::VectorXd column(6 * rod.size());
  bool solved = true;
  for (int p = 0; p < static_cast<int>(points.size()) && solved; ++p)
    for (int a = 0; a < 2; ++a) {
      column.setZero();
      column.segment<6>(6 * points[p].sphere) = points[p].g.transpose() * points[p].basis.col(a);
      solved = solve_kept(column);
      friction_columns.col(2 * p + a) = column;
    }
  if (!solved) return false;
  // Slips (in each point's basis) of the step as taken, the Delassus
  // operator M, and the correction loads g already applied [m/s, N].
  Eigen::VectorXd w0(unknowns), g0(unknowns);
  Eigen::MatrixXd delassus(unknowns, unknowns);
  for (int p = 0; p < static_cast<int>(points.size()); ++p) {
    const RubbingPoint& pt = points[p];
    const Eigen::Matrix<double, 2, 6> bg = pt.basis.transpose() * pt.g;
    w0.segment<2>(2 * p) = bg * step_displacement(pt.sphere) / dt;
    for (int q = 0; q < unknowns; ++q)
      delassus.block<2, 1>(2 * p, q) = bg * friction_columns.col(q).segment<6>(6 * pt.sphere) / dt;
    // The correction force already applied at this point (a repeat).
    g0.segment<2>(2 * p) = given_load.empty() ? Eigen::Vector2d::Zero()
                                              : Eigen::Vector2d(pt.basis.transpose() * point_load[3 * pt.contact + pt.k]);
  }
  // The friction forces at the step's end slips (contact_friction_problem.h).
  std::vector<FrictionPointLaw> laws;
  laws.reserve(points.size());
  double smallest_sliding = HUGE_VAL;
  for (const RubbingPoint& pt : points) {
    laws.push_back({pt.sliding, pt.secant});
    smallest_sliding = std::min(smallest_sliding, pt.sliding);
  }
  const Eigen::VectorXd force = contact_friction_correction(delassus, w0, g0, laws, walls.slip_velocity,
                                                            1e-3 * walls.friction_tolerance * smallest_sliding);
  // The correction loads per contact point (lab frame) and per sphere.
  point_load.assign(3 * wall_contacts.size(), Eigen::Vector3d::Zero());
  given_load.assign(wall_contacts.size(), Vector6d::Zero());
  keep_abouts();
  for (int p = 0; p < static_cast<int>(points.size()); ++p) {
    const Eigen::Vector3d load = points[p].basis * force.segment<2>(2 * p);
    point_load[3 * points[p].contact + points[p].k] = load;
    given_load[points[p].contact] += points[p].g.transpose() * load;
  }
  return true;
}

}  // namespace hsrod

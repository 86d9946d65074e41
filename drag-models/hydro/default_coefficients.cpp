// Built-in confinement coefficients (ConfinementTable::default_table()).
//
// Sphere columns, from published results:
//  - sphere_friction: Faxen's series for a sphere midway between two walls
//    (Happel & Brenner 1965, eq. 7-4.28). Ganatos et al. (1980) note the
//    series degrades beyond 2a/H ~ 0.5; rows above beta = 0.6 extrapolate
//    it and are meant to be replaced by calibration against resolved runs.
//  - sphere_driving: Faxen's law in the parabolic gap profile (u_max =
//    3/2 U): a free sphere at the mid-plane moves with u_max (1 - beta^2/3);
//    tends to the maximal fluid velocity as beta -> 0 (Berthet et al. 2013).
// Rod columns (level 2), derived from level 3: the friction per sphere of a
// rigid 10-sphere rod (the paper's N) moving along / across its axis, over
// the isolated sphere's, and its force-free velocity along / across the
// axis, from the non-local model (hydro/nonlocal_model.h) in a uniform
// stream. This gives the chain shielding (parallel friction about half of
// independent spheres at moderate confinement) and Berthet et al.'s
// orientation anisotropy (a perpendicular rod moves faster, weakly below
// beta ~ 0.5) as a local closure.
#include "hydro/confinement_coefficients.h"
#include "common/math_constants.h"
#include "hydro/nonlocal_model.h"

#include <Eigen/Dense>

namespace hsrod {

namespace {

// Uniform gap-averaged stream of speed 1 m/s along x, for deriving the rod columns.
class UniformStream : public BackgroundFlow {
 public:
  explicit UniformStream(double gap_height) : geometry_(1.0, 1.0, gap_height, -0.5, -0.5) {}
  Eigen::Vector2d velocity(double, double) const override { return {1.0, 0.0}; }
  Eigen::Matrix2d velocity_gradient(double, double) const override { return Eigen::Matrix2d::Zero(); }
  double pressure(double, double) const override { return 0.0; }
  double mean_velocity() const override { return 1.0; }
  const ChannelGeometry& geometry() const override { return geometry_; }
  std::string description() const override { return "uniform stream"; }

 private:
  ChannelGeometry geometry_;
};

struct RigidRodResponse {
  double friction_per_sphere;  // [N s/m]
  double free_velocity;        // along the stream [m/s]
};

RigidRodResponse rigid_rod(const HydrodynamicModel& model, const BackgroundFlow& flow, int n, double d, bool along) {
  RodGeometry rod;
  rod.sphere_diameter = d;
  for (int k = 0; k < n; ++k) {
    const double s = (k - 0.5 * (n - 1)) * d;
    rod.positions.push_back(along ? Eigen::Vector3d(s, 0, 0) : Eigen::Vector3d(0, s, 0));
  }
  RodDrag drag;
  model.evaluate(rod, flow, drag);
  Eigen::Matrix3d total_resistance = Eigen::Matrix3d::Zero();
  Eigen::Vector3d total_driving = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) {
    total_driving += drag.driving_force[i];
    for (int k = 0; k < n; ++k) total_resistance += drag.coupled_resistance.block<3, 3>(3 * i, 3 * k);
  }
  return {total_resistance(0, 0) / n, (total_resistance.inverse() * total_driving).x()};
}

}  // namespace

ConfinementTable ConfinementTable::default_table() {
  const double d = 1.0;  // coefficients are dimensionless: any d, H = d / beta, mu = 1
  std::vector<Row> sphere_rows;
  for (int k = 0; k <= 17; ++k) {
    const double beta = 0.05 * k;  // 0 .. 0.85
    ConfinementCoefficients c;
    c.sphere_friction = faxen_midplane_friction(beta);
    c.sphere_driving = 1.5 * (1.0 - beta * beta / 3.0);
    c.parallel_driving = c.perpendicular_driving = c.sphere_driving;
    sphere_rows.push_back({beta, c});
  }
  const ConfinementTable spheres(sphere_rows, "sphere columns only");
  std::vector<Row> rows = sphere_rows;
  for (Row& r : rows) {
    if (r.beta <= 0.0) continue;  // beta -> 0: no interaction, independent spheres
    const HydrodynamicParameters p{1.0, d / r.beta, d};
    const NonlocalRodModel model(p, spheres);
    const UniformStream stream(p.gap_height);
    const double zeta = 3.0 * kPi * d * r.c.sphere_friction;
    const RigidRodResponse along = rigid_rod(model, stream, 10, d, true);
    const RigidRodResponse across = rigid_rod(model, stream, 10, d, false);
    r.c.parallel_friction = along.friction_per_sphere / zeta;
    r.c.perpendicular_friction = across.friction_per_sphere / zeta;
    r.c.parallel_driving = along.free_velocity;
    r.c.perpendicular_driving = across.free_velocity;
  }
  return ConfinementTable(std::move(rows),
                          "built-in defaults: Faxen mid-plane friction (Happel & Brenner 1965), Faxen-law driving; "
                          "rod columns from the level-3 model for a rigid 10-sphere rod");
}

}  // namespace hsrod

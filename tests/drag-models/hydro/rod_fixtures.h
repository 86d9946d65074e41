// Rigid straight rods in a uniform stream, for the hydrodynamic model tests.
#pragma once

#include "flow/uniform_flow.h"
#include "hydro/hydrodynamic_model.h"

#include <Eigen/Dense>

#include <cmath>
#include <string>

namespace hsrod_test {

// Uniform gap-averaged stream of 1 m/s along x in a wide slit (gap height H
// [m], 1 m unless given: level 4 needs the model's H).
class UniformStream : public hsrod::UniformFlow {
 public:
  explicit UniformStream(double gap = 1.0) : UniformFlow(wide_slit(gap, {1.0, 0.0})) {}
};

// N spheres of diameter d, axis at angle theta from the flow (x) direction:
// t = (cos theta, sin theta), sphere 0 at the downstream end for theta < 90 deg.
inline hsrod::RodGeometry straight_rod(int n, double d, double theta) {
  hsrod::RodGeometry rod;
  rod.sphere_diameter = d;
  const Eigen::Vector3d t(std::cos(theta), std::sin(theta), 0.0);
  for (int k = 0; k < n; ++k) rod.positions.push_back((0.5 * (n - 1) - k) * d * t);
  return rod;
}

struct RigidMotion {
  Eigen::Vector3d velocity;     // [m/s]
  Eigen::Matrix3d resistance;   // total translational resistance [N s/m]
};

// Force-free rigid translation (a straight rod in a uniform stream has no torque).
inline RigidMotion free_rigid_translation(const hsrod::HydrodynamicModel& model, const hsrod::RodGeometry& rod,
                                          const hsrod::BackgroundFlow& flow) {
  hsrod::RodDrag drag;
  model.evaluate(rod, flow, drag);
  const int n = rod.size();
  Eigen::Matrix3d total = Eigen::Matrix3d::Zero();
  Eigen::Vector3d driving = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) {
    driving += drag.driving_force[i];
    if (drag.coupled()) {
      for (int k = 0; k < n; ++k) total += drag.coupled_resistance.block<3, 3>(3 * i, 3 * k);
    } else {
      total += drag.resistance[i];
    }
  }
  return {total.inverse() * driving, total};
}

}  // namespace hsrod_test

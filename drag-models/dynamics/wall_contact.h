// Sphere-wall contact with the scene's walls: the planform walls (side walls
// and obstacles, from ChannelGeometry's signed distance) and the two gap
// walls z = gap_bottom and z = gap_bottom + H. Hertz normal force of an
// elastic sphere on a rigid wall (Johnson 1985, eq. 4.22),
//     F = 4/3 E* sqrt(r) delta^(3/2),  E* = E / (1 - nu^2),
// with its stiffness dF/d delta = 2 E* sqrt(r delta) for implicit steps.
// Frictionless: tangential wall friction is not modelled.
#pragma once

#include "geometry/channel_geometry.h"

#include <Eigen/Core>

namespace hsrod {

struct WallContactParameters {
  double youngs_modulus = 0.0;  // E of the spheres [Pa]
  double poisson_ratio = 0.3;   // nu [-]
  double gap_bottom = 0.0;      // z of the lower gap wall [m]
  bool planform_walls = true;   // side walls and obstacles
  bool gap_walls = true;        // the two walls bounding the gap
  bool self_contact = true;     // non-bonded spheres of one rod touch (a folding rod)
  double effective_modulus() const { return youngs_modulus / (1.0 - poisson_ratio * poisson_ratio); }
};

struct WallContact {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();       // on the sphere [N]
  Eigen::Matrix3d stiffness = Eigen::Matrix3d::Zero();   // -dF/dx [N/m]
  bool touching = false;
};

// Hertz contact between two spheres of one rod (E* = E / (2 (1 - nu^2)),
// R* = r_i r_j / (r_i + r_j)): the force on sphere i (on j: minus it) and the
// stiffness -dF_i/dx_i. Zero when they do not overlap.
WallContact sphere_contact(const WallContactParameters& parameters, const Eigen::Vector3d& centre_i, double radius_i,
                           const Eigen::Vector3d& centre_j, double radius_j);

WallContact wall_contact(const ChannelGeometry& geometry, const WallContactParameters& parameters,
                         const Eigen::Vector3d& centre, double radius);

}  // namespace hsrod

// One linearly implicit overdamped step of a rod (DESIGN.md, "Time
// integration and stability").
//
// At the scales of a microfluidic rod the sphere inertia relaxes in
// m / zeta ~ 1 us, far below the steps of interest, so the rod moves in the
// overdamped (force-balance) limit, which the bond springs and wall
// contacts make stiff. Each step solves, for the displacements and rotation
// vectors dy = (dx_i, dphi_i) of all spheres,
//     (R / dt + K) dy = F_hyd(v = 0) + F_bonds(y_n) + F_walls(y_n) + F_ext,
// with R the hydrodynamic resistance (hydro/hydrodynamic_model.h), K the
// stiffness of the bonds and the wall contacts at y_n (bond Jacobian by
// central differences of the bond law, wall contacts analytic). This is one
// Newton step of backward Euler: stable for any dt on the linear(ised)
// springs, so the step is set by accuracy, not by the 1e-9 s explicit limit.
// Bond dashpots are negligible next to the fluid friction here and are not
// applied in this integrator.
#pragma once

#include "dynamics/wall_contact.h"
#include "hydro/hydrodynamic_model.h"
#include "rod/beam_bond.h"
#include "rod/rod_layout.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

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
  int size() const { return static_cast<int>(positions.size()); }
};

struct OverdampedStepResult {
  std::vector<Eigen::Vector3d> velocities;        // dx / dt [m/s]
  std::vector<Eigen::Vector3d> angular_velocities;  // dphi / dt [rad/s]
  std::vector<Eigen::Vector3d> hydrodynamic_forces;  // F_hyd at the new velocities [N]
  double largest_displacement = 0.0;              // max |dx| [m]
  bool wall_contact = false;
  bool self_contact = false;                      // non-bonded spheres of the rod touched
  double wall_force = 0.0;                        // sum of |contact force| [N]
};

// A rod at rest in its layout (identity orientations), bonds from `material`.
OverdampedRod make_overdamped_rod(const RodLayout& layout, const BeamBondMaterial& material, double sphere_diameter);

// Advances `rod` (positions, orientations) in place by dt [s].
// `walls` may be null (no wall contact).
OverdampedStepResult overdamped_rod_step(OverdampedRod& rod, const RodDrag& drag, double dt,
                                         const ChannelGeometry* geometry, const WallContactParameters* walls);

// Bond loads and their 12x12 Jacobian (d loads / d (x_i, phi_i, x_j, phi_j))
// by central differences; loads ordered (F_i, T_i, F_j, T_j).
void beam_bond_jacobian(const SphereState& si, const SphereState& sj, const RodBond& bond,
                        Eigen::Matrix<double, 12, 1>& loads, Eigen::Matrix<double, 12, 12>& jacobian);

}  // namespace hsrod

// In-plane rigid-body reduction of a rod's hydrodynamic load:
// for a rigid planar motion q = (V_x, V_y, Omega_z) about the centroid c of
// the sphere centres, sphere i moves with v_i = J_i q = (V_x - Omega (y_i - c_y),
// V_y + Omega (x_i - c_x), 0) and spins with omega_i = Omega e_z. With the
// model's affine load F = d - R v, T_i = t_i - r_i omega_i
// (hydrodynamic_model.h) the rod's in-plane force and torque about c are
//     Q(q) = D - R_rigid q,   D = sum J_i^T d_i + sum t_i,z e_3,
//     R_rigid = J^T R J + (sum r_i) e_3 e_3^T    (3 x 3, symmetric),
// and the free (force- and torque-free) rigid velocity is R_rigid^-1 D. The
// drift angle is the angle of the free translation against the local
// background flow at c (Berthet et al., Phys. Fluids 25, 2013: tilted confined
// rods drift sideways).
#pragma once

#include "flow/background_flow.h"
#include "hydro/hydrodynamic_model.h"

#include <Eigen/Core>

#include <vector>

namespace hsrod {

struct RigidRodLoad {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();        // centroid of the sphere centres [m]
  // (V_x, V_y, Omega_z) -> (F_x, F_y, T_z): [N s/m] translation, [N s] coupling, [N m s] rotation.
  Eigen::Matrix3d resistance = Eigen::Matrix3d::Zero();
  Eigen::Vector3d driving = Eigen::Vector3d::Zero();        // (F_x, F_y, T_z) on the rod at rest [N, N, N m]
  Eigen::Vector3d free_velocity = Eigen::Vector3d::Zero();  // R_rigid^-1 D: (V_x, V_y [m/s], Omega_z [1/s])
  // (F_x, F_y, T_z) on the rod moving rigidly with q.
  Eigen::Vector3d load(const Eigen::Vector3d& q) const { return driving - resistance * q; }
};

RigidRodLoad rigid_rod_load(const RodGeometry& rod, const RodDrag& drag);

// Velocities (3n, sphere by sphere) of the rigid motion q about `centre`.
Eigen::VectorXd rigid_sphere_velocities(const RodGeometry& rod, const Eigen::Vector2d& centre,
                                        const Eigen::Vector3d& q);

// In-plane force and z-torque about `centre` [N, N, N m] of per-sphere forces
// (3n) and torques (one 3-vector per sphere).
Eigen::Vector3d rod_in_plane_load(const RodGeometry& rod, const Eigen::Vector2d& centre,
                                  const Eigen::VectorXd& forces, const std::vector<Eigen::Vector3d>& torques);

// Angle [rad] from the background velocity at the rod centre to the free
// translation (V_x, V_y), in (-pi, pi]; 0 if either vanishes.
double drift_angle(const RigidRodLoad& load, const BackgroundFlow& flow);

}  // namespace hsrod

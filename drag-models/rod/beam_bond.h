// Elastic beam bond between two spheres of a rod.
//
// The bond carries the four springs of the bonded-particle rod models of
// Guo et al. (2013, Powder Technol. 249) and Schramm et al. (2019, Powder
// Technol. 344): normal (axial), shear, bending and twisting, with
// stiffnesses of a beam of length L0, area A, second moment I and polar
// moment J = 2 I:
//     k_n = E A / L0,  k_s = G A / L0,  k_b = E I / L0,  k_t = G J / L0.
// Unlike the incremental form of those papers, the deformation is measured
// from the spheres' current orientations against a recorded rest state
// (a co-rotational formulation), so the bond has a potential energy, does
// not drift, and its state is just the rest geometry recorded at creation.
// Damping: each spring gets a dashpot at a fraction `damping_ratio` of its
// critical damping (the paper's bond damping coefficient beta_damp).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hsrod {

// Material and cross-section of a bond (SI).
struct BeamBondMaterial {
  double youngs_modulus = 0.0;   // E [Pa]
  double poisson_ratio = 0.0;    // nu [-]
  double bond_diameter = 0.0;    // diameter of the bond's circular section [m]
  double damping_ratio = 0.0;    // fraction of critical damping of each spring [-]

  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }  // G [Pa]
  double area() const;            // A = pi d^2 / 4 [m^2]
  double second_moment() const;   // I = pi d^4 / 64 [m^4]
};

// Spring constants of one bond of rest length L0.
struct BeamBondStiffness {
  double axial = 0.0;      // k_n [N/m]
  double shear = 0.0;      // k_s [N/m]
  double bending = 0.0;    // k_b [N m/rad]
  double twisting = 0.0;   // k_t [N m/rad]

  static BeamBondStiffness from_material(const BeamBondMaterial& material, double rest_length);
};

// What a bond remembers of its rest (stress-free) configuration.
struct BeamBondRest {
  Eigen::Vector3d rest_vector_in_frame_i = Eigen::Vector3d::Zero();  // x_j - x_i in i's body frame [m]
  Eigen::Quaterniond rest_relative_rotation = Eigen::Quaterniond::Identity();  // q_i^-1 q_j at rest

  double rest_length() const { return rest_vector_in_frame_i.norm(); }  // [m]
  // Records the current configuration as the rest state.
  static BeamBondRest from_current(const Eigen::Vector3d& x_i, const Eigen::Quaterniond& q_i,
                                   const Eigen::Vector3d& x_j, const Eigen::Quaterniond& q_j);
};

// Kinematic state of one sphere (SI).
struct SphereState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();          // [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // body -> lab
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // [m/s]
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // [rad/s], lab frame
};

// Dashpot constants of one bond (critical fractions turned into N s/m etc).
struct BeamBondDamping {
  double axial = 0.0;      // [N s/m]
  double shear = 0.0;      // [N s/m]
  double bending = 0.0;    // [N m s/rad]
  double twisting = 0.0;   // [N m s/rad]

  // c = 2 zeta sqrt(k m_eff): m_eff = reduced mass of the two spheres [kg],
  // inertia_eff = reduced moment of inertia [kg m^2].
  static BeamBondDamping critical_fraction(double damping_ratio, const BeamBondStiffness& k,
                                           double reduced_mass, double reduced_inertia);
};

// Loads of one bond on its two spheres (lab frame). F_i = -force_on_j.
struct BeamBondLoads {
  Eigen::Vector3d force_on_j = Eigen::Vector3d::Zero();   // [N]
  Eigen::Vector3d torque_on_i = Eigen::Vector3d::Zero();  // [N m]
  Eigen::Vector3d torque_on_j = Eigen::Vector3d::Zero();  // [N m]
  double elastic_energy = 0.0;                            // [J]
  double axial_strain = 0.0;                              // (|x_j - x_i| - L0)/L0 [-]
};

BeamBondLoads evaluate_beam_bond(const SphereState& sphere_i, const SphereState& sphere_j,
                                 const BeamBondRest& rest, const BeamBondStiffness& stiffness,
                                 const BeamBondDamping& damping);

// Rotation vector (axis * angle, angle in [0, pi]) of a unit quaternion.
Eigen::Vector3d rotation_vector(const Eigen::Quaterniond& q);
// Unit quaternion of a rotation vector.
Eigen::Quaterniond quaternion_from_rotation_vector(const Eigen::Vector3d& phi);

}  // namespace hsrod

#include "common/math_constants.h"
#include "rod/beam_bond.h"

#include <cmath>

namespace hsrod {

namespace {
using hsrod::kPi;
}

double BeamBondMaterial::area() const { return kPi * bond_diameter * bond_diameter / 4.0; }

double BeamBondMaterial::second_moment() const {
  const double d2 = bond_diameter * bond_diameter;
  return kPi * d2 * d2 / 64.0;
}

BeamBondStiffness BeamBondStiffness::from_material(const BeamBondMaterial& m, double rest_length) {
  BeamBondStiffness k;
  const double polar_moment = 2.0 * m.second_moment();  // J of a circular section [m^4]
  k.axial = m.youngs_modulus * m.area() / rest_length;
  k.shear = m.shear_modulus() * m.area() / rest_length;
  k.bending = m.youngs_modulus * m.second_moment() / rest_length;
  k.twisting = m.shear_modulus() * polar_moment / rest_length;
  return k;
}

BeamBondRest BeamBondRest::from_current(const Eigen::Vector3d& x_i, const Eigen::Quaterniond& q_i,
                                        const Eigen::Vector3d& x_j, const Eigen::Quaterniond& q_j) {
  BeamBondRest rest;
  rest.rest_vector_in_frame_i = q_i.conjugate() * (x_j - x_i);
  rest.rest_relative_rotation = (q_i.conjugate() * q_j).normalized();
  return rest;
}

BeamBondDamping BeamBondDamping::critical_fraction(double zeta, const BeamBondStiffness& k,
                                                   double reduced_mass, double reduced_inertia) {
  BeamBondDamping c;
  c.axial = 2.0 * zeta * std::sqrt(k.axial * reduced_mass);
  c.shear = 2.0 * zeta * std::sqrt(k.shear * reduced_mass);
  c.bending = 2.0 * zeta * std::sqrt(k.bending * reduced_inertia);
  c.twisting = 2.0 * zeta * std::sqrt(k.twisting * reduced_inertia);
  return c;
}

Eigen::Vector3d rotation_vector(const Eigen::Quaterniond& q_in) {
  Eigen::Quaterniond q = q_in;
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // shortest rotation
  const Eigen::Vector3d v = q.vec();
  const double s = v.norm();
  if (s < 1e-12) return 2.0 * v;  // small-angle limit, exact to O(angle^3)
  const double angle = 2.0 * std::atan2(s, q.w());
  return v * (angle / s);
}

Eigen::Quaterniond quaternion_from_rotation_vector(const Eigen::Vector3d& phi) {
  const double angle = phi.norm();
  if (angle < 1e-12) {
    Eigen::Quaterniond q(1.0, 0.5 * phi.x(), 0.5 * phi.y(), 0.5 * phi.z());
    return q.normalized();
  }
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, phi / angle));
}

BeamBondLoads evaluate_beam_bond(const SphereState& si, const SphereState& sj,
                                 const BeamBondRest& rest, const BeamBondStiffness& k,
                                 const BeamBondDamping& c) {
  BeamBondLoads out;
  // Elastic relative rotation of j w.r.t. i, in i's body frame, then in the
  // lab frame. theta_lab is the same seen from i or j (it is the axis of
  // the relative rotation), which makes the bond symmetric.
  const Eigen::Quaterniond q_rel =
      si.orientation.conjugate() * sj.orientation * rest.rest_relative_rotation.conjugate();
  const Eigen::Vector3d theta_body = rotation_vector(q_rel);
  const Eigen::Vector3d theta = si.orientation * theta_body;  // [rad], lab frame

  // Expected bond vector: the rest vector carried by the mid-rotation
  // q_i * exp(theta_body / 2), so that neither end is privileged.
  const Eigen::Quaterniond q_mid = si.orientation * quaternion_from_rotation_vector(0.5 * theta_body);
  const Eigen::Vector3d expected = q_mid * rest.rest_vector_in_frame_i;  // [m]
  const double rest_length = rest.rest_vector_in_frame_i.norm();
  const Eigen::Vector3d axis = expected / rest_length;  // unit bond axis

  const Eigen::Vector3d bond = sj.position - si.position;  // [m]
  const Eigen::Vector3d mismatch = bond - expected;          // [m]
  const Eigen::Vector3d mismatch_axial = axis * axis.dot(mismatch);
  const Eigen::Vector3d mismatch_shear = mismatch - mismatch_axial;

  const Eigen::Vector3d theta_twist = axis * axis.dot(theta);
  const Eigen::Vector3d theta_bend = theta - theta_twist;

  // Rates: the mismatch rate seen in the frame rotating with the bond's
  // mid-rotation, and the relative angular velocity.
  const Eigen::Vector3d mean_omega = 0.5 * (si.angular_velocity + sj.angular_velocity);
  const Eigen::Vector3d mismatch_rate = sj.velocity - si.velocity - mean_omega.cross(expected);
  const Eigen::Vector3d rate_axial = axis * axis.dot(mismatch_rate);
  const Eigen::Vector3d rate_shear = mismatch_rate - rate_axial;
  const Eigen::Vector3d relative_omega = sj.angular_velocity - si.angular_velocity;
  const Eigen::Vector3d omega_twist = axis * axis.dot(relative_omega);
  const Eigen::Vector3d omega_bend = relative_omega - omega_twist;

  const Eigen::Vector3d force_on_j = -k.axial * mismatch_axial - k.shear * mismatch_shear -
                                     c.axial * rate_axial - c.shear * rate_shear;
  const Eigen::Vector3d moment = k.bending * theta_bend + k.twisting * theta_twist +
                                 c.bending * omega_bend + c.twisting * omega_twist;

  // Angular momentum balance: the couple of the transverse force is shared
  // by the two spheres (standard for bonded-particle models).
  const Eigen::Vector3d couple = -0.5 * bond.cross(force_on_j);
  out.force_on_j = force_on_j;
  out.torque_on_i = moment + couple;
  out.torque_on_j = -moment + couple;
  out.elastic_energy = 0.5 * k.axial * mismatch_axial.squaredNorm() +
                       0.5 * k.shear * mismatch_shear.squaredNorm() +
                       0.5 * k.bending * theta_bend.squaredNorm() +
                       0.5 * k.twisting * theta_twist.squaredNorm();
  out.axial_strain = (bond.norm() - rest_length) / rest_length;
  return out;
}

}  // namespace hsrod

#include "rod/rod_linearisation.h"

#include "rod/stability_limits.h"

#include <vector>

namespace hsrod {

Eigen::VectorXd rod_bond_loads(const RodLayout& layout, const BeamBondMaterial& bond,
                               const Eigen::VectorXd& dof) {
  const int n = static_cast<int>(layout.spheres.size());
  Eigen::VectorXd loads = Eigen::VectorXd::Zero(6 * n);
  std::vector<SphereState> state(n);
  for (int s = 0; s < n; ++s) {
    state[s].position = layout.spheres[s].position + dof.segment<3>(6 * s);
    state[s].orientation = quaternion_from_rotation_vector(dof.segment<3>(6 * s + 3));
  }
  for (const auto& b : layout.bonds) {
    const auto& xi = layout.spheres[b.first].position;
    const auto& xj = layout.spheres[b.second].position;
    const BeamBondRest rest = BeamBondRest::from_current(xi, Eigen::Quaterniond::Identity(), xj,
                                                         Eigen::Quaterniond::Identity());
    const auto k = BeamBondStiffness::from_material(bond, rest.rest_length());
    const auto out = evaluate_beam_bond(state[b.first], state[b.second], rest, k, BeamBondDamping{});
    loads.segment<3>(6 * b.first) -= out.force_on_j;
    loads.segment<3>(6 * b.second) += out.force_on_j;
    loads.segment<3>(6 * b.first + 3) += out.torque_on_i;
    loads.segment<3>(6 * b.second + 3) += out.torque_on_j;
  }
  return loads;
}

Eigen::MatrixXd linearised_bond_stiffness(const RodLayout& layout, const BeamBondMaterial& bond) {
  const int ndof = 6 * static_cast<int>(layout.spheres.size());
  double spacing = 1.0;
  if (!layout.bonds.empty())
    spacing = (layout.spheres[layout.bonds[0].second].position -
               layout.spheres[layout.bonds[0].first].position).norm();
  Eigen::MatrixXd stiffness(ndof, ndof);
  for (int c = 0; c < ndof; ++c) {
    // Step sizes: small against the rod's scales, large against round-off.
    const double h = (c % 6) >= 3 ? 1e-6 : 1e-6 * spacing;
    Eigen::VectorXd dof = Eigen::VectorXd::Zero(ndof);
    dof[c] = h;
    const Eigen::VectorXd plus = rod_bond_loads(layout, bond, dof);
    dof[c] = -h;
    const Eigen::VectorXd minus = rod_bond_loads(layout, bond, dof);
    stiffness.col(c) = -(plus - minus) / (2.0 * h);
  }
  return 0.5 * (stiffness + stiffness.transpose());
}

Eigen::VectorXd rod_mass_diagonal(const RodLayout& layout, const SphereMaterial& sphere) {
  const int n = static_cast<int>(layout.spheres.size());
  Eigen::VectorXd mass(6 * n);
  for (int s = 0; s < n; ++s) {
    mass.segment<3>(6 * s).setConstant(sphere.mass());
    mass.segment<3>(6 * s + 3).setConstant(sphere.moment_of_inertia());
  }
  return mass;
}

}  // namespace hsrod

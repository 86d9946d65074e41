#include "rod/rod_linearisation.h"

#include "rod/stability_limits.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <vector>

namespace hsrod {

BeamBondRest layout_rest_state(const RodLayout& layout, const std::pair<int, int>& bond) {
  return BeamBondRest::from_current(layout.spheres[bond.first].position, Eigen::Quaterniond::Identity(),
                                    layout.spheres[bond.second].position, Eigen::Quaterniond::Identity());
}

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
    const BeamBondRest rest = layout_rest_state(layout, b);
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

namespace hsrod {

Eigen::MatrixXd linearised_bond_damping(const RodLayout& layout, const BeamBondMaterial& bond,
                                        const SphereMaterial& sphere) {
  const int n = static_cast<int>(layout.spheres.size());
  const int ndof = 6 * n;
  Eigen::MatrixXd damping = Eigen::MatrixXd::Zero(ndof, ndof);
  const double reduced_mass = 0.5 * sphere.mass();
  const double reduced_inertia = 0.5 * sphere.moment_of_inertia();
  for (const auto& b : layout.bonds) {
    const auto& xi = layout.spheres[b.first].position;
    const auto& xj = layout.spheres[b.second].position;
    const BeamBondRest rest = layout_rest_state(layout, b);
    const auto k = BeamBondStiffness::from_material(bond, rest.rest_length());
    const auto c = BeamBondDamping::critical_fraction(bond.damping_ratio, k, reduced_mass, reduced_inertia);
    const int base[2] = {6 * b.first, 6 * b.second};
    // Loads are linear in the velocities: unit velocity columns.
    for (int col = 0; col < 12; ++col) {
      SphereState si, sj;
      si.position = xi;
      sj.position = xj;
      SphereState& s = col < 6 ? si : sj;
      if (col % 6 < 3) s.velocity[col % 6] = 1.0;
      else s.angular_velocity[col % 6 - 3] = 1.0;
      const auto out = evaluate_beam_bond(si, sj, rest, k, c);
      Eigen::Matrix<double, 12, 1> loads;
      loads << -out.force_on_j, out.torque_on_i, out.force_on_j, out.torque_on_j;
      for (int row = 0; row < 12; ++row) damping(base[row / 6] + row % 6, base[col / 6] + col % 6) -= loads[row];
    }
  }
  return damping;
}

double velocity_verlet_limit(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& damping,
                             const Eigen::VectorXd& mass_diagonal) {
  const int n = static_cast<int>(stiffness.rows());
  // Mass-normalised operators M^-1/2 K M^-1/2, M^-1/2 C M^-1/2.
  const Eigen::VectorXd s = mass_diagonal.cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd k = s.asDiagonal() * stiffness * s.asDiagonal();
  const Eigen::MatrixXd c = s.asDiagonal() * damping * s.asDiagonal();
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(n, n);
  // One step in dimensionless variables (x, V = dt v, A = dt^2 a), a = the
  // acceleration of the previous force evaluation:
  //   V' = V + A/2;  x+ = x + V';  A+ = -dt^2 k x+ - dt c V';  V+ = V' + A+/2.
  auto spectral_radius = [&](double dt) {
    Eigen::MatrixXd vprime(n, 3 * n), xplus(n, 3 * n);
    vprime << Eigen::MatrixXd::Zero(n, n), identity, 0.5 * identity;
    xplus << identity, identity, 0.5 * identity;
    const Eigen::MatrixXd aplus = -dt * dt * k * xplus - dt * c * vprime;
    const Eigen::MatrixXd vplus = vprime + 0.5 * aplus;
    Eigen::MatrixXd map(3 * n, 3 * n);
    map << xplus, vplus, aplus;
    Eigen::EigenSolver<Eigen::MatrixXd> eig(map, false);
    return eig.eigenvalues().cwiseAbs().maxCoeff();
  };
  // The undamped limit 2/omega_max bounds the damped one from above.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> undamped(0.5 * (k + k.transpose()), Eigen::EigenvaluesOnly);
  // Without damping that is the limit itself (each mode x'' = -omega^2 x
  // under velocity Verlet is stable for omega dt <= 2): no bisection, which
  // costs ~14 eigenvalue problems of the 3n x 3n map (most of a run's
  // start-up, tests/benchmarks/RESULTS.md).
  if (damping.isZero(0.0)) return 2.0 / std::sqrt(undamped.eigenvalues().maxCoeff());
  double hi = 2.0 / std::sqrt(undamped.eigenvalues().maxCoeff()) * 1.001;
  double lo = 0.0;
  for (int it = 0; it < 40 && hi - lo > 1e-4 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    // Rigid-body modes are defective eigenvalues 1: allow their O(sqrt(eps)) spread.
    if (spectral_radius(mid) <= 1.0 + 1e-6) lo = mid;
    else hi = mid;
  }
  return lo;
}

}  // namespace hsrod

#include "dynamics/overdamped_rod_step.h"

#include "rod/rod_linearisation.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>

namespace hsrod {

namespace {

Eigen::Matrix<double, 12, 1> bond_loads(const SphereState& si, const SphereState& sj, const RodBond& b) {
  const auto out = evaluate_beam_bond(si, sj, b.rest, b.stiffness, BeamBondDamping{});
  Eigen::Matrix<double, 12, 1> loads;
  loads << -out.force_on_j, out.torque_on_i, out.force_on_j, out.torque_on_j;
  return loads;
}

SphereState perturbed(const SphereState& s, int component, double h) {
  SphereState p = s;
  if (component < 3) {
    p.position[component] += h;
  } else {
    Eigen::Vector3d phi = Eigen::Vector3d::Zero();
    phi[component - 3] = h;
    p.orientation = (quaternion_from_rotation_vector(phi) * s.orientation).normalized();
  }
  return p;
}

}  // namespace

void beam_bond_jacobian(const SphereState& si, const SphereState& sj, const RodBond& bond,
                        Eigen::Matrix<double, 12, 1>& loads, Eigen::Matrix<double, 12, 12>& jacobian) {
  loads = bond_loads(si, sj, bond);
  const double length_step = 1e-7 * bond.rest.rest_length();  // [m]
  const double angle_step = 1e-7;                              // [rad]
  for (int c = 0; c < 12; ++c) {
    const int local = c % 6;
    const double h = local < 3 ? length_step : angle_step;
    const bool on_i = c < 6;
    const SphereState ip = on_i ? perturbed(si, local, h) : si;
    const SphereState im = on_i ? perturbed(si, local, -h) : si;
    const SphereState jp = on_i ? sj : perturbed(sj, local, h);
    const SphereState jm = on_i ? sj : perturbed(sj, local, -h);
    jacobian.col(c) = (bond_loads(ip, jp, bond) - bond_loads(im, jm, bond)) / (2.0 * h);
  }
}

OverdampedRod make_overdamped_rod(const RodLayout& layout, const BeamBondMaterial& material, double sphere_diameter) {
  OverdampedRod rod;
  const int n = static_cast<int>(layout.spheres.size());
  for (const auto& s : layout.spheres) rod.positions.push_back(s.position);
  rod.orientations.assign(n, Eigen::Quaterniond::Identity());
  rod.radii.assign(n, 0.5 * sphere_diameter);
  rod.external_forces.assign(n, Eigen::Vector3d::Zero());
  rod.external_torques.assign(n, Eigen::Vector3d::Zero());
  for (const auto& b : layout.bonds) {
    RodBond bond;
    bond.i = b.first;
    bond.j = b.second;
    bond.rest = layout_rest_state(layout, b);
    bond.stiffness = BeamBondStiffness::from_material(material, bond.rest.rest_length());
    rod.bonds.push_back(bond);
  }
  return rod;
}

OverdampedStepResult overdamped_rod_step(OverdampedRod& rod, const RodDrag& drag, double dt,
                                         const ChannelGeometry* geometry, const WallContactParameters* walls) {
  const int n = rod.size();
  const int ndof = 6 * n;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(ndof);
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(36 * n + 144 * rod.bonds.size() + 9 * n * (drag.coupled() ? n : 1));
  OverdampedStepResult result;

  // Hydrodynamic resistance / dt and driving.
  for (int i = 0; i < n; ++i) {
    rhs.segment<3>(6 * i) += drag.driving_force[i] + rod.external_forces[i];
    rhs.segment<3>(6 * i + 3) += drag.driving_torque[i] + rod.external_torques[i];
    for (int a = 0; a < 3; ++a) triplets.emplace_back(6 * i + 3 + a, 6 * i + 3 + a, drag.rotational_resistance[i] / dt);
    if (drag.coupled()) {
      for (int k = 0; k < n; ++k)
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) {
            const double value = drag.coupled_resistance(3 * i + a, 3 * k + b);
            if (value != 0.0) triplets.emplace_back(6 * i + a, 6 * k + b, value / dt);
          }
    } else {
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) triplets.emplace_back(6 * i + a, 6 * i + b, drag.resistance[i](a, b) / dt);
    }
  }

  // Bonds: loads at y_n and stiffness K = -d loads / dy.
  std::vector<SphereState> state(n);
  for (int i = 0; i < n; ++i) {
    state[i].position = rod.positions[i];
    state[i].orientation = rod.orientations[i];
  }
  Eigen::Matrix<double, 12, 1> loads;
  Eigen::Matrix<double, 12, 12> jacobian;
  for (const RodBond& b : rod.bonds) {
    beam_bond_jacobian(state[b.i], state[b.j], b, loads, jacobian);
    const int base[2] = {6 * b.i, 6 * b.j};
    for (int r = 0; r < 12; ++r) {
      rhs[base[r / 6] + r % 6] += loads[r];
      for (int c = 0; c < 12; ++c)
        if (jacobian(r, c) != 0.0) triplets.emplace_back(base[r / 6] + r % 6, base[c / 6] + c % 6, -jacobian(r, c));
    }
  }

  // Wall contacts.
  if (geometry && walls) {
    for (int i = 0; i < n; ++i) {
      const WallContact c = wall_contact(*geometry, *walls, rod.positions[i], rod.radii[i]);
      if (!c.touching) continue;
      result.wall_contact = true;
      result.wall_force += c.force.norm();
      rhs.segment<3>(6 * i) += c.force;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) triplets.emplace_back(6 * i + a, 6 * i + b, c.stiffness(a, b));
    }
  }

  // Non-bonded spheres of the rod touching each other (a folding rod).
  if (walls && walls->self_contact && n > 2) {
    std::vector<std::vector<int>> bonded(n);
    for (const RodBond& b : rod.bonds) {
      bonded[b.i].push_back(b.j);
      bonded[b.j].push_back(b.i);
    }
    double largest_radius = 0.0;
    for (double r : rod.radii) largest_radius = std::max(largest_radius, r);
    const double reach = 2.0 * largest_radius;
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        const Eigen::Vector3d offset = rod.positions[i] - rod.positions[j];
        if (std::fabs(offset.x()) > reach || std::fabs(offset.y()) > reach) continue;
        if (std::find(bonded[i].begin(), bonded[i].end(), j) != bonded[i].end()) continue;
        const WallContact c = sphere_contact(*walls, rod.positions[i], rod.radii[i], rod.positions[j], rod.radii[j]);
        if (!c.touching) continue;
        result.self_contact = true;
        rhs.segment<3>(6 * i) += c.force;
        rhs.segment<3>(6 * j) -= c.force;
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) {
            triplets.emplace_back(6 * i + a, 6 * i + b, c.stiffness(a, b));
            triplets.emplace_back(6 * j + a, 6 * j + b, c.stiffness(a, b));
            triplets.emplace_back(6 * i + a, 6 * j + b, -c.stiffness(a, b));
            triplets.emplace_back(6 * j + a, 6 * i + b, -c.stiffness(a, b));
          }
      }
    }
  }

  Eigen::SparseMatrix<double> matrix(ndof, ndof);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::VectorXd dy;
  if (drag.coupled() || n <= 16) {
    dy = Eigen::MatrixXd(matrix).partialPivLu().solve(rhs);
  } else {
    // Spheres are numbered along the rod, so the matrix is banded (bonds
    // couple neighbouring sections only, unless the drag is non-local):
    // the natural ordering keeps the LU fill inside the band, O(n).
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::NaturalOrdering<int>> lu;
    lu.compute(matrix);
    dy = lu.solve(rhs);
  }

  result.velocities.resize(n);
  result.angular_velocities.resize(n);
  Eigen::VectorXd translational(3 * n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d dx = dy.segment<3>(6 * i);
    const Eigen::Vector3d dphi = dy.segment<3>(6 * i + 3);
    rod.positions[i] += dx;
    rod.orientations[i] = (quaternion_from_rotation_vector(dphi) * rod.orientations[i]).normalized();
    result.velocities[i] = dx / dt;
    result.angular_velocities[i] = dphi / dt;
    translational.segment<3>(3 * i) = result.velocities[i];
    result.largest_displacement = std::max(result.largest_displacement, dx.norm());
  }
  const Eigen::VectorXd f = drag.forces(translational);
  result.hydrodynamic_forces.resize(n);
  for (int i = 0; i < n; ++i) result.hydrodynamic_forces[i] = f.segment<3>(3 * i);
  return result;
}

}  // namespace hsrod

#include "dynamics/overdamped_rod_step.h"

#include "rod/rod_linearisation.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>

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

std::vector<std::pair<int, int>> nearby_sphere_pairs(const std::vector<Eigen::Vector3d>& positions, double reach) {
  std::vector<std::pair<int, int>> pairs;
  const int n = static_cast<int>(positions.size());
  if (n < 2 || !(reach > 0.0)) return pairs;
  // Cells of side `reach` in the plane: a pair within reach in x and y lies
  // in the same or a neighbouring cell. The gap holds only a few spheres
  // across z, so cells stay nearly empty and the search is O(n log n).
  double x_min = std::numeric_limits<double>::infinity(), y_min = x_min;
  for (const auto& p : positions) {
    if (!p.allFinite()) continue;
    x_min = std::min(x_min, p.x());
    y_min = std::min(y_min, p.y());
  }
  struct Cell {
    std::int64_t cx, cy;
    int sphere;
  };
  const auto cell_order = [](const Cell& a, const Cell& b) {
    return std::tie(a.cx, a.cy, a.sphere) < std::tie(b.cx, b.cy, b.sphere);
  };
  std::vector<Cell> cells;
  cells.reserve(n);
  for (int i = 0; i < n; ++i) {
    // A non-finite sphere has already spoilt the step; it has no neighbours.
    if (!positions[i].allFinite()) continue;
    cells.push_back({static_cast<std::int64_t>(std::floor((positions[i].x() - x_min) / reach)),
                     static_cast<std::int64_t>(std::floor((positions[i].y() - y_min) / reach)), i});
  }
  std::sort(cells.begin(), cells.end(), cell_order);
  for (const Cell& c : cells) {
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const Cell first{c.cx + dx, c.cy + dy, -1};
        for (auto it = std::lower_bound(cells.begin(), cells.end(), first, cell_order);
             it != cells.end() && it->cx == first.cx && it->cy == first.cy; ++it) {
          if (it->sphere <= c.sphere) continue;
          const Eigen::Vector3d offset = positions[c.sphere] - positions[it->sphere];
          if (std::fabs(offset.x()) > reach || std::fabs(offset.y()) > reach) continue;
          pairs.emplace_back(c.sphere, it->sphere);
        }
      }
  }
  // The order the contacts are summed in is then independent of the cells.
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

struct OverdampedRodSolver::Workspace {
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<SphereState> state;
  Eigen::VectorXd rhs;  // loads [N, N m]
  Eigen::SparseMatrix<double> matrix;
  // Spheres are numbered along the rod, so without non-local drag the matrix
  // is banded (bonds couple neighbouring sections only; a self-contact adds
  // a block off the band): the natural ordering keeps the LU fill inside
  // the band, O(n).
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::NaturalOrdering<int>> lu;
  std::vector<int> analysed_outer, analysed_inner;  // pattern `lu` was analysed for
  std::vector<Vector6d> previous_velocities;
  std::vector<std::pair<int, Matrix6d>> frictions;  // this step's friction resistance per rubbing sphere  // (v, omega) of the last step, where wall friction is linearised
  int analyses = 0;

  // Factorises `matrix`, analysing its pattern only when it changed.
  void factorize() {
    const int outer_size = static_cast<int>(matrix.outerSize()) + 1;
    const int nonzeros = static_cast<int>(matrix.nonZeros());
    const bool same_pattern =
        analyses > 0 && static_cast<int>(analysed_outer.size()) == outer_size &&
        static_cast<int>(analysed_inner.size()) == nonzeros &&
        std::equal(analysed_outer.begin(), analysed_outer.end(), matrix.outerIndexPtr()) &&
        std::equal(analysed_inner.begin(), analysed_inner.end(), matrix.innerIndexPtr());
    if (!same_pattern) {
      lu.analyzePattern(matrix);
      analysed_outer.assign(matrix.outerIndexPtr(), matrix.outerIndexPtr() + outer_size);
      analysed_inner.assign(matrix.innerIndexPtr(), matrix.innerIndexPtr() + nonzeros);
      ++analyses;
    }
    lu.factorize(matrix);
  }
};

OverdampedRodSolver::OverdampedRodSolver() : workspace_(std::make_unique<Workspace>()) {}
OverdampedRodSolver::~OverdampedRodSolver() = default;
OverdampedRodSolver::OverdampedRodSolver(OverdampedRodSolver&&) noexcept = default;
OverdampedRodSolver& OverdampedRodSolver::operator=(OverdampedRodSolver&&) noexcept = default;

int OverdampedRodSolver::pattern_analyses() const { return workspace_->analyses; }

OverdampedStepResult overdamped_rod_step(OverdampedRod& rod, const RodDrag& drag, double dt,
                                         const ChannelGeometry* geometry, const WallContactParameters* walls) {
  OverdampedRodSolver solver;
  return solver.step(rod, drag, dt, geometry, walls);
}

OverdampedStepResult OverdampedRodSolver::step(OverdampedRod& rod, const RodDrag& drag, double dt,
                                               const ChannelGeometry* geometry, const WallContactParameters* walls) {
  Workspace& w = *workspace_;
  const int n = rod.size();
  const int ndof = 6 * n;
  Eigen::VectorXd& rhs = w.rhs;
  rhs.setZero(ndof);
  std::vector<Eigen::Triplet<double>>& triplets = w.triplets;
  triplets.clear();
  triplets.reserve(36 * n + 144 * rod.bonds.size() + 9 * n * (drag.coupled() ? n : 1));
  OverdampedStepResult result;
  if (static_cast<int>(w.previous_velocities.size()) != n) w.previous_velocities.assign(n, Vector6d::Zero());
  w.frictions.clear();

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

  // Bonds: loads at y_n and stiffness K = -d loads / dy. Every entry of a
  // bond's block enters the pattern, also one that happens to be zero at
  // this configuration, so that the pattern (and its LU analysis) stays put.
  std::vector<SphereState>& state = w.state;
  state.resize(n);
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
      for (int c = 0; c < 12; ++c) triplets.emplace_back(base[r / 6] + r % 6, base[c / 6] + c % 6, -jacobian(r, c));
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
      // Wall friction: secant resistance about the previous velocities,
      // c G^T G / dt on the sphere's 6x6 block (dynamics/wall_contact.h).
      if (walls->friction_coefficient > 0.0) {
        Vector6d u0 = w.previous_velocities[i];
        if (static_cast<int>(rod.velocities.size()) == n) {
          u0.head<3>() = rod.velocities[i];
          u0.tail<3>() = static_cast<int>(rod.angular_velocities.size()) == n ? rod.angular_velocities[i]
                                                                               : Eigen::Vector3d::Zero();
        }
        Matrix6d friction = Matrix6d::Zero();
        for (int k = 0; k < c.points; ++k)
          friction += wall_friction_resistance(c.point[k], rod.radii[i], walls->friction_coefficient,
                                               walls->slip_velocity, u0);
        w.frictions.emplace_back(i, friction);
        for (int a = 0; a < 6; ++a)
          for (int b = 0; b < 6; ++b) triplets.emplace_back(6 * i + a, 6 * i + b, friction(a, b) / dt);
      }
    }
  }

  // Non-bonded spheres of the rod touching each other (a folding rod).
  if (walls && walls->self_contact && n > 2) {
    double largest_radius = 0.0;
    for (double r : rod.radii) largest_radius = std::max(largest_radius, r);
    const auto candidates = nearby_sphere_pairs(rod.positions, 2.0 * largest_radius);
    if (!candidates.empty()) {
      std::vector<std::vector<int>> bonded(n);
      for (const RodBond& b : rod.bonds) {
        bonded[b.i].push_back(b.j);
        bonded[b.j].push_back(b.i);
      }
      for (const auto& pair : candidates) {
        const int i = pair.first, j = pair.second;
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

  Eigen::SparseMatrix<double>& matrix = w.matrix;
  matrix.resize(ndof, ndof);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::VectorXd dy;
  if (drag.coupled() || n <= 16) {
    dy = Eigen::MatrixXd(matrix).partialPivLu().solve(rhs);
  } else {
    w.factorize();
    dy = w.lu.solve(rhs);
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
    w.previous_velocities[i] << result.velocities[i], result.angular_velocities[i];
  }
  for (const auto& rubbing : w.frictions)
    result.friction_force += (rubbing.second * w.previous_velocities[rubbing.first]).head<3>().norm();
  const Eigen::VectorXd f = drag.forces(translational);
  result.hydrodynamic_forces.resize(n);
  for (int i = 0; i < n; ++i) result.hydrodynamic_forces[i] = f.segment<3>(3 * i);
  return result;
}

}  // namespace hsrod

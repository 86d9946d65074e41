#include "dynamics/finite_rotation_update.h"

#include <Eigen/SparseCore>

namespace hsrod {

void FiniteRotationUpdate::analyse(const OverdampedRod& rod) {
  const int n = rod.size();
  bool same = n == spheres_ && rod.bonds.size() == bonds_.size();
  for (std::size_t k = 0; same && k < rod.bonds.size(); ++k)
    same = rod.bonds[k].i == bonds_[k].first && rod.bonds[k].j == bonds_[k].second;
  if (same) return;
  spheres_ = n;
  bonds_.clear();
  for (const RodBond& b : rod.bonds) bonds_.emplace_back(b.i, b.j);
  incidence_rhs_.setZero(n, 3);
  correction_.setZero(n, 3);
  // A chain: each link (k, k+1) bonded exactly once.
  std::vector<int> links(n > 0 ? n - 1 : 0, 0);
  chain_ = static_cast<int>(bonds_.size()) == n - 1;
  for (const auto& [i, j] : bonds_) {
    if (std::abs(i - j) != 1) {
      chain_ = false;
      break;
    }
    ++links[std::min(i, j)];
  }
  for (int c : links) chain_ = chain_ && c == 1;
  // Connected components (union-find), for the pins and the means.
  std::vector<int> parent(n);
  for (int i = 0; i < n; ++i) parent[i] = i;
  const auto root = [&parent](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& [i, j] : bonds_) parent[root(i)] = root(j);
  component_.assign(n, -1);
  component_size_.clear();
  std::vector<int> label(n, -1);
  for (int i = 0; i < n; ++i) {
    const int r = root(i);
    if (label[r] < 0) {
      label[r] = static_cast<int>(component_size_.size());
      component_size_.push_back(0);
    }
    component_[i] = label[r];
    ++component_size_[label[r]];
  }
  if (chain_ || n == 0) return;
  // Graph Laplacian plus 1 on the diagonal of each component's first sphere:
  // with a right-hand side summing to zero over each component this pins
  // that sphere's z to 0 (the means are removed afterwards).
  std::vector<Eigen::Triplet<double>> t;
  std::vector<bool> pinned(component_size_.size(), false);
  for (int i = 0; i < n; ++i)
    if (!pinned[component_[i]]) {
      pinned[component_[i]] = true;
      t.emplace_back(i, i, 1.0);
    }
  for (const auto& [i, j] : bonds_) {
    t.emplace_back(i, i, 1.0);
    t.emplace_back(j, j, 1.0);
    t.emplace_back(i, j, -1.0);
    t.emplace_back(j, i, -1.0);
  }
  Eigen::SparseMatrix<double> laplacian(n, n);
  laplacian.setFromTriplets(t.begin(), t.end());
  laplacian_.compute(laplacian);
}

void FiniteRotationUpdate::apply(OverdampedRod& rod, const Eigen::VectorXd& dy) {
  analyse(rod);
  const int n = rod.size();
  // delta_b of each bond (j minus i), gathered as B^T delta (chain: kept per link).
  incidence_rhs_.setZero();
  for (const RodBond& b : rod.bonds) {
    const Eigen::Vector3d r = rod.positions[b.j] - rod.positions[b.i];  // [m]
    const Eigen::Vector3d du = dy.segment<3>(6 * b.j) - dy.segment<3>(6 * b.i);  // [m]
    // The bond's rotation, from its own end displacements (spheres that
    // roll on a wall turn without turning the bond).
    const Eigen::Vector3d phi = r.cross(du) / r.squaredNorm();  // [rad]
    const Eigen::Vector3d delta = quaternion_from_rotation_vector(phi) * r - r - phi.cross(r);  // [m]
    if (chain_) {
      incidence_rhs_.row(std::min(b.i, b.j)) = (b.j > b.i ? delta : Eigen::Vector3d(-delta)).transpose();
    } else {
      incidence_rhs_.row(b.j) += delta.transpose();
      incidence_rhs_.row(b.i) -= delta.transpose();
    }
  }
  if (chain_) {
    // z_{k+1} = z_k + delta_(k,k+1): the bond vectors met exactly.
    Eigen::RowVector3d z = Eigen::RowVector3d::Zero();
    for (int k = 0; k < n; ++k) {
      correction_.row(k) = z;
      z += incidence_rhs_.row(k);
    }
  } else if (n > 0) {
    correction_ = laplacian_.solve(incidence_rhs_);
  }
  // Zero mean per component: its centroid moves by the mean dx.
  std::vector<Eigen::RowVector3d>& mean = component_mean_;  // kept: no allocation per step
  mean.assign(component_size_.size(), Eigen::RowVector3d::Zero());
  for (int i = 0; i < n; ++i) mean[component_[i]] += correction_.row(i) / component_size_[component_[i]];
  for (int i = 0; i < n; ++i)
    rod.positions[i] += dy.segment<3>(6 * i) + (correction_.row(i) - mean[component_[i]]).transpose();
}

}  // namespace hsrod

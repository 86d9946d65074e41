#include "dynamics/rod_cluster.h"

#include <algorithm>
#include <numeric>

namespace hsrod {

namespace {
int root_of(std::vector<int>& parent, int a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}
}  // namespace

std::vector<std::vector<int>> rod_clusters(const std::vector<std::vector<Eigen::Vector3d>>& rods, double reach) {
  const int m = static_cast<int>(rods.size());
  std::vector<int> parent(m);
  std::iota(parent.begin(), parent.end(), 0);
  if (m > 1 && reach > 0.0) {
    std::vector<Eigen::Vector3d> all;
    std::vector<int> rod_of;
    for (int r = 0; r < m; ++r)
      for (const auto& x : rods[r]) {
        all.push_back(x);
        rod_of.push_back(r);
      }
    for (const auto& [i, j] : nearby_sphere_pairs(all, reach)) {
      if (rod_of[i] == rod_of[j] || (all[i] - all[j]).norm() > reach) continue;
      const int a = root_of(parent, rod_of[i]), b = root_of(parent, rod_of[j]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  std::vector<std::vector<int>> clusters;
  std::vector<int> cluster_of_root(m, -1);
  for (int r = 0; r < m; ++r) {
    const int root = root_of(parent, r);
    if (cluster_of_root[root] < 0) {
      cluster_of_root[root] = static_cast<int>(clusters.size());
      clusters.emplace_back();
    }
    clusters[cluster_of_root[root]].push_back(r);
  }
  return clusters;
}

std::vector<std::pair<int, int>> touching_groups(const std::vector<const std::vector<Eigen::Vector3d>*>& positions,
                                                 const std::vector<const std::vector<double>*>& radii) {
  std::vector<Eigen::Vector3d> all;
  std::vector<double> radius;
  std::vector<int> group_of;
  double largest_radius = 0.0;
  for (std::size_t g = 0; g < positions.size(); ++g) {
    all.insert(all.end(), positions[g]->begin(), positions[g]->end());
    radius.insert(radius.end(), radii[g]->begin(), radii[g]->end());
    group_of.insert(group_of.end(), positions[g]->size(), static_cast<int>(g));
  }
  for (double r : radius) largest_radius = std::max(largest_radius, r);
  std::vector<std::pair<int, int>> touching;
  if (positions.size() < 2) return touching;
  for (const auto& [i, j] : nearby_sphere_pairs(all, 2.0 * largest_radius)) {
    if (group_of[i] == group_of[j] || (all[i] - all[j]).norm() >= radius[i] + radius[j]) continue;
    touching.emplace_back(std::min(group_of[i], group_of[j]), std::max(group_of[i], group_of[j]));
  }
  std::sort(touching.begin(), touching.end());
  touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
  return touching;
}

OverdampedRod merge_rods(const std::vector<OverdampedRod>& rods) {
  OverdampedRod all;
  bool velocities = true;
  for (const OverdampedRod& rod : rods) velocities = velocities && rod.velocities.size() == rod.positions.size();
  for (std::size_t k = 0; k < rods.size(); ++k) {
    const OverdampedRod& rod = rods[k];
    const int offset = all.size();
    auto append = [](auto& to, const auto& from) { to.insert(to.end(), from.begin(), from.end()); };
    append(all.positions, rod.positions);
    append(all.orientations, rod.orientations);
    append(all.radii, rod.radii);
    append(all.external_forces, rod.external_forces);
    append(all.external_torques, rod.external_torques);
    if (velocities) {
      append(all.velocities, rod.velocities);
      if (rod.angular_velocities.size() == rod.positions.size()) append(all.angular_velocities, rod.angular_velocities);
      else all.angular_velocities.insert(all.angular_velocities.end(), rod.positions.size(), Eigen::Vector3d::Zero());
    }
    for (RodBond b : rod.bonds) {
      b.i += offset;
      b.j += offset;
      all.bonds.push_back(b);
    }
    all.rod_of_sphere.insert(all.rod_of_sphere.end(), rod.positions.size(), static_cast<int>(k));
  }
  return all;
}

}  // namespace hsrod

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
  RodSearchBuffers buffers;
  return rod_clusters(rods, reach, buffers);
}

std::vector<std::vector<int>> rod_clusters(const std::vector<std::vector<Eigen::Vector3d>>& rods, double reach,
                                           RodSearchBuffers& buffers) {
  const int m = static_cast<int>(rods.size());
  std::vector<int> parent(m);
  std::iota(parent.begin(), parent.end(), 0);
  if (m > 1 && reach > 0.0) {
    std::vector<Eigen::Vector3d>& all = buffers.start;
    std::vector<int>& rod_of = buffers.group_of;
    all.clear();
    rod_of.clear();
    for (int r = 0; r < m; ++r)
      for (const auto& x : rods[r]) {
        all.push_back(x);
        rod_of.push_back(r);
      }
    // Pairs in cell order: the groups (connected components) do not depend
    // on the order in which their links are found.
    find_nearby_pairs(all, reach, buffers.cells, buffers.pairs, false);
    for (const auto& [i, j] : buffers.pairs) {
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

std::vector<std::pair<int, int>> rods_within_reach(const std::vector<std::vector<Eigen::Vector3d>>& rods, double reach,
                                                   RodSearchBuffers& buffers) {
  std::vector<std::pair<int, int>> near;
  if (rods.size() < 2 || !(reach > 0.0)) return near;
  std::vector<Eigen::Vector3d>& all = buffers.start;
  std::vector<int>& rod_of = buffers.group_of;
  all.clear();
  rod_of.clear();
  for (std::size_t r = 0; r < rods.size(); ++r)
    for (const auto& x : rods[r]) {
      all.push_back(x);
      rod_of.push_back(static_cast<int>(r));
    }
  find_nearby_pairs(all, reach, buffers.cells, buffers.pairs, false);
  for (const auto& [i, j] : buffers.pairs) {
    if (rod_of[i] == rod_of[j] || (all[i] - all[j]).norm() > reach) continue;
    near.emplace_back(std::min(rod_of[i], rod_of[j]), std::max(rod_of[i], rod_of[j]));
  }
  std::sort(near.begin(), near.end());
  near.erase(std::unique(near.begin(), near.end()), near.end());
  return near;
}

std::vector<std::pair<int, int>> groups_meeting_in_step(const std::vector<const std::vector<Eigen::Vector3d>*>& starts,
                                                        const std::vector<const std::vector<Eigen::Vector3d>*>& ends,
                                                        const std::vector<const std::vector<double>*>& radii) {
  RodSearchBuffers buffers;
  return groups_meeting_in_step(starts, ends, radii, buffers);
}

std::vector<std::pair<int, int>> groups_meeting_in_step(const std::vector<const std::vector<Eigen::Vector3d>*>& starts,
                                                        const std::vector<const std::vector<Eigen::Vector3d>*>& ends,
                                                        const std::vector<const std::vector<double>*>& radii,
                                                        RodSearchBuffers& buffers) {
  std::vector<std::pair<int, int>> meeting;
  if (starts.size() < 2) return meeting;
  std::vector<Eigen::Vector3d>&start = buffers.start, &moved = buffers.moved;
  std::vector<double>& radius = buffers.radius;
  std::vector<int>& group_of = buffers.group_of;
  start.clear();
  moved.clear();
  radius.clear();
  group_of.clear();
  double largest_radius = 0.0, largest_move = 0.0;
  for (std::size_t g = 0; g < starts.size(); ++g) {
    for (std::size_t k = 0; k < starts[g]->size(); ++k) {
      start.push_back((*starts[g])[k]);
      moved.push_back((*ends[g])[k] - (*starts[g])[k]);
      radius.push_back((*radii[g])[k]);
      group_of.push_back(static_cast<int>(g));
      largest_radius = std::max(largest_radius, radius.back());
      if (moved.back().allFinite()) largest_move = std::max(largest_move, moved.back().norm());
    }
  }
  // unsorted candidates: the meeting groups are sorted and made unique below
  find_nearby_pairs(start, 2.0 * largest_radius + 2.0 * largest_move, buffers.cells, buffers.pairs, false);
  for (const auto& [i, j] : buffers.pairs) {
    if (group_of[i] == group_of[j]) continue;
    // Closest approach of x_i - x_j = d0 + s dd, s in [0, 1].
    const Eigen::Vector3d d0 = start[i] - start[j], dd = moved[i] - moved[j];
    const double dd2 = dd.squaredNorm();
    const double s = dd2 > 0.0 ? std::clamp(-d0.dot(dd) / dd2, 0.0, 1.0) : 0.0;
    if ((d0 + s * dd).norm() >= radius[i] + radius[j]) continue;
    meeting.emplace_back(std::min(group_of[i], group_of[j]), std::max(group_of[i], group_of[j]));
  }
  std::sort(meeting.begin(), meeting.end());
  meeting.erase(std::unique(meeting.begin(), meeting.end()), meeting.end());
  return meeting;
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

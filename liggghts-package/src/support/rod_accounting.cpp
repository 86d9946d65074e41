#include "rod_accounting.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <cstdio>

namespace LAMMPS_NS {

std::string RodCensus::check(const std::map<int, std::vector<GatheredSphere>> &rods) {
  char msg[160];
  for (const auto &known : spheres_by_rod_) {
    const auto found = rods.find(known.first);
    if (found == rods.end()) {
      std::snprintf(msg, sizeof(msg), "rod %d (%d spheres) is gone", known.first, known.second);
      return msg;
    }
    const int now = static_cast<int>(found->second.size());
    if (now < known.second) {
      std::snprintf(msg, sizeof(msg), "rod %d has %d of its %d spheres", known.first, now, known.second);
      return msg;
    }
  }
  for (const auto &rod : rods) {
    int &count = spheres_by_rod_[rod.first];
    count = std::max(count, static_cast<int>(rod.second.size()));
  }
  return "";
}

int leaving_face(const std::vector<Eigen::Vector3d> &positions, const double *boxlo, const double *boxhi,
                 const int *periodic) {
  for (const auto &x : positions)
    for (int a = 0; a < 3; a++) {
      if (periodic[a]) continue;
      if (x[a] < boxlo[a]) return 2 * a;
      if (x[a] > boxhi[a]) return 2 * a + 1;
    }
  return -1;
}

double fraction_inside_box(const std::vector<Eigen::Vector3d> &before, const std::vector<Eigen::Vector3d> &after,
                           const double *boxlo, const double *boxhi, const int *periodic) {
  double fraction = 1.0;
  for (std::size_t k = 0; k < before.size() && k < after.size(); k++)
    for (int a = 0; a < 3; a++) {
      if (periodic[a]) continue;
      // A centre exactly on a face belongs to no sub-domain (LIGGGHTS
      // drops it as lost): stop a hair inside, 1e-9 of the box extent.
      const double margin = 1e-9 * (boxhi[a] - boxlo[a]);
      const double from = before[k][a], to = after[k][a];
      if (to > boxhi[a] - margin && to > from)
        fraction = std::min(fraction, (boxhi[a] - margin - from) / (to - from));
      if (to < boxlo[a] + margin && to < from)
        fraction = std::min(fraction, (from - boxlo[a] - margin) / (from - to));
    }
  return std::max(0.0, fraction);
}

const char *face_name(int face) {
  static const char *names[6] = {"-x", "+x", "-y", "+y", "-z", "+z"};
  return face >= 0 && face < 6 ? names[face] : "none";
}

RodOverlap first_rod_overlap(const std::map<int, std::vector<GatheredSphere>> &rods) {
  // Bounding boxes first: rods are few, spheres per rod many.
  struct Box {
    int id;
    Eigen::Vector3d lo, hi;
    const std::vector<GatheredSphere> *spheres;
  };
  std::vector<Box> boxes;
  Eigen::Vector2d largest = Eigen::Vector2d::Zero();  // largest box extent in x, y [m]
  for (const auto &rod : rods) {
    Box b{rod.first, Eigen::Vector3d::Constant(1e300), Eigen::Vector3d::Constant(-1e300), &rod.second};
    for (const auto &s : rod.second) {
      b.lo = b.lo.cwiseMin(s.position - Eigen::Vector3d::Constant(s.radius));
      b.hi = b.hi.cwiseMax(s.position + Eigen::Vector3d::Constant(s.radius));
    }
    if (b.lo.allFinite() && b.hi.allFinite()) largest = largest.cwiseMax((b.hi - b.lo).head<2>());
    boxes.push_back(b);
  }
  // Boxes that overlap have lower corners less than the largest extent
  // apart in x and y: a cell list of that side in the plane gives every
  // such pair from a cell and its neighbours, O(rods) instead of all pairs.
  // A box with non-finite bounds is a candidate against every box.
  std::vector<std::pair<std::size_t, std::size_t>> candidates;
  std::map<std::pair<long, long>, std::vector<std::size_t>> cells;
  std::vector<std::size_t> unplaced;
  const Eigen::Vector2d side = largest.cwiseMax(Eigen::Vector2d::Constant(1e-300));
  const auto cell_of = [&](const Box &b) {
    return std::make_pair(static_cast<long>(std::floor(b.lo.x() / side.x())),
                          static_cast<long>(std::floor(b.lo.y() / side.y())));
  };
  for (std::size_t a = 0; a < boxes.size(); a++) {
    const Box &b = boxes[a];
    const bool placeable = b.lo.allFinite() && b.hi.allFinite() && std::fabs(b.lo.x() / side.x()) < 1e15 &&
                           std::fabs(b.lo.y() / side.y()) < 1e15;
    if (placeable) cells[cell_of(b)].push_back(a);
    else unplaced.push_back(a);
  }
  for (const auto &cell : cells)
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy) {
        const auto other = cells.find({cell.first.first + dx, cell.first.second + dy});
        if (other == cells.end()) continue;
        for (std::size_t a : cell.second)
          for (std::size_t b : other->second)
            if (a < b) candidates.emplace_back(a, b);
      }
  for (std::size_t a : unplaced)
    for (std::size_t b = 0; b < boxes.size(); b++)
      if (a != b) candidates.emplace_back(std::min(a, b), std::max(a, b));
  // In the order of an all-pairs search: the first overlapping pair of rods
  // (by rod id), and its closest spheres.
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  RodOverlap worst;
  double smallest = 1.0;
  for (const auto &[a, b] : candidates) {
    const Box &p = boxes[a], &q = boxes[b];
    if ((p.lo.array() > q.hi.array()).any() || (q.lo.array() > p.hi.array()).any()) continue;
    for (const auto &s : *p.spheres)
      for (const auto &t : *q.spheres) {
        const double ratio = (s.position - t.position).norm() / (s.radius + t.radius);
        if (ratio < smallest) {
          smallest = ratio;
          worst = RodOverlap{p.id, q.id, ratio};
        }
      }
    if (worst.rod_a >= 0) return worst;
  }
  return worst;
}

}  // namespace LAMMPS_NS

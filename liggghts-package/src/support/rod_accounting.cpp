#include "rod_accounting.h"

#include <algorithm>
#include <tuple>
#include <cmath>
#include <map>
#include <utility>
#include <cstdio>

namespace LAMMPS_NS {

std::string RodCensus::check(const std::map<int, std::vector<GatheredSphere>> &rods) {
  char msg[160];
  // Both maps are sorted by rod ID: walked side by side, O(rods).
  auto found = rods.begin();
  for (const auto &known : spheres_by_rod_) {
    while (found != rods.end() && found->first < known.first) ++found;
    if (found == rods.end() || found->first != known.first) {
      std::snprintf(msg, sizeof(msg), "rod %d (%d spheres) is gone", known.first, known.second);
      return msg;
    }
    const int now = static_cast<int>(found->second.size());
    if (now < known.second) {
      std::snprintf(msg, sizeof(msg), "rod %d has %d of its %d spheres", known.first, now, known.second);
      return msg;
    }
  }
  auto known = spheres_by_rod_.begin();
  for (const auto &rod : rods) {
    while (known != spheres_by_rod_.end() && known->first < rod.first) ++known;
    if (known == spheres_by_rod_.end() || known->first != rod.first) known = spheres_by_rod_.emplace_hint(known, rod.first, 0);
    known->second = std::max(known->second, static_cast<int>(rod.second.size()));
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
  struct Placed {
    long cx, cy;
    std::size_t box;
  };
  std::vector<Placed> placed;
  std::vector<std::size_t> unplaced;
  const Eigen::Vector2d side = largest.cwiseMax(Eigen::Vector2d::Constant(1e-300));
  for (std::size_t a = 0; a < boxes.size(); a++) {
    const Box &b = boxes[a];
    const bool placeable = b.lo.allFinite() && b.hi.allFinite() && std::fabs(b.lo.x() / side.x()) < 1e15 &&
                           std::fabs(b.lo.y() / side.y()) < 1e15;
    if (placeable)
      placed.push_back({static_cast<long>(std::floor(b.lo.x() / side.x())),
                        static_cast<long>(std::floor(b.lo.y() / side.y())), a});
    else unplaced.push_back(a);
  }
  const auto cell_less = [](const Placed &p, const Placed &q) { return std::tie(p.cx, p.cy) < std::tie(q.cx, q.cy); };
  std::sort(placed.begin(), placed.end(), [](const Placed &p, const Placed &q) {
    return std::tie(p.cx, p.cy, p.box) < std::tie(q.cx, q.cy, q.box);
  });
  // The first overlapping pair of rods in the order of an all-pairs search
  // (by rod id, i.e. by box index): the smallest candidate (a, b) whose
  // rods overlap, then its closest spheres.
  const auto spheres_overlap = [](const Box &p, const Box &q) {
    if ((p.lo.array() > q.hi.array()).any() || (q.lo.array() > p.hi.array()).any()) return false;
    for (const auto &s : *p.spheres)
      for (const auto &t : *q.spheres)
        if ((s.position - t.position).norm() / (s.radius + t.radius) < 1.0) return true;
    return false;
  };
  std::pair<std::size_t, std::size_t> first{boxes.size(), boxes.size()};
  const auto consider = [&](std::size_t a, std::size_t b) {
    const std::pair<std::size_t, std::size_t> candidate{std::min(a, b), std::max(a, b)};
    if (candidate < first && spheres_overlap(boxes[candidate.first], boxes[candidate.second])) first = candidate;
  };
  for (const Placed &cell : placed)
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy) {
        const Placed key{cell.cx + dx, cell.cy + dy, 0};
        for (auto other = std::lower_bound(placed.begin(), placed.end(), key, cell_less);
             other != placed.end() && other->cx == key.cx && other->cy == key.cy; ++other)
          if (cell.box < other->box) consider(cell.box, other->box);
      }
  for (std::size_t a : unplaced)
    for (std::size_t b = 0; b < boxes.size(); b++)
      if (a != b) consider(a, b);
  RodOverlap worst;
  if (first.first == boxes.size()) return worst;
  const Box &p = boxes[first.first], &q = boxes[first.second];
  double smallest = 1.0;
  for (const auto &s : *p.spheres)
    for (const auto &t : *q.spheres) {
      const double ratio = (s.position - t.position).norm() / (s.radius + t.radius);
      if (ratio < smallest) {
        smallest = ratio;
        worst = RodOverlap{p.id, q.id, ratio};
      }
    }
  return worst;
}

}  // namespace LAMMPS_NS

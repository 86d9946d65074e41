// The search for sphere pairs that may touch (a folding rod, rods of a
// cluster): a cell list in the plane, kept sorted between steps.
#include "dynamics/overdamped_rod_step_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace hsrod {

namespace {

bool cell_order(const PairSearchCell& a, const PairSearchCell& b) {
  return std::tie(a.cx, a.cy, a.sphere) < std::tie(b.cx, b.cy, b.sphere);
}

// Sorts cells that were sorted at the previous step and have moved a
// little since (few entries out of place): insertion sort, O(n) then; falls
// back to std::sort when the order has changed much.
void resort_cells(std::vector<PairSearchCell>& cells) {
  long moves = 0;
  const long budget = 8L * static_cast<long>(cells.size()) + 64;
  for (std::size_t k = 1; k < cells.size(); ++k) {
    const PairSearchCell c = cells[k];
    std::size_t m = k;
    for (; m > 0 && cell_order(c, cells[m - 1]); --m) cells[m] = cells[m - 1];
    cells[m] = c;
    moves += static_cast<long>(k - m);
    if (moves > budget) {
      std::sort(cells.begin(), cells.end(), cell_order);
      return;
    }
  }
}

// Cells in cell_order, from spheres listed in ascending order in cells of
// a grid of nx x ny (cx in [0, nx), cy in [0, ny)): a counting sort by
// cell, O(n + nx ny), stable, so the spheres of a cell stay ascending (the
// order std::sort gives). A grid much larger than the spheres (spheres far
// apart, a tiny reach) is sorted by comparison instead.
void sort_cells(PairSearchCells& search, double nx, double ny) {
  std::vector<PairSearchCell>& cells = search.cells;
  const double grid = nx * ny;
  if (!(grid <= 4.0 * static_cast<double>(cells.size()) + 64.0)) {
    std::sort(cells.begin(), cells.end(), cell_order);
    return;
  }
  const std::int64_t rows = static_cast<std::int64_t>(ny);
  std::vector<int>& start = search.cell_start;
  start.assign(static_cast<std::size_t>(grid) + 1, 0);
  for (const PairSearchCell& c : cells) ++start[c.cx * rows + c.cy + 1];
  for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  std::vector<PairSearchCell>& sorted = search.sorting;
  sorted.resize(cells.size());
  for (const PairSearchCell& c : cells) sorted[start[c.cx * rows + c.cy]++] = c;
  cells.swap(sorted);
}

}  // namespace

void find_nearby_pairs(const std::vector<Eigen::Vector3d>& positions, double reach, PairSearchCells& search,
                       std::vector<std::pair<int, int>>& pairs, bool sort_pairs) {
  std::vector<PairSearchCell>& cells = search.cells;
  pairs.clear();
  const int n = static_cast<int>(positions.size());
  if (n < 2 || !(reach > 0.0)) {
    cells.clear();
    return;
  }
  if (n <= 32) {
    // A short rod: every pair, the same test as below (sorting cells costs
    // more than the n (n - 1) / 2 comparisons here).
    cells.clear();
    for (int i = 0; i < n; ++i) {
      if (!positions[i].allFinite()) continue;  // it has already spoilt the step; no neighbours
      for (int j = i + 1; j < n; ++j) {
        if (!positions[j].allFinite()) continue;
        const Eigen::Vector3d offset = positions[i] - positions[j];
        if (std::fabs(offset.x()) > reach || std::fabs(offset.y()) > reach) continue;
        pairs.emplace_back(i, j);
      }
    }
    return;  // in lexicographic order already
  }
  // Cells of side `reach` in the plane: a pair within reach in x and y lies
  // in the same or a neighbouring cell. The gap holds only a few spheres
  // across z, so cells stay nearly empty and the search is O(n) (cells
  // bucketed by a counting sort, or re-sorted from the last step's order).
  double x_min = std::numeric_limits<double>::infinity(), y_min = x_min;
  double x_max = -x_min, y_max = -x_min;
  bool all_finite = true;
  for (const auto& p : positions) {
    if (!p.allFinite()) {
      all_finite = false;
      continue;
    }
    x_min = std::min(x_min, p.x());
    y_min = std::min(y_min, p.y());
    x_max = std::max(x_max, p.x());
    y_max = std::max(y_max, p.y());
  }
  const auto cell_of = [&](int i) {
    return PairSearchCell{static_cast<std::int64_t>(std::floor((positions[i].x() - x_min) / reach)),
                          static_cast<std::int64_t>(std::floor((positions[i].y() - y_min) / reach)), i};
  };
  if (all_finite && static_cast<int>(cells.size()) == n) {
    for (PairSearchCell& c : cells) c = cell_of(c.sphere);
    resort_cells(cells);
  } else {
    cells.clear();
    // A non-finite sphere has already spoilt the step; it has no neighbours.
    for (int i = 0; i < n; ++i)
      if (positions[i].allFinite()) cells.push_back(cell_of(i));
    sort_cells(search, std::floor((x_max - x_min) / reach) + 1.0, std::floor((y_max - y_min) / reach) + 1.0);
  }
  // Cells (cx + dx, cy - 1 .. cy + 1) are contiguous in the sorted list,
  // and where that run starts only moves forward as c goes through the
  // list in order: one cursor per dx, advanced instead of searched for
  // (O(n) in all; the pairs found and their order are those of a search).
  std::size_t start[3] = {0, 0, 0};
  for (const PairSearchCell& c : cells) {
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      const PairSearchCell first{c.cx + dx, c.cy - 1, -1};
      std::size_t& k = start[dx + 1];
      while (k < cells.size() && cell_order(cells[k], first)) ++k;
      for (std::size_t m = k; m < cells.size() && cells[m].cx == first.cx && cells[m].cy <= c.cy + 1; ++m) {
        const PairSearchCell& other = cells[m];
        if (other.sphere <= c.sphere) continue;
        const Eigen::Vector3d offset = positions[c.sphere] - positions[other.sphere];
        if (std::fabs(offset.x()) > reach || std::fabs(offset.y()) > reach) continue;
        pairs.emplace_back(c.sphere, other.sphere);
      }
    }
  }
  if (sort_pairs) std::sort(pairs.begin(), pairs.end());
}

std::vector<std::pair<int, int>> nearby_sphere_pairs(const std::vector<Eigen::Vector3d>& positions, double reach,
                                                     bool sorted) {
  PairSearchCells cells;
  std::vector<std::pair<int, int>> pairs;
  find_nearby_pairs(positions, reach, cells, pairs, sorted);
  return pairs;
}

}  // namespace hsrod

// Where level 4 places a rod's window: the lattice (fine zone, graded ring,
// cut at the side walls), when the rod has left it, and the reuse of a
// wall-free window's factorisation by translation.
#include "hydro/twoway_window_model.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hsrod {

namespace {

// Faces beyond `start` [m] along one direction (sign +-1), cells growing by
// `ratio` from h, up to `distance` [m] (the last face exactly there; a last
// cell smaller than half its neighbour is merged into it). Offsets from
// start, increasing in magnitude.
std::vector<double> graded_offsets(double distance, double h, double ratio) {
  std::vector<double> offsets;
  double size = h, at = 0.0;
  while (at < distance - 1e-9 * h) {
    size *= ratio;
    at += size;
    offsets.push_back(std::min(at, distance));
  }
  const std::size_t k = offsets.size();
  if (k >= 2 && offsets[k - 1] - offsets[k - 2] < 0.5 * (offsets[k - 2] - (k >= 3 ? offsets[k - 3] : 0.0))) {
    offsets.erase(offsets.end() - 2);
  }
  return offsets;
}

// Faces of one axis: `fine` uniform cells of size h from `first`, then the
// graded cells out to `below` [m] before and `above` [m] after them.
std::vector<double> graded_axis(double first, int fine, double h, double below, double above, double ratio) {
  std::vector<double> faces;
  const std::vector<double> lower = graded_offsets(below, h, ratio), upper = graded_offsets(above, h, ratio);
  for (auto it = lower.rbegin(); it != lower.rend(); ++it) faces.push_back(first - *it);
  for (int i = 0; i <= fine; ++i) faces.push_back(first + i * h);
  const double last = first + fine * h;
  for (double offset : upper) faces.push_back(last + offset);
  return faces;
}
}  // namespace

double TwoWayWindowModel::margin_for(double rod_extent) const {
  if (options_.margin > 0.0) return options_.margin;
  const double screening = parameters_.gap_height / std::sqrt(12.0);
  return std::max({kOuterScreenings * screening, kOuterExtents * rod_extent, 2.0 * parameters_.sphere_diameter});
}

double TwoWayWindowModel::fine_margin_for(double rod_extent) const {
  if (options_.fine_margin > 0.0) return std::min(options_.fine_margin, margin_for(rod_extent));
  const double screening = parameters_.gap_height / std::sqrt(12.0);
  return std::min(margin_for(rod_extent), std::max(2.0 * screening, 2.0 * parameters_.sphere_diameter));
}

// No wall or obstacle within a cell of the window rectangle (then the window
// system is that of free space, the same for every such placement).
bool TwoWayWindowModel::window_clear_of_cylinders(const WindowLattice& g, const ChannelGeometry& geometry) {
  const double x0 = g.x0 - g.h, x1 = g.x1() + g.h, y0 = g.y0 - g.h, y1 = g.y1() + g.h;
  for (const ZCylinder& c : geometry.cylinders()) {
    const double dx = std::max({x0 - c.center_x, 0.0, c.center_x - x1});
    const double dy = std::max({y0 - c.center_y, 0.0, c.center_y - y1});
    if (c.radius > 0.0 && std::hypot(dx, dy) <= c.radius) return false;
  }
  return true;
}

bool TwoWayWindowModel::near_side_walls(const WindowLattice& g, const ChannelGeometry& geometry) {
  return g.y0 - 2.0 * g.dy(0) <= geometry.y_lo() || g.y1() + 2.0 * g.dy(g.ny - 1) >= geometry.y_hi();
}

WindowLattice TwoWayWindowModel::window_lattice(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                                                const ChannelGeometry& geometry, const Eigen::Vector2i& travel) const {
  const double r = window_footprint_radius(), h = window_spacing_;
  const double extent = (hi - lo).maxCoeff() + 2.0 * r;
  const double reach = fine_margin_for(extent) + r, outer = margin_for(extent) + r;
  // Fine zone anchored at the planform corner, so that windows placed at
  // different times share their nodes (the footprints vary continuously).
  // Its size depends on the rod's extent only (not on where it sits on the
  // lattice), so that wall-free placements of a rod share one system.
  // Downstream (along `travel`, components -1, 0 or 1) the fine zone
  // reaches one fine margin further: the rod's way until its next placement.
  const double ahead = fine_margin_for(extent);
  const double below_x = reach + (travel.x() < 0 ? ahead : 0.0), above_x = reach + (travel.x() > 0 ? ahead : 0.0);
  const double below_y = reach + (travel.y() < 0 ? ahead : 0.0), above_y = reach + (travel.y() > 0 ? ahead : 0.0);
  const long i0 = static_cast<long>(std::floor((lo.x() - below_x - geometry.x_lo()) / h));
  const long i1 = i0 + 1 + static_cast<long>(std::ceil((hi.x() - lo.x() + below_x + above_x) / h));
  long j0 = static_cast<long>(std::floor((lo.y() - below_y - geometry.y_lo()) / h));
  long j1 = j0 + 1 + static_cast<long>(std::ceil((hi.y() - lo.y() + below_y + above_y) / h));
  j0 = std::max(j0, 0L);  // no disturbance beyond the side walls
  j1 = std::min(j1, static_cast<long>(std::ceil(geometry.width() / h)));
  WindowLattice lattice;
  lattice.h = h;
  const double fx0 = geometry.x_lo() + i0 * h, fy0 = geometry.y_lo() + j0 * h;
  const int fine_x = static_cast<int>(i1 - i0), fine_y = static_cast<int>(j1 - j0);
  // Graded part: from the fine zone out to `outer` beyond the rod's
  // footprints, never beyond the side walls.
  const double grow_x = std::max(0.0, fx0 - (lo.x() - outer));
  const double grow_x_up = std::max(0.0, hi.x() + outer - (fx0 + fine_x * h));
  const double grow_y = std::max(0.0, fy0 - std::max(lo.y() - outer, geometry.y_lo()));
  const double grow_y_up = std::max(0.0, std::min(hi.y() + outer, geometry.y_hi()) - (fy0 + fine_y * h));
  if (grow_x + grow_x_up + grow_y + grow_y_up < 1e-9 * h) {
    lattice.x0 = fx0;
    lattice.y0 = fy0;
    lattice.nx = fine_x;
    lattice.ny = fine_y;
    return lattice;
  }
  lattice.x_faces = graded_axis(fx0, fine_x, h, grow_x, grow_x_up, options_.grading);
  lattice.y_faces = graded_axis(fy0, fine_y, h, grow_y, grow_y_up, options_.grading);
  lattice.nx = static_cast<int>(lattice.x_faces.size()) - 1;
  lattice.ny = static_cast<int>(lattice.y_faces.size()) - 1;
  lattice.x0 = lattice.x_faces.front();
  lattice.y0 = lattice.y_faces.front();
  return lattice;
}

WindowLattice TwoWayWindowModel::free_lattice(double h, int cells, double margin) const {
  WindowLattice lattice;
  lattice.h = h;
  lattice.x_faces = graded_axis(-cells * h, 2 * cells, h, margin, margin, options_.grading);
  lattice.y_faces = lattice.x_faces;
  lattice.nx = lattice.ny = static_cast<int>(lattice.x_faces.size()) - 1;
  lattice.x0 = lattice.y0 = lattice.x_faces.front();
  return lattice;
}

WindowLattice TwoWayWindowModel::lattice_for(const RodGeometry& rod, const BackgroundFlow& flow) const {
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const auto& x : rod.positions) {
    lo = lo.cwiseMin(x.head<2>());
    hi = hi.cwiseMax(x.head<2>());
  }
  // The way the rod is carried: the background flow at its centroid, per
  // axis where that axis carries at least a third of it.
  const Eigen::Vector2d centre = 0.5 * (lo + hi);
  const Eigen::Vector2d stream = flow.velocity(centre.x(), centre.y());
  Eigen::Vector2i travel = Eigen::Vector2i::Zero();
  for (int a = 0; a < 2; ++a)
    if (std::abs(stream[a]) > stream.norm() / 3.0) travel[a] = stream[a] > 0.0 ? 1 : -1;
  return window_lattice(lo, hi, flow.geometry(), travel);
}

long TwoWayWindowModel::window_cells_for(const RodGeometry& rod, const BackgroundFlow& flow) const {
  const WindowLattice lattice = lattice_for(rod, flow);
  return static_cast<long>(lattice.nx) * lattice.ny;
}

void TwoWayWindowModel::place_window(const RodGeometry& rod, const BackgroundFlow& flow, RodState& rod_state,
                                     TwoWayWindowState& state) const {
  const ChannelGeometry& geometry = flow.geometry();
  const WindowLattice lattice = lattice_for(rod, flow);
  const long cells = static_cast<long>(lattice.nx) * lattice.ny;
  if (cells > options_.max_window_cells)
    throw std::invalid_argument("twoway: window of " + std::to_string(cells) + " cells exceeds the limit of " +
                                std::to_string(options_.max_window_cells) +
                                " (coarser grid, smaller margin or shorter rod)");
  TwoWayWindowStatistics& stats = state.statistics;
  ++stats.placements;
  stats.last_window_cells = static_cast<int>(cells);
  rod_state.placed = lattice;
  rod_state.translated = false;
  // A window that no pore cylinder reaches is the same system as an earlier
  // one of the same shape moved along x (a straight channel's side walls are
  // parallel to x), or in any direction if no side wall is in either: its
  // factorisation is reused.
  const bool clear = window_clear_of_cylinders(lattice, geometry);
  const auto cached = state.free_windows.find({lattice.nx, lattice.ny});
  if (clear && cached != state.free_windows.end()) {
    const WindowLattice& g = cached->second->lattice();
    const bool side = near_side_walls(lattice, geometry) || near_side_walls(g, geometry);
    const WindowLattice moved = g.shifted(lattice.x0 - g.x0, side ? 0.0 : lattice.y0 - g.y0);
    if (same_cells(moved, lattice)) {
      rod_state.translated = true;
      rod_state.placed = moved;
      rod_state.window = std::make_unique<BrinkmanWindow>(
          cached->second->translated(moved.x0 - g.x0, moved.y0 - g.y0, cached->second->has_walls()));
      return;
    }
  }
  const auto start = std::chrono::steady_clock::now();
  rod_state.window = std::make_unique<BrinkmanWindow>(geometry, lattice, parameters_.viscosity);
  ++stats.factorisations;
  stats.factorisation_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (clear) state.free_windows[{lattice.nx, lattice.ny}] = std::make_shared<const BrinkmanWindow>(*rod_state.window);
}

bool TwoWayWindowModel::same_cells(const WindowLattice& a, const WindowLattice& b) {
  if (a.nx != b.nx || a.ny != b.ny || a.h != b.h) return false;
  const double tolerance = 1e-9 * a.h;
  for (int i = 0; i <= a.nx; ++i)
    if (std::abs(a.x_face(i) - b.x_face(i)) > tolerance) return false;
  for (int j = 0; j <= a.ny; ++j)
    if (std::abs(a.y_face(j) - b.y_face(j)) > tolerance) return false;
  return true;
}

// The uniform part of a window: its cells of size h (the whole window if uniform).
void TwoWayWindowModel::fine_zone(const WindowLattice& g, Eigen::Vector2d& lo, Eigen::Vector2d& hi) {
  auto fine = [&](double size) { return std::abs(size - g.h) <= 1e-6 * g.h; };
  int i0 = 0, i1 = g.nx, j0 = 0, j1 = g.ny;
  while (i0 < g.nx && !fine(g.dx(i0))) ++i0;
  while (i1 > i0 && !fine(g.dx(i1 - 1))) --i1;
  while (j0 < g.ny && !fine(g.dy(j0))) ++j0;
  while (j1 > j0 && !fine(g.dy(j1 - 1))) --j1;
  lo = Eigen::Vector2d(g.x_face(i0), g.y_face(j0));
  hi = Eigen::Vector2d(g.x_face(i1), g.y_face(j1));
}

// The rod still lies in the inner part of its window: at least half the
// margin from every edge that is not beyond a side wall.
bool TwoWayWindowModel::window_holds(const RodGeometry& rod, const ChannelGeometry& geometry,
                                     const BrinkmanWindow& window) const {
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const auto& x : rod.positions) {
    lo = lo.cwiseMin(x.head<2>());
    hi = hi.cwiseMax(x.head<2>());
  }
  const double r = window_footprint_radius(), h = window_spacing_;
  const double keep = 0.5 * fine_margin_for((hi - lo).maxCoeff() + 2.0 * r) + r;
  Eigen::Vector2d zone_lo, zone_hi;
  fine_zone(window.lattice(), zone_lo, zone_hi);
  const bool lower_wall = zone_lo.y() <= geometry.y_lo() + 1e-9 * h;
  const bool upper_wall = zone_hi.y() >= geometry.y_hi() - 1e-9 * h;
  return lo.x() - keep >= zone_lo.x() && hi.x() + keep <= zone_hi.x() && (lower_wall || lo.y() - keep >= zone_lo.y()) &&
         (upper_wall || hi.y() + keep <= zone_hi.y());
}

}  // namespace hsrod

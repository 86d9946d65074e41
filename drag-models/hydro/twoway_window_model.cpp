#include "hydro/twoway_window_model.h"
#include "common/math_constants.h"
#include "hydro/nonlocal_model.h"
#include "hydro/peskin_kernel.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <limits>
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

// Mean self-mobility of a footprint on a free lattice table of cells h [m]
// over sub-cell places and the two in-plane directions [m/(N s)].
double mean_lattice_self_mobility(const LatticeGreenTable& table, double h) {
  double sum = 0.0;
  int samples = 0;
  for (double ox : {0.0, 0.125, 0.25, 0.375, 0.5})
    for (double oy : {0.0, 0.125, 0.25, 0.375, 0.5}) {
      const LatticeFootprint f = table.footprint(Eigen::Vector3d(ox * h, oy * h, 0.0), Eigen::Vector2d::Zero());
      const Eigen::Matrix2d m = table.pair(f, f);
      sum += m(0, 0) + m(1, 1);
      samples += 2;
    }
  return sum / samples;
}

// Mean free-lattice mobility [m/(N s)] between the footprints of two
// spheres at x_i and x_j on a table of cells h [m], over sub-cell places of
// the pair (both shifted alike across one cell): a function of x_j - x_i
// alone, as the continuous Green's function is.
Eigen::Matrix2d mean_lattice_pair_mobility(const LatticeGreenTable& table, const Eigen::Vector3d& x_i,
                                           const Eigen::Vector3d& x_j, const Eigen::Vector2d& anchor, double h) {
  // Places per direction (the midpoint rule over one period of the lattice):
  // the pair term's sub-cell variation is its first harmonic, so 2 x 2
  // places remove it as 4 x 4 do (the dumbbell test's turn: the same to
  // 1e-3 deg per 200 um), at a quarter of the cost.
  constexpr int kPlaces = 2;
  Eigen::Matrix2d sum = Eigen::Matrix2d::Zero();
  for (int a = 0; a < kPlaces; ++a)
    for (int b = 0; b < kPlaces; ++b) {
      const Eigen::Vector3d shift((a + 0.5) / kPlaces * h, (b + 0.5) / kPlaces * h, 0.0);
      sum += table.pair(table.footprint(x_i + shift, anchor), table.footprint(x_j + shift, anchor));
    }
  return sum / (kPlaces * kPlaces);
}
}  // namespace

TwoWayWindowModel::TwoWayWindowModel(const HydrodynamicParameters& p, const ConfinementTable& table,
                                     const TwoWayWindowOptions& options)
    : LocalDragBase(p, table), options_(options) {
  if (!(options_.cells_per_diameter >= 2.0) || options_.cells_per_diameter > 16.0)
    throw std::invalid_argument("twoway: cells per diameter must be in [2, 16]");
  if (options_.margin < 0.0) throw std::invalid_argument("twoway: window margin must be >= 0 m");
  if (options_.update_distance < 0.0) throw std::invalid_argument("twoway: update distance must be >= 0 m");
  if (options_.update_every < 0) throw std::invalid_argument("twoway: update interval must be >= 0 steps");
  if (options_.fine_margin < 0.0) throw std::invalid_argument("twoway: window fine margin must be >= 0 m");
  if (options_.grading != 0.0 && (!(options_.grading > 1.0) || options_.grading > 2.0))
    throw std::invalid_argument("twoway: window grading must be in (1, 2]");
  if (options_.margin > 0.0 && options_.fine_margin > options_.margin)
    throw std::invalid_argument("twoway: window fine margin must not exceed the window margin");
  const double d = p.sphere_diameter;
  if (options_.update_distance == 0.0) options_.update_distance = 0.5 * d;
  spacing_ = d / options_.cells_per_diameter;
  if (options_.reflection_cells_per_diameter == 0.0)
    options_.reflection_cells_per_diameter = std::min(kReflectionCellsPerDiameter, options_.cells_per_diameter);
  if (!(options_.reflection_cells_per_diameter >= 1.0) ||
      options_.reflection_cells_per_diameter > options_.cells_per_diameter)
    throw std::invalid_argument("twoway: reflection cells per diameter must be in [1, cells per diameter]");
  window_spacing_ = d / options_.reflection_cells_per_diameter;
  if (options_.grading == 0.0) options_.grading = two_scales() ? kTwoScaleGrading : kOneScaleGrading;
  if (two_scales()) {
    near_reach_ = kNearReach * d;
    fine_table_ = free_lattice_table(spacing_, kernel_width());
    window_table_ = free_lattice_table(window_spacing_, window_kernel_width());
    fine_self_mobility_ = mean_lattice_self_mobility(*fine_table_, spacing_);
  }
  obstruction_ = LocalDragBase::obstruction_friction();
  film_friction_ = sphere_friction_ - obstruction_;
  free_self_mobility_ = measure_free_self_mobility();
  // c m_free < 1/zeta_o is not required: the rod's matrix
  // I/zeta_o + c (M - m_free I) stays positive definite while the spheres'
  // mutual mobilities stay below 1/(c zeta_o) (checked at each update).
}

double TwoWayWindowModel::margin_for(double rod_extent) const {
  if (options_.margin > 0.0) return options_.margin;
  const double screening = parameters_.gap_height / std::sqrt(12.0);
  return std::max({kOuterScreenings * screening, kOuterExtents * rod_extent, 2.0 * parameters_.sphere_diameter});
}

// Self-mobility of one footprint on the lattice in free space (a planform
// far wider than the window), on the window the model places around a lone
// sphere, averaged over sub-cell positions and the two in-plane directions.
double TwoWayWindowModel::measure_free_self_mobility() const {
  const double h = window_spacing_, r = window_footprint_radius();
  const double half = margin_for(2.0 * r) + r;
  const double side = 2.0 * h * std::ceil(200.0 * half / h);  // planform corner on the lattice
  const ChannelGeometry open(side, side, parameters_.gap_height, -0.5 * side, -0.5 * side);
  const WindowLattice lattice =
      window_lattice(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), open, Eigen::Vector2i::Zero());
  const BrinkmanWindow window(open, lattice, parameters_.viscosity);
  double sum = 0.0;
  int samples = 0;
  for (double ox : {0.0, 0.25, 0.5})
    for (double oy : {0.0, 0.25, 0.5}) {
      RodGeometry sphere;
      sphere.sphere_diameter = parameters_.sphere_diameter;
      sphere.positions.push_back(Eigen::Vector3d(ox * spacing_, oy * spacing_, 0.0));
      const Eigen::MatrixXd m = footprint_mobility(sphere, open, window);
      sum += m(0, 0) + m(1, 1);
      samples += 2;
    }
  return sum / samples;
}

// Green's table of a free lattice of cells h [m] for footprints of kernel
// width w [m]: a wall-free window, uniform over the pairs' reach plus a
// footprint on each side and graded out to the model's margin beyond it.
std::shared_ptr<const LatticeGreenTable> TwoWayWindowModel::free_lattice_table(double h, double w) const {
  const double reach = near_reach_ + 4.0 * std::sqrt(2.0) * w + h;
  const int cells = static_cast<int>(std::ceil(reach / h)) + 2;
  const double margin = margin_for(2.0 * reach);
  const double side = 4.0 * (cells * h + margin);
  const ChannelGeometry open(side, side, parameters_.gap_height, -0.5 * side, -0.5 * side);
  WindowLattice lattice;
  lattice.h = h;
  lattice.x_faces = graded_axis(-cells * h, 2 * cells, h, margin, margin, options_.grading);
  lattice.y_faces = lattice.x_faces;
  lattice.nx = lattice.ny = static_cast<int>(lattice.x_faces.size()) - 1;
  lattice.x0 = lattice.y0 = lattice.x_faces.front();
  const BrinkmanWindow window(open, lattice, parameters_.viscosity);
  return std::make_shared<const LatticeGreenTable>(window, w, reach);
}

double TwoWayWindowModel::near_weight(double distance) const {
  const double t = (distance - 0.5 * near_reach_) / (0.5 * near_reach_);
  if (t <= 0.0) return 1.0;
  if (t >= 1.0) return 0.0;
  return 1.0 - t * t * (3.0 - 2.0 * t);  // smoothstep
}

TwoWayWindowModel::Footprint TwoWayWindowModel::footprint(const BrinkmanWindow& window,
                                                          const Eigen::Vector3d& centre) const {
  Footprint f;
  const double w = window_kernel_width();
  const Eigen::Vector2d c = centre.head<2>();
  for (int a = 0; a < 2; ++a) {
    double total = 0.0;
    for (int k : window.nodes_near(c, 2.0 * std::sqrt(2.0) * w, a)) {
      const Eigen::Vector2d r = (window.nodes()[k].position - c) / w;
      const double weight = peskin_kernel(r.x()) * peskin_kernel(r.y());
      if (weight <= 0.0) continue;
      f.nodes[a].push_back(k);
      f.weights[a].push_back(weight);
      total += weight;
    }
    // Near a wall some nodes are missing: the force stays on the fluid ones.
    for (double& weight : f.weights[a]) weight /= total;
  }
  return f;
}

Eigen::VectorXd TwoWayWindowModel::fluid_node_forces(const BrinkmanWindow& window,
                                                     const std::vector<Eigen::Vector3d>& positions,
                                                     const Eigen::VectorXd& sphere_forces) const {
  if (sphere_forces.size() != 2 * static_cast<Eigen::Index>(positions.size()))
    throw std::invalid_argument("twoway: fluid_node_forces needs 2 force components per sphere");
  Eigen::VectorXd nodes = Eigen::VectorXd::Zero(window.unknowns());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Footprint f = footprint(window, positions[i]);
    for (int a = 0; a < 2; ++a)
      for (std::size_t k = 0; k < f.nodes[a].size(); ++k)
        nodes[f.nodes[a][k]] -= f.weights[a][k] * sphere_forces[2 * static_cast<Eigen::Index>(i) + a];
  }
  return nodes;
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


double TwoWayWindowModel::fine_margin_for(double rod_extent) const {
  if (options_.fine_margin > 0.0) return std::min(options_.fine_margin, margin_for(rod_extent));
  const double screening = parameters_.gap_height / std::sqrt(12.0);
  return std::min(margin_for(rod_extent), std::max(2.0 * screening, 2.0 * parameters_.sphere_diameter));
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

Eigen::MatrixXd TwoWayWindowModel::footprint_mobility(const RodGeometry& rod, const ChannelGeometry& geometry,
                                                      const BrinkmanWindow& window) const {
  const int n = rod.size();
  std::vector<Footprint> prints;
  prints.reserve(n);
  for (const auto& x : rod.positions) prints.push_back(footprint(window, x));
  // Unit forces spread over each footprint, the response averaged over the
  // footprints with the same weights (BrinkmanWindow::weighted_response).
  std::vector<BrinkmanWindow::NodeForces> forces(2 * n);
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < 2; ++a) {
      forces[2 * i + a].reserve(prints[i].nodes[a].size());
      for (std::size_t k = 0; k < prints[i].nodes[a].size(); ++k)
        forces[2 * i + a].emplace_back(prints[i].nodes[a][k], prints[i].weights[a][k]);
    }
  Eigen::MatrixXd mobility = window.weighted_response(forces, forces);
  if (two_scales()) {
    // The fine lattice's free-space mobility replaces the window lattice's
    // between nearby footprints (each footprint with itself and with its
    // neighbours within the near reach); what the window adds to its own
    // free-space mobility (the walls' reflection, the window's edges, the
    // far field) is kept.
    const Eigen::Vector2d anchor(geometry.x_lo(), geometry.y_lo());
    std::vector<LatticeFootprint> coarse;
    for (const auto& x : rod.positions) coarse.push_back(window_table_->footprint(x, anchor));
    // The fine pair terms, each pair once (reciprocity: M_ji = M_ij^T).
    std::vector<Eigen::Matrix2d> fine_pairs(static_cast<std::size_t>(n) * n);
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (near_weight((rod.positions[i] - rod.positions[j]).head<2>().norm()) > 0.0) {
          fine_pairs[i * n + j] =
              mean_lattice_pair_mobility(*fine_table_, rod.positions[i], rod.positions[j], anchor, spacing_);
          fine_pairs[j * n + i] = fine_pairs[i * n + j].transpose();
        }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double weight = near_weight((rod.positions[i] - rod.positions[j]).head<2>().norm());
        if (weight <= 0.0) continue;
        // A footprint's fine-lattice mobility, with itself or with a
        // neighbour, varies by a fraction of a percent with its place
        // between the nodes; a rod's spheres sit at different places, so
        // that noise would make the two ends of a short rod unequal and turn
        // it (a 2-sphere rod ~3 deg over 200 um of travel by the self term,
        // up to 2.7 deg by the pair term at beta 0.85): both terms take
        // their mean over sub-cell places instead.
        const Eigen::Matrix2d fine_pair =
            i == j ? Eigen::Matrix2d(fine_self_mobility_ * Eigen::Matrix2d::Identity()) : fine_pairs[i * n + j];
        mobility.block<2, 2>(2 * i, 2 * j) += weight * (fine_pair - window_table_->pair(coarse[i], coarse[j]));
      }
  }
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < 2; ++a)
      if (prints[i].nodes[a].empty()) {  // footprint off the grid: isolated sphere
        const int row = 2 * i + a;
        mobility.row(row).setZero();
        mobility(row, row) = free_self_mobility_;
      }
  return mobility;
}

// R_o = (I / zeta_o + c (M - m_free I))^-1 from the footprint mobility M.
void TwoWayWindowModel::update_resistance(const RodGeometry& rod, const ChannelGeometry& geometry, RodState& state,
                                          TwoWayWindowStatistics& stats) const {
  const int n = rod.size();
  const auto start = std::chrono::steady_clock::now();
  Eigen::MatrixXd mobility = footprint_mobility(rod, geometry, *state.window);
  stats.solve_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Reciprocity holds for the continuous problem; the wall stencils make the
  // discrete M slightly non-symmetric.
  mobility = 0.5 * (mobility + mobility.transpose()).eval();
  Eigen::MatrixXd a = kMidplaneFactor * mobility;
  a.diagonal().array() += 1.0 / obstruction_ - kMidplaneFactor * free_self_mobility_;
  Eigen::LLT<Eigen::MatrixXd> llt(a);
  if (llt.info() != Eigen::Success)
    throw std::runtime_error("twoway: the rod's obstruction matrix is not positive definite: level 4's window "
                             "model does not describe this rod here (seen for a sphere too close to a wall for "
                             "the window grid, and for long rods at beta >= 0.85 at any window_cells); "
                             "refine window_cells, or use model nonlocal (level 3) or local (level 2)");
  state.obstruction = llt.solve(Eigen::MatrixXd::Identity(2 * n, 2 * n));
  state.solved_positions = rod.positions;
  state.evaluations_since_update = 0;
  ++stats.updates;
}

std::string TwoWayWindowState::work_summary() const {
  const TwoWayWindowStatistics& s = statistics;
  char line[320];
  std::snprintf(line, sizeof(line),
                "twoway: %ld evaluations, %ld resistance updates (%.3g s of solves), %ld window placements, "
                "%ld factorisations (%.3g s), last window %d cells of %.3g m",
                s.evaluations, s.updates, s.solve_seconds, s.placements, s.factorisations, s.factorisation_seconds,
                s.last_window_cells, spacing);
  return line;
}

namespace {
void put_lattice(std::vector<double>& out, const WindowLattice& g) {
  out.insert(out.end(), {g.x0, g.y0, g.h, static_cast<double>(g.nx), static_cast<double>(g.ny), g.graded() ? 1.0 : 0.0});
  if (!g.graded()) return;
  for (int i = 0; i <= g.nx; ++i) out.push_back(g.x_face(i));
  for (int j = 0; j <= g.ny; ++j) out.push_back(g.y_face(j));
}

// Reads the restart data back in order; throws on running past its end.
struct Reader {
  const std::vector<double>& data;
  std::size_t at = 0;
  double next() {
    if (at >= data.size()) throw std::invalid_argument("twoway: restart data ends early");
    return data[at++];
  }
  int integer() { return static_cast<int>(next()); }
  WindowLattice lattice() {
    WindowLattice g;
    g.x0 = next();
    g.y0 = next();
    g.h = next();
    g.nx = integer();
    g.ny = integer();
    if (next() != 0.0) {
      if (g.nx < 0 || g.ny < 0 || data.size() - at < static_cast<std::size_t>(g.nx) + g.ny + 2)
        throw std::invalid_argument("twoway: restart data ends early");
      for (int i = 0; i <= g.nx; ++i) g.x_faces.push_back(next());
      for (int j = 0; j <= g.ny; ++j) g.y_faces.push_back(next());
    }
    return g;
  }
};
constexpr double kStateTag = 4.0;  // first number: the model level that wrote the data
}  // namespace

std::vector<double> TwoWayWindowModel::save_state(const ModelState& base) const {
  const auto& state = dynamic_cast<const TwoWayWindowState&>(base);
  std::vector<double> out{kStateTag, static_cast<double>(state.free_windows.size())};
  for (const auto& entry : state.free_windows) put_lattice(out, entry.second->lattice());
  out.push_back(static_cast<double>(state.rods.size()));
  for (const auto& entry : state.rods) {
    const RodState& rod = entry.second;
    const int n = static_cast<int>(rod.solved_positions.size());
    out.insert(out.end(), {static_cast<double>(entry.first), rod.window ? 1.0 : 0.0, rod.translated ? 1.0 : 0.0});
    put_lattice(out, rod.placed);
    out.insert(out.end(), {static_cast<double>(n), static_cast<double>(rod.evaluations_since_update)});
    for (const auto& x : rod.solved_positions) out.insert(out.end(), {x.x(), x.y(), x.z()});
    for (int k = 0; k < rod.obstruction.size(); ++k) out.push_back(rod.obstruction.data()[k]);
  }
  const TwoWayWindowStatistics& s = state.statistics;
  out.insert(out.end(), {static_cast<double>(s.evaluations), static_cast<double>(s.updates),
                         static_cast<double>(s.placements), static_cast<double>(s.factorisations),
                         static_cast<double>(s.last_window_cells), s.factorisation_seconds, s.solve_seconds});
  return out;
}

void TwoWayWindowModel::restore_state(ModelState& base, const std::vector<double>& data,
                                      const BackgroundFlow& flow) const {
  auto& state = dynamic_cast<TwoWayWindowState&>(base);
  Reader in{data};
  if (in.next() != kStateTag) throw std::invalid_argument("twoway: restart data from another model");
  const ChannelGeometry& geometry = flow.geometry();
  state.rods.clear();
  state.free_windows.clear();
  for (int count = in.integer(); count > 0; --count) {
    const WindowLattice g = in.lattice();
    state.free_windows[{g.nx, g.ny}] = std::make_shared<const BrinkmanWindow>(geometry, g, parameters_.viscosity);
  }
  for (int count = in.integer(); count > 0; --count) {
    RodState& rod = state.rods[in.integer()];
    const bool has_window = in.next() != 0.0;
    rod.translated = in.next() != 0.0;
    rod.placed = in.lattice();
    const int n = in.integer();
    rod.evaluations_since_update = in.integer();
    rod.solved_positions.resize(n);
    for (auto& x : rod.solved_positions)
      for (int a = 0; a < 3; ++a) x[a] = in.next();
    rod.obstruction.resize(2 * n, 2 * n);
    for (int k = 0; k < rod.obstruction.size(); ++k) rod.obstruction.data()[k] = in.next();
    if (!has_window) continue;
    // Rebuilt as it was built: a translation of the shared wall-free window, or its own factorisation.
    const auto cached = state.free_windows.find({rod.placed.nx, rod.placed.ny});
    if (rod.translated && cached != state.free_windows.end()) {
      const WindowLattice& g = cached->second->lattice();
      rod.window = std::make_unique<BrinkmanWindow>(cached->second->translated(
          rod.placed.x0 - g.x0, rod.placed.y0 - g.y0, cached->second->has_walls()));
    } else {
      rod.window = std::make_unique<BrinkmanWindow>(geometry, rod.placed, parameters_.viscosity);
    }
  }
  TwoWayWindowStatistics& s = state.statistics;
  s.evaluations = static_cast<long>(in.next());
  s.updates = static_cast<long>(in.next());
  s.placements = static_cast<long>(in.next());
  s.factorisations = static_cast<long>(in.next());
  s.last_window_cells = in.integer();
  s.factorisation_seconds = in.next();
  s.solve_seconds = in.next();
  if (in.at != data.size()) throw std::invalid_argument("twoway: restart data longer than expected");
}

std::unique_ptr<ModelState> TwoWayWindowModel::make_state() const {
  auto state = std::make_unique<TwoWayWindowState>();
  state->spacing = window_spacing_;
  return state;
}

void TwoWayWindowModel::evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out,
                                 ModelState* state) const {
  if (!state) {
    TwoWayWindowState fresh;
    fresh.spacing = window_spacing_;
    evaluate_with(rod, flow, out, fresh);
    return;
  }
  auto* own = dynamic_cast<TwoWayWindowState*>(state);
  if (!own) throw std::invalid_argument("twoway: the state given is not a level-4 state (make_state())");
  evaluate_with(rod, flow, out, *own);
}

int TwoWayWindowModel::joint_key(const std::vector<RodGeometry>& rods) {
  int smallest = rods.empty() ? 0 : rods.front().id;
  for (const RodGeometry& rod : rods) smallest = std::min(smallest, rod.id);
  return -(1 + smallest);
}

void TwoWayWindowModel::evaluate_rods(const std::vector<RodGeometry>& rods, const BackgroundFlow& flow, RodDrag& out,
                                      ModelState* state) const {
  if (rods.size() == 1) {
    evaluate(rods.front(), flow, out, state);
    return;
  }
  const RodGeometry all = joined_rods(rods, joint_key(rods));
  std::vector<int> members;
  for (const RodGeometry& rod : rods) members.push_back(rod.id);
  if (auto* own = dynamic_cast<TwoWayWindowState*>(state)) {
    // A window kept under this key for another set of rods is dropped (a
    // restored one, members unknown, is kept: it was saved for these rods).
    const auto it = own->rods.find(all.id);
    if (it != own->rods.end() && !it->second.members.empty() && it->second.members != members) own->rods.erase(it);
    own->rods[all.id].members = members;
  }
  evaluate(all, flow, out, state);  // virtual: the registered model adds its near field
}

double TwoWayWindowModel::interaction_reach() const {
  return depth_averaged_interaction_reach(parameters_.gap_height, parameters_.viscosity, obstruction_,
                                          NonlocalRodModel::kInteractionTolerance);
}

void TwoWayWindowModel::evaluate_with(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out,
                                      TwoWayWindowState& rods) const {
  ++rods.statistics.evaluations;
  if (std::abs(flow.geometry().gap_height() - parameters_.gap_height) > 1e-9 * parameters_.gap_height)
    throw std::invalid_argument("twoway: the flow's gap height differs from the model's");
  const int n = rod.size();
  RodState& state = rods.rods[rod.id];
  bool update = !state.window || static_cast<int>(state.solved_positions.size()) != n ||
                (options_.update_every > 0 && state.evaluations_since_update >= options_.update_every);
  // The rod's in-plane turn since its last solve [rad]: the stored
  // resistance is used turned with it.
  double turn = 0.0;
  if (!update) {
    // Away from walls the window system is translation invariant: only a
    // change of the rod's shape or orientation (sphere displacements
    // relative to the centroid's) calls for a new solve (measured on the pore
    // passage: x changes by 0.13 d, within the grid's sub-cell noise of
    // 0.1-0.3 % in R). A rigid shift changes only the walls' reflection,
    // which falls off as 1/s^2 with the distance s to the nearest wall: a
    // shift by s/8 changes it by ~25 % of itself (a fraction of a percent
    // of R once s is several l), so the rod is re-solved after a shift of
    // max(update distance, s/8); along a straight channel (no pore cylinder
    // in the window) a shift along x changes nothing.
    Eigen::Vector2d shift = Eigen::Vector2d::Zero();
    for (int i = 0; i < n; ++i) shift += (rod.positions[i] - state.solved_positions[i]).head<2>() / n;
    double wall_distance = std::numeric_limits<double>::infinity();
    if (state.window->has_walls())
      for (const auto& x : rod.positions)
        wall_distance = std::min(wall_distance, flow.geometry().signed_distance(x.x(), x.y()));
    Eigen::Vector2d rigid = shift;
    if (window_clear_of_cylinders(state.window->lattice(), flow.geometry())) rigid.x() = 0.0;
    update = rigid.norm() > std::max(options_.update_distance, kWallShiftFraction * wall_distance);
    for (int i = 0; !update && i < n; ++i) {
      const Eigen::Vector2d moved = (rod.positions[i] - state.solved_positions[i]).head<2>() - shift;
      update = moved.norm() > options_.update_distance;
    }
    update = update || !window_holds(rod, flow.geometry(), *state.window);
    // Between solves the rod turns (its ends up to the update distance from
    // the centroid's move: ~6 deg for a 10-sphere rod); the stored
    // resistance is turned with it (Q R Q^T, exact for the continuous
    // problem away from walls), by the angle of the rigid motion that best
    // carries the solved positions onto the current ones. Kept unturned,
    // level 4's pore passage ended 0.036 deg off one re-solved at every
    // evaluation (window_every 1); turned, 0.003 deg.
    if (!update && n > 1) {
      Eigen::Vector2d solved_centre = Eigen::Vector2d::Zero(), centre = Eigen::Vector2d::Zero();
      for (int i = 0; i < n; ++i) {
        solved_centre += state.solved_positions[i].head<2>() / n;
        centre += rod.positions[i].head<2>() / n;
      }
      double dot = 0.0, cross = 0.0;
      for (int i = 0; i < n; ++i) {
        const Eigen::Vector2d a = state.solved_positions[i].head<2>() - solved_centre;
        const Eigen::Vector2d b = rod.positions[i].head<2>() - centre;
        dot += a.dot(b);
        cross += a.x() * b.y() - a.y() * b.x();
      }
      turn = std::atan2(cross, dot);
      update = !(std::fabs(turn) <= kMaxTurn);
    }
  }
  if (update) turn = 0.0;
  if (update) {
    if (!state.window || !window_holds(rod, flow.geometry(), *state.window))
      place_window(rod, flow, state, rods);
    update_resistance(rod, flow.geometry(), state, rods.statistics);
  } else {
    ++state.evaluations_since_update;
  }

  // Footprint-averaged background flow at the current positions.
  Eigen::VectorXd background(2 * n);
  for (int i = 0; two_scales() && i < n; ++i) {
    // On the fine lattice (the sphere's own footprint), not the window's.
    const Eigen::Vector2d anchor(flow.geometry().x_lo(), flow.geometry().y_lo());
    const LatticeFootprint f =
        lattice_footprint(rod.positions[i].head<2>(), anchor, spacing_, kernel_width(), &flow.geometry());
    for (int a = 0; a < 2; ++a) {
      double u = f.nodes[a].empty() ? flow.velocity(rod.positions[i].x(), rod.positions[i].y())[a] : 0.0;
      for (std::size_t k = 0; k < f.nodes[a].size(); ++k) {
        const Eigen::Vector2d p = lattice_node_position(f.nodes[a][k], anchor, spacing_);
        u += f.weights[a][k] * flow.velocity(p.x(), p.y())[a];
      }
      background[2 * i + a] = u;
    }
  }
  for (int i = 0; !two_scales() && i < n; ++i) {
    const Footprint f = footprint(*state.window, rod.positions[i]);
    for (int a = 0; a < 2; ++a) {
      if (f.nodes[a].empty()) {
        background[2 * i + a] = flow.velocity(rod.positions[i].x(), rod.positions[i].y())[a];
        continue;
      }
      double u = 0.0;
      for (std::size_t k = 0; k < f.nodes[a].size(); ++k) {
        const Eigen::Vector2d& p = state.window->nodes()[f.nodes[a][k]].position;
        u += f.weights[a][k] * flow.velocity(p.x(), p.y())[a];
      }
      background[2 * i + a] = u;
    }
  }
  // The stored resistance turned with the rod: Q R Q^T block by block.
  const Eigen::MatrixXd* obstruction = &state.obstruction;
  Eigen::MatrixXd turned;
  if (turn != 0.0) {
    const Eigen::Matrix2d q = Eigen::Rotation2Dd(turn).toRotationMatrix();
    turned.resize(2 * n, 2 * n);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k)
        turned.block<2, 2>(2 * i, 2 * k) = q * state.obstruction.block<2, 2>(2 * i, 2 * k) * q.transpose();
    obstruction = &turned;
  }
  const Eigen::VectorXd driving = kMidplaneFactor * (*obstruction * background);

  out.resize(n);
  out.coupled_resistance = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < n; ++k)
      out.coupled_resistance.block<2, 2>(3 * i, 3 * k) = obstruction->block<2, 2>(2 * i, 2 * k);
    out.coupled_resistance(3 * i, 3 * i) += film_friction_;
    out.coupled_resistance(3 * i + 1, 3 * i + 1) += film_friction_;
    out.coupled_resistance(3 * i + 2, 3 * i + 2) = sphere_friction_;
    out.driving_force[i] = Eigen::Vector3d(driving[2 * i], driving[2 * i + 1], 0.0);
    out.resistance[i] = out.coupled_resistance.block<3, 3>(3 * i, 3 * i);
  }
  add_rotation(rod, flow, out);
}

}  // namespace hsrod

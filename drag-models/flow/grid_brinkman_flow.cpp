#include "flow/grid_brinkman_flow.h"

#include "flow/flow_cache.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hsrod {
namespace {

std::atomic<long> g_instances{0};
std::atomic<long> g_solves{0};

void check_options(const GridBrinkmanOptions& o) {
  auto fail = [](const std::string& what) {
    throw std::invalid_argument("GridBrinkmanOptions: " + what);
  };
  if (!std::isfinite(o.cell_size) || o.cell_size < 0.0)
    fail("cell_size must be >= 0 m (0 = automatic)");
  if (o.cells_per_wall_layer < 1) fail("cells_per_wall_layer must be >= 1");
  if (o.cells_across_opening < 2) fail("cells_across_opening must be >= 2");
  if (o.max_picard_iterations < 1) fail("max_picard_iterations must be >= 1");
  if (!(o.picard_tolerance > 0.0)) fail("picard_tolerance must be > 0");
  if (o.max_cells < 4) fail("max_cells must be >= 4");
  if (!(o.max_memory_bytes > 0.0)) fail("max_memory_bytes must be > 0");
  if (!(o.max_predicted_seconds > 0.0)) fail("max_predicted_seconds must be > 0 s");
  if (!(o.resolved_layer_max_seconds >= 0.0)) fail("resolved_layer_max_seconds must be >= 0 s");
}

// Grid of cells no larger than h [m] over the planform; throws over max_cells.
MacGrid grid_with_cell_size(const ChannelGeometry& geo, double h, long max_cells) {
  const double nx = std::ceil(geo.length() / h - 1e-9), ny = std::ceil(geo.width() / h - 1e-9);
  if (!(nx * ny <= static_cast<double>(max_cells))) {
    std::ostringstream msg;
    msg << "background-flow grid of " << nx << " x " << ny << " cells (cell size " << h
        << " m) exceeds max_cells = " << max_cells;
    throw GridSolveTooLarge(msg.str());
  }
  MacGrid g;
  g.nx = std::max(2, static_cast<int>(nx));
  g.ny = std::max(4, static_cast<int>(ny));
  g.hx = geo.length() / g.nx / geo.gap_height();
  g.hy = geo.width() / g.ny / geo.gap_height();
  return g;
}

// Why a grid over the limits is that fine, for the refusal's message: the
// narrowest opening sets the cell size (a nearly closed pore was otherwise
// refused with the names of options the user cannot set). Finds by
// bisection the narrowest opening whose grid would fit.
std::string opening_note(const ChannelGeometry& geo, const GridBrinkmanOptions& o) {
  if (o.cell_size > 0.0 || o.wall_layer == GridBrinkmanOptions::WallLayer::kResolved) return "";
  const ChannelGeometry scaled = scaled_planform(geo);
  auto fits = [&](double h) {
    const double nx = std::ceil(geo.length() / h - 1e-9), ny = std::ceil(geo.width() / h - 1e-9);
    if (!(nx * ny <= static_cast<double>(o.max_cells))) return false;
    const GridSolveEstimate e = estimate_grid_solve(scaled, grid_with_cell_size(geo, h, o.max_cells), o.include_inertia);
    return e.memory_bytes <= o.max_memory_bytes && e.seconds <= o.max_predicted_seconds;
  };
  const double opening = geo.narrowest_opening();
  double coarse = std::min(geo.length(), geo.width()) / 4.0, fine = opening / o.cells_across_opening;
  if (!fits(coarse)) return "";
  for (int i = 0; i < 60 && coarse / fine > 1.001; ++i) {
    const double mid = std::sqrt(coarse * fine);
    (fits(mid) ? coarse : fine) = mid;
  }
  std::ostringstream msg;
  msg.precision(3);
  msg << "; the cell size is set by the narrowest opening of the planform, " << opening << " m across (resolved by "
      << o.cells_across_opening << " cells): in this " << geo.length() << " x " << geo.width()
      << " m planform the grid fits for openings of at least " << coarse * o.cells_across_opening
      << " m (widen the pore or the gap between obstacles, or shorten the channel)";
  return msg.str();
}

}  // namespace

double grid_cell_size(const ChannelGeometry& geo, const GridBrinkmanOptions& o) {
  check_options(o);
  if (o.cell_size > 0.0) return o.cell_size;
  const double wall_layer = geo.gap_height() / std::sqrt(12.0);
  return std::min(wall_layer / o.cells_per_wall_layer,
                  geo.narrowest_opening() / o.cells_across_opening);
}

MacGrid make_mac_grid(const ChannelGeometry& geo, const GridBrinkmanOptions& o) {
  return grid_with_cell_size(geo, grid_cell_size(geo, o), o.max_cells);
}

GridChoice choose_grid(const ChannelGeometry& geo, const GridBrinkmanOptions& o) {
  check_options(o);
  using WallLayer = GridBrinkmanOptions::WallLayer;
  const ChannelGeometry scaled = scaled_planform(geo);
  GridChoice c;
  c.exponential_wall_layer = o.wall_layer == WallLayer::kExponential;
  if (o.wall_layer == WallLayer::kAuto && o.cell_size == 0.0) {
    // Would a grid resolving the wall layer be affordable? Predicted from the
    // cell count alone (a grid over max_cells counts as unaffordable).
    const double h = grid_cell_size(geo, o);
    const double cells = std::ceil(geo.length() / h - 1e-9) * std::ceil(geo.width() / h - 1e-9);
    bool affordable = cells <= static_cast<double>(o.max_cells);
    if (affordable) {
      const MacGrid resolved = grid_with_cell_size(geo, h, o.max_cells);
      affordable = estimate_grid_solve(scaled, resolved, o.include_inertia).seconds <=
                   o.resolved_layer_max_seconds;
    }
    c.exponential_wall_layer = !affordable;
  }
  const double h = c.exponential_wall_layer && o.cell_size == 0.0
                       ? geo.narrowest_opening() / o.cells_across_opening
                       : grid_cell_size(geo, o);
  c.grid = grid_with_cell_size(geo, h, o.max_cells);
  c.estimate = estimate_grid_solve(scaled, c.grid, o.include_inertia);
  return c;
}

ChannelGeometry scaled_planform(const ChannelGeometry& geo) {
  const double h = geo.gap_height();
  std::vector<ZCylinder> cyl;
  for (const ZCylinder& c : geo.cylinders())
    cyl.push_back({(c.center_x - geo.x_lo()) / h, (c.center_y - geo.y_lo()) / h, c.radius / h});
  return ChannelGeometry(geo.length() / h, geo.width() / h, 1.0, 0.0, 0.0, std::move(cyl));
}

GridBrinkmanFlow::GridBrinkmanFlow(const ChannelGeometry& geometry, const FluidProperties& fluid,
                                   const Inflow& inflow, const GridBrinkmanOptions& options)
    : geometry_(geometry),
      mean_velocity_(inflow.mean_velocity_in(geometry)),
      viscosity_(fluid.dynamic_viscosity) {
  fluid.validate();
  ++g_instances;
  inertia_reynolds_ = options.include_inertia ? fluid.density * mean_velocity_ *
                                                    geometry.gap_height() / fluid.dynamic_viscosity
                                              : 0.0;
  const ChannelGeometry scaled = scaled_planform(geometry);
  GridChoice choice;
  try {
    choice = choose_grid(geometry, options);
  } catch (const GridSolveTooLarge& e) {
    throw GridSolveTooLarge(e.what() + opening_note(geometry, options));
  }
  const MacGrid& grid = choice.grid;
  exponential_wall_layer_ = choice.exponential_wall_layer;
  const std::string key =
      brinkman_cache_key(scaled, grid, inertia_reynolds_, exponential_wall_layer_);

  std::filesystem::path cache_dir;
  if (options.use_cache) {
    cache_dir = options.cache_dir.empty() ? default_cache_directory() : std::filesystem::path(options.cache_dir);
    if (!cache_dir.empty()) cache_file_ = (cache_dir / brinkman_cache_file_name(key)).string();
  }
  if (!cache_file_.empty()) {
    std::string why_unused;
    if (std::optional<StaggeredField> cached = load_cached_field(cache_file_, key, &why_unused)) {
      field_ = std::move(*cached);
      loaded_from_cache_ = true;
      return;
    }
    // A damaged or foreign file is solved anew and overwritten, with a notice.
    if (!why_unused.empty()) cache_notice_ = "cache file " + cache_file_ + " not used (" + why_unused + "), solved anew";
  }

  // Bounded work: refuse before the first allocation of solver size.
  try {
    check_grid_solve_budget(choice.estimate, GridSolveLimits{options.max_cells, options.max_memory_bytes,
                                                             options.max_predicted_seconds});
  } catch (const GridSolveTooLarge& e) {
    throw GridSolveTooLarge(e.what() + opening_note(geometry, options));
  }
  const auto start = std::chrono::steady_clock::now();
  BrinkmanGridSettings settings;
  settings.exponential_wall_layer = exponential_wall_layer_;
  settings.control = options.control;
  settings.inertia_reynolds = inertia_reynolds_;
  settings.max_picard_iterations = options.max_picard_iterations;
  settings.picard_tolerance = options.picard_tolerance;
  const BrinkmanGridSolution solution = solve_brinkman_on_grid(scaled, grid, settings);
  field_ = StaggeredField(solution, scaled);
  solve_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  picard_iterations_ = solution.picard_iterations;
  unknowns_ = solution.unknowns;
  solves_performed_ = 1;
  ++g_solves;
  if (!cache_file_.empty() && store_cached_field(cache_file_, key, field_, &cache_error_)) {
    // Bounded cache: without pruning, cache files would pile up for ever.
    const double limit = options.cache_size_limit >= 0.0 ? options.cache_size_limit : cache_size_limit_bytes();
    const std::string pruned = prune_cache_directory(cache_dir, limit, cache_file_).summary();
    if (!pruned.empty()) cache_notice_ += (cache_notice_.empty() ? "" : "; ") + pruned;
  }
}

// No-slip correction: the interpolant vanishes on the walls only up to its
// O(h^3) error. Within a band of 1.5 cells from the nearest wall, subtract its
// value at the wall point p_w = p - phi n, weighted by the smoothstep
// w(s) = 1 - 3 s^2 + 2 s^3, s = phi / band: exact zero on the wall, the wall
// shear (w'(0) = 0) and the field beyond the band (C1 at s = 1) unchanged.
// Exponentially fitted wall layer: the grid does not resolve the layer, so
// within layer_band() of a wall the velocity is rebuilt from the layer's
// analytic structure (Brinkman boundary layer of thickness 1/k, k = sqrt(12)/H):
// the outer (slip) field is taken from the interpolant at two points on the
// wall normal, at distances r = layer_band() and r + h_cell where the cubic
// interpolant is accurate, divided by the layer shape there, and extrapolated linearly in the wall
// distance phi; then
//     u_t = (1 - exp(-k phi)) u~_t(phi),
//     u_n = u~_n(phi) + (du~_n/dphi) exp(-k phi) / k,
// the second from continuity across the layer (u_n = 0 on the wall). Returns
// false where the two points do not see the same wall (corners), and the
// plain interpolant is used there.
bool GridBrinkmanFlow::layer_velocity(double x, double y, double phi,
                                      Eigen::Vector2d* u) const {
  const double h = geometry_.gap_height();
  const double k = std::sqrt(12.0) / h;
  const double cell = std::max(cell_size_x(), cell_size_y());
  const double r = layer_band();
  const Eigen::Vector2d n = geometry_.wall_normal(x, y);
  const Eigen::Vector2d t(-n.y(), n.x());
  const Eigen::Vector2d p(x, y);
  const Eigen::Vector2d p2 = p + (r - phi) * n, p3 = p + (r + cell - phi) * n;
  auto usable = [&](const Eigen::Vector2d& q, double distance) {
    return q.x() > geometry_.x_lo() + cell && q.x() < geometry_.x_hi() - cell &&
           std::abs(geometry_.signed_distance(q.x(), q.y()) - distance) < 0.05 * cell;
  };
  if (!usable(p2, r) || !usable(p3, r + cell)) return false;
  auto field_at = [&](const Eigen::Vector2d& q) {
    const double qx = std::clamp(q.x(), geometry_.x_lo(), geometry_.x_hi());
    return field_.velocity((qx - geometry_.x_lo()) / h, (q.y() - geometry_.y_lo()) / h);
  };
  const Eigen::Vector2d u2 = field_at(p2), u3 = field_at(p3);
  const double s2 = -std::expm1(-k * r), s3 = -std::expm1(-k * (r + cell));
  const double t2 = u2.dot(t) / s2, t3 = u3.dot(t) / s3;  // outer tangential
  const double n2 = u2.dot(n), n3 = u3.dot(n);            // outer normal (layer part < e^-5)
  const double w = (phi - r) / cell;
  const double ut = -std::expm1(-k * phi) * (t2 + w * (t3 - t2));
  const double slope = (n3 - n2) / cell;
  const double un = n2 + w * (n3 - n2) + slope * std::exp(-k * phi) / k;
  *u = ut * t + un * n;
  return true;
}

// Three cells: there the cubic interpolant no longer sees the layer's kink
// (relative layer amplitude exp(-3 k h) < 0.2 for k h >= 0.5). Grids with
// k h < 0.5 resolve the layer and need no reconstruction.
double GridBrinkmanFlow::layer_band() const {
  if (!exponential_wall_layer_) return 0.0;
  const double k = std::sqrt(12.0) / geometry_.gap_height();
  const double cell = std::max(cell_size_x(), cell_size_y());
  return k * cell < 0.5 ? 0.0 : 3.0 * cell;
}

Eigen::Vector2d GridBrinkmanFlow::velocity(double x, double y) const {
  x = std::clamp(x, geometry_.x_lo(), geometry_.x_hi());
  const double phi = geometry_.signed_distance(x, y);
  if (phi <= 0.0) return Eigen::Vector2d::Zero();
  if (phi < layer_band()) {
    Eigen::Vector2d u;
    if (layer_velocity(x, y, phi, &u)) return mean_velocity_ * u;
  }
  const double h = geometry_.gap_height();
  auto field_at = [&](double px, double py) {
    return field_.velocity((px - geometry_.x_lo()) / h, (py - geometry_.y_lo()) / h);
  };
  Eigen::Vector2d u = field_at(x, y);
  const double band = wall_band();
  if (phi < band) {
    const WallBandBlend b = wall_band_blend(x, y, phi);
    u -= b.weight * field_at(b.foot.x(), b.foot.y());
  }
  return mean_velocity_ * u;
}

GridBrinkmanFlow::WallBandBlend GridBrinkmanFlow::wall_band_blend(double x, double y, double phi) const {
  const double band = wall_band();
  WallBandBlend b;
  b.normal = geometry_.wall_normal(x, y);
  b.foot = Eigen::Vector2d(x, y) - phi * b.normal;
  const double s = phi / band;
  b.weight = 1.0 - s * s * (3.0 - 2.0 * s);
  b.weight_slope = -6.0 * s * (1.0 - s) / band;
  return b;
}

// Gradient of velocity(); inside the no-slip band the curvature of the wall
// (a term phi / R relative) is neglected in the derivative of the correction.
Eigen::Matrix2d GridBrinkmanFlow::velocity_gradient(double x, double y) const {
  x = std::clamp(x, geometry_.x_lo(), geometry_.x_hi());
  const double phi = geometry_.signed_distance(x, y);
  if (phi <= 0.0) return Eigen::Matrix2d::Zero();
  if (phi < layer_band()) {
    // Central differences of the layer reconstruction (step 1e-4 of the
    // layer thickness, kept inside the fluid).
    const double step = std::min(1e-4 * geometry_.gap_height() / std::sqrt(12.0), 0.5 * phi);
    Eigen::Matrix2d g;
    for (int b = 0; b < 2; ++b) {
      const Eigen::Vector2d e = b == 0 ? Eigen::Vector2d(step, 0) : Eigen::Vector2d(0, step);
      g.col(b) = (velocity(x + e.x(), y + e.y()) - velocity(x - e.x(), y - e.y())) / (2 * step);
    }
    return g;
  }
  const double h = geometry_.gap_height();
  auto grad_at = [&](double px, double py) {
    return field_.velocity_gradient((px - geometry_.x_lo()) / h, (py - geometry_.y_lo()) / h);
  };
  Eigen::Matrix2d g = grad_at(x, y);
  const double band = wall_band();
  if (phi < band) {
    const WallBandBlend b = wall_band_blend(x, y, phi);
    const Eigen::Vector2d &n = b.normal, &pw = b.foot;
    const double w = b.weight, dw_dphi = b.weight_slope;
    const Eigen::Vector2d uw = field_.velocity((pw.x() - geometry_.x_lo()) / h, (pw.y() - geometry_.y_lo()) / h);
    const Eigen::Matrix2d tangential = Eigen::Matrix2d::Identity() - n * n.transpose();
    g -= w * grad_at(pw.x(), pw.y()) * tangential + uw * (dw_dphi * h) * n.transpose();
  }
  return (mean_velocity_ / h) * g;
}

// velocity() and velocity_gradient() in one: the wall distance, the wall
// normal and the stencils at the point (and at its wall foot in the wall
// band) are found once; the arithmetic is theirs, so the values are equal
// to the last bit.
void GridBrinkmanFlow::velocity_and_gradient(double x, double y, Eigen::Vector2d& u, Eigen::Matrix2d& g) const {
  x = std::clamp(x, geometry_.x_lo(), geometry_.x_hi());
  const double phi = geometry_.signed_distance(x, y);
  if (phi <= 0.0) {
    u.setZero();
    g.setZero();
    return;
  }
  if (phi < layer_band()) {  // the layer reconstruction (rare: within ~H/10 of a wall)
    u = velocity(x, y);
    g = velocity_gradient(x, y);
    return;
  }
  const double h = geometry_.gap_height();
  field_.velocity_and_gradient((x - geometry_.x_lo()) / h, (y - geometry_.y_lo()) / h, u, g);
  const double band = wall_band();
  if (phi < band) {
    const WallBandBlend b = wall_band_blend(x, y, phi);
    const Eigen::Vector2d &n = b.normal, &pw = b.foot;
    const double w = b.weight, dw_dphi = b.weight_slope;
    Eigen::Vector2d uw;
    Eigen::Matrix2d gw;
    field_.velocity_and_gradient((pw.x() - geometry_.x_lo()) / h, (pw.y() - geometry_.y_lo()) / h, uw, gw);
    u -= w * uw;
    const Eigen::Matrix2d tangential = Eigen::Matrix2d::Identity() - n * n.transpose();
    g -= w * gw * tangential + uw * (dw_dphi * h) * n.transpose();
  }
  u = mean_velocity_ * u;
  g = (mean_velocity_ / h) * g;
}

double GridBrinkmanFlow::pressure(double x, double y) const {
  const double h = geometry_.gap_height();
  return viscosity_ * mean_velocity_ / h *
         field_.pressure((x - geometry_.x_lo()) / h, (y - geometry_.y_lo()) / h);
}

std::string GridBrinkmanFlow::description() const {
  std::ostringstream s;
  s << "grid Brinkman solver (MAC, Shortley-Weller walls, cut-face fluxes): " << field_.grid().nx << " x "
    << field_.grid().ny << " cells of " << cell_size_x() << " x " << cell_size_y() << " m, "
    << (inertia_reynolds_ > 0.0 ? "with" : "without") << " gap-averaged inertia, "
    << (exponential_wall_layer_ ? "exponentially fitted wall layer, " : "");
  if (loaded_from_cache_)
    s << "loaded from cache " << cache_file_;
  else
    s << "solved in " << solve_seconds_ << " s (" << unknowns_ << " unknowns)"
      << (cache_file_.empty() ? ", not cached"
                              : (cache_error_.empty() ? ", cached in " + cache_file_
                                                      : ", not cached: " + cache_error_));
  if (!cache_notice_.empty()) s << "; " << cache_notice_;
  return s.str();
}

long GridBrinkmanFlow::instances_created() { return g_instances.load(); }
long GridBrinkmanFlow::total_solves() { return g_solves.load(); }

}  // namespace hsrod

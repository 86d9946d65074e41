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
  const double h = grid_cell_size(geo, o);
  const double nx = std::ceil(geo.length() / h - 1e-9), ny = std::ceil(geo.width() / h - 1e-9);
  if (nx * ny > static_cast<double>(o.max_cells)) {
    std::ostringstream msg;
    msg << "GridBrinkmanFlow: grid of " << nx << " x " << ny << " cells (cell size " << h
        << " m) exceeds max_cells = " << o.max_cells
        << "; choose a larger cell_size or fewer cells_per_wall_layer / cells_across_opening";
    throw std::invalid_argument(msg.str());
  }
  MacGrid g;
  g.nx = std::max(2, static_cast<int>(nx));
  g.ny = std::max(4, static_cast<int>(ny));
  g.hx = geo.length() / g.nx / geo.gap_height();
  g.hy = geo.width() / g.ny / geo.gap_height();
  return g;
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
  const MacGrid grid = make_mac_grid(geometry, options);
  const std::string key = brinkman_cache_key(scaled, grid, inertia_reynolds_);

  if (options.use_cache) {
    const std::filesystem::path dir =
        options.cache_dir.empty() ? default_cache_directory() : std::filesystem::path(options.cache_dir);
    if (!dir.empty()) cache_file_ = (dir / brinkman_cache_file_name(key)).string();
  }
  if (!cache_file_.empty()) {
    if (std::optional<StaggeredField> cached = load_cached_field(cache_file_, key)) {
      field_ = std::move(*cached);
      loaded_from_cache_ = true;
      return;
    }
  }

  const auto start = std::chrono::steady_clock::now();
  BrinkmanGridSettings settings;
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
  if (!cache_file_.empty()) store_cached_field(cache_file_, key, field_, &cache_error_);
}

// No-slip correction: the interpolant vanishes on the walls only up to its
// O(h^3) error. Within a band of 1.5 cells from the nearest wall, subtract its
// value at the wall point p_w = p - phi n, weighted by the smoothstep
// w(s) = 1 - 3 s^2 + 2 s^3, s = phi / band: exact zero on the wall, the wall
// shear (w'(0) = 0) and the field beyond the band (C1 at s = 1) unchanged.
Eigen::Vector2d GridBrinkmanFlow::velocity(double x, double y) const {
  x = std::clamp(x, geometry_.x_lo(), geometry_.x_hi());
  const double phi = geometry_.signed_distance(x, y);
  if (phi <= 0.0) return Eigen::Vector2d::Zero();
  const double h = geometry_.gap_height();
  auto field_at = [&](double px, double py) {
    return field_.velocity((px - geometry_.x_lo()) / h, (py - geometry_.y_lo()) / h);
  };
  Eigen::Vector2d u = field_at(x, y);
  const double band = wall_band();
  if (phi < band) {
    const Eigen::Vector2d pw = Eigen::Vector2d(x, y) - phi * geometry_.wall_normal(x, y);
    const double s = phi / band;
    u -= (1.0 - s * s * (3.0 - 2.0 * s)) * field_at(pw.x(), pw.y());
  }
  return mean_velocity_ * u;
}

// Gradient of velocity(); inside the no-slip band the curvature of the wall
// (a term phi / R relative) is neglected in the derivative of the correction.
Eigen::Matrix2d GridBrinkmanFlow::velocity_gradient(double x, double y) const {
  x = std::clamp(x, geometry_.x_lo(), geometry_.x_hi());
  const double phi = geometry_.signed_distance(x, y);
  if (phi <= 0.0) return Eigen::Matrix2d::Zero();
  const double h = geometry_.gap_height();
  auto grad_at = [&](double px, double py) {
    return field_.velocity_gradient((px - geometry_.x_lo()) / h, (py - geometry_.y_lo()) / h);
  };
  Eigen::Matrix2d g = grad_at(x, y);
  const double band = wall_band();
  if (phi < band) {
    const Eigen::Vector2d n = geometry_.wall_normal(x, y);
    const Eigen::Vector2d pw = Eigen::Vector2d(x, y) - phi * n;
    const double s = phi / band;
    const double w = 1.0 - s * s * (3.0 - 2.0 * s), dw_dphi = -6.0 * s * (1.0 - s) / band;
    const Eigen::Vector2d uw = field_.velocity((pw.x() - geometry_.x_lo()) / h, (pw.y() - geometry_.y_lo()) / h);
    const Eigen::Matrix2d tangential = Eigen::Matrix2d::Identity() - n * n.transpose();
    g -= w * grad_at(pw.x(), pw.y()) * tangential + (uw / h) * (dw_dphi * h) * n.transpose();
  }
  return (mean_velocity_ / h) * g;
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
    << (inertia_reynolds_ > 0.0 ? "with" : "without") << " gap-averaged inertia, ";
  if (loaded_from_cache_)
    s << "loaded from cache " << cache_file_;
  else
    s << "solved in " << solve_seconds_ << " s (" << unknowns_ << " unknowns)"
      << (cache_file_.empty() ? ", not cached"
                              : (cache_error_.empty() ? ", cached in " + cache_file_
                                                      : ", not cached: " + cache_error_));
  return s.str();
}

long GridBrinkmanFlow::instances_created() { return g_instances.load(); }
long GridBrinkmanFlow::total_solves() { return g_solves.load(); }

}  // namespace hsrod

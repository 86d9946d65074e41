// Background flow of an arbitrary planform from the grid solver
// (brinkman_grid_solver.h), solved once per scene and cached on disk
// (flow_cache.h); queries interpolate the stored field (staggered_field.h).
#pragma once

#include "flow/background_flow.h"
#include "flow/brinkman_grid_solver.h"
#include "flow/fluid_properties.h"
#include "flow/grid_solve_budget.h"
#include "flow/inflow.h"
#include "flow/staggered_field.h"

#include <algorithm>
#include <string>

namespace hsrod {

struct GridBrinkmanOptions {
  // Cell size [m]; 0 picks it from the two resolution targets below.
  double cell_size = 0.0;
  // Cells per Brinkman wall-layer length H / sqrt(12) (automatic size).
  int cells_per_wall_layer = 3;
  // Cells across the narrowest opening, e.g. the pore (automatic size).
  int cells_across_opening = 16;
  // Largest accepted grid [cells]; larger requests throw std::invalid_argument.
  long max_cells = 4'000'000;
  // Limits on the predicted peak memory [bytes] and wall time [s] of a grid
  // solve (grid_solve_budget.h), checked before anything is allocated; a
  // larger request throws GridSolveTooLarge with the figures.
  double max_memory_bytes = 2.0e9;
  double max_predicted_seconds = 120.0;
  // How the Brinkman wall layer H/sqrt(12) is treated:
  //  kResolved:    the grid resolves it (cells_per_wall_layer cells per layer);
  //  kExponential: exponentially fitted stencils (brinkman_grid_solver.h), exact
  //                for the layer profile, so the grid only needs
  //                cells_across_opening cells across the narrowest opening;
  //  kAuto:        kResolved, unless an automatic grid that resolves the layer
  //                would take longer than resolved_layer_max_seconds
  //                (predicted): then kExponential (thin gaps). An explicit
  //                cell_size keeps kResolved.
  enum class WallLayer { kAuto, kResolved, kExponential };
  WallLayer wall_layer = WallLayer::kAuto;
  double resolved_layer_max_seconds = 10.0;
  // Cancellation and progress hooks of the solve (brinkman_grid_solver.h).
  SolveControl control;
  // Gap-averaged inertia (6/5) rho (u.grad)u, by Picard iterations.
  bool include_inertia = false;
  int max_picard_iterations = 50;
  double picard_tolerance = 1e-9;  // on max |du| / U between iterations [-]
  // Cache: read and write solved fields in cache_dir ("" = default_cache_directory(),
  // i.e. $HSROD_CACHE_DIR, $XDG_CACHE_HOME/hsrod or ~/.cache/hsrod).
  bool use_cache = true;
  std::string cache_dir;
  // Largest total size of the cache directory's files [bytes]; the least
  // recently used are removed after a store. < 0: cache_size_limit_bytes()
  // ($HSROD_CACHE_MAX_MB, else 2000 MB).
  double cache_size_limit = -1.0;
};

// Cell size [m] the options give for `geometry`:
// min(H / (sqrt(12) cells_per_wall_layer), narrowest_opening / cells_across_opening)
// unless cell_size is set.
double grid_cell_size(const ChannelGeometry& geometry, const GridBrinkmanOptions& options);
// The MAC grid (in units of H) covering the planform with cells no larger than
// grid_cell_size: nx = ceil(L / h), ny = ceil(W / h).
MacGrid make_mac_grid(const ChannelGeometry& geometry, const GridBrinkmanOptions& options);
// The planform in units of H with its lower corner at the origin.
ChannelGeometry scaled_planform(const ChannelGeometry& geometry);

// The grid a GridBrinkmanFlow solves on, how it treats the wall layer, and
// the predicted cost of the solve; decided from the options alone (nothing
// of grid size is allocated). Throws std::invalid_argument for bad options
// or a grid over max_cells.
struct GridChoice {
  MacGrid grid;
  bool exponential_wall_layer = false;
  GridSolveEstimate estimate;
};
GridChoice choose_grid(const ChannelGeometry& geometry, const GridBrinkmanOptions& options);

class GridBrinkmanFlow final : public BackgroundFlow {
 public:
  // Loads the field from the cache or solves (and stores) it. Throws
  // std::invalid_argument for bad fluid/options, GridSolveTooLarge (an
  // invalid_argument) when the predicted solve exceeds the limits,
  // FlowSolveCancelled when options.control cancels it, std::runtime_error
  // if the solve fails.
  GridBrinkmanFlow(const ChannelGeometry& geometry, const FluidProperties& fluid,
                   const Inflow& inflow, const GridBrinkmanOptions& options = {});

  Eigen::Vector2d velocity(double x, double y) const override;
  Eigen::Matrix2d velocity_gradient(double x, double y) const override;
  void velocity_and_gradient(double x, double y, Eigen::Vector2d& u, Eigen::Matrix2d& g) const override;
  double pressure(double x, double y) const override;
  double mean_velocity() const override { return mean_velocity_; }
  const ChannelGeometry& geometry() const override { return geometry_; }
  std::string description() const override;

  bool loaded_from_cache() const { return loaded_from_cache_; }
  // Grid solves done by this object: 0 (loaded from the cache) or 1.
  int solves_performed() const { return solves_performed_; }
  const std::string& cache_file() const { return cache_file_; }    // "" without cache
  const std::string& cache_error() const { return cache_error_; }  // "" if stored fine
  // "" or what happened to the cache: a file not used (damaged, another
  // format or scene) and solved anew; old files removed to stay under the limit.
  const std::string& cache_notice() const { return cache_notice_; }
  int picard_iterations() const { return picard_iterations_; }
  bool exponential_wall_layer() const { return exponential_wall_layer_; }
  const StaggeredField& field() const { return field_; }
  double cell_size_x() const { return field_.grid().hx * geometry_.gap_height(); }  // m
  double cell_size_y() const { return field_.grid().hy * geometry_.gap_height(); }  // m
  // Width [m] of the band along the walls where velocity() enforces exact
  // no-slip (1.5 cells; see grid_brinkman_flow.cpp).
  double wall_band() const { return 1.5 * std::max(cell_size_x(), cell_size_y()); }

  // Process-wide counters (thread-safe): grid flows constructed and grid
  // solves performed. Used by tests to show what was skipped.
  static long instances_created();
  static long total_solves();

 private:
  // Exact no-slip in the wall band: the point's wall foot pw (and normal n)
  // and the smoothstep weight w(phi) of the wall's velocity subtracted there,
  // with its derivative (see grid_brinkman_flow.cpp).
  struct WallBandBlend {
    Eigen::Vector2d normal, foot;  // unit wall normal; wall foot [m]
    double weight = 0.0, weight_slope = 0.0;  // w; dw/dphi [1/m]
  };
  WallBandBlend wall_band_blend(double x, double y, double phi) const;
  // Wall-layer reconstruction of the exponentially fitted scheme (see .cpp).
  bool layer_velocity(double x, double y, double phi, Eigen::Vector2d* u) const;
  // Distance [m] from the walls within which layer_velocity is used (0 when
  // the grid resolves the layer).
  double layer_band() const;

  ChannelGeometry geometry_;
  double mean_velocity_;      // U [m/s]
  double viscosity_;          // mu [Pa s]
  double inertia_reynolds_;   // Re_H = rho U H / mu used in the solve (0: none)
  StaggeredField field_;
  bool loaded_from_cache_ = false;
  int solves_performed_ = 0;
  std::string cache_file_, cache_error_, cache_notice_;
  double solve_seconds_ = 0.0;
  int picard_iterations_ = 0;
  int unknowns_ = 0;
  bool exponential_wall_layer_ = false;
};

}  // namespace hsrod

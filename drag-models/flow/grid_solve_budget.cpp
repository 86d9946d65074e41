#include "flow/grid_solve_budget.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hsrod {
namespace {

// Cost model, fitted to solves of the pore scene's planform (Eigen 3.4
// SparseLU/COLAMD, one core; flow/README.md, "Bounded work"):
//   memory  M = kBaseBytes + kBytesPerUnknown n (n / kReferenceUnknowns)^kFillExponent
//   time    T = kReferenceSeconds (n / kReferenceUnknowns)^kTimeExponent
// (fill-in of the COLAMD-ordered LU grows faster than n log n on these grids).
// Time is for an idle core (the measured 1.9 s of the default pore grid);
// inertia adds Picard iterations (measured 3.3 s against 1.9 s).
constexpr double kBaseBytes = 30e6;
constexpr double kBytesPerUnknown = 3.5e3;
constexpr double kReferenceUnknowns = 172932;
constexpr double kFillExponent = 0.4;
constexpr double kReferenceSeconds = 6.4;  // 172 932 unknowns, idle core
constexpr double kTimeExponent = 1.6;
constexpr double kInertiaTimeFactor = 1.7;

}  // namespace

std::string GridSolveEstimate::summary() const {
  std::ostringstream s;
  s.precision(3);
  s << nx << " x " << ny << " cells (" << fluid_cells << " in the fluid), " << unknowns
    << " unknowns, predicted " << memory_bytes / 1e9 << " GB and " << seconds << " s";
  return s.str();
}

GridSolveEstimate estimate_grid_solve(const ChannelGeometry& geo, const MacGrid& grid,
                                      bool inertia) {
  GridSolveEstimate e;
  e.nx = grid.nx;
  e.ny = grid.ny;
  e.cells = static_cast<long>(grid.nx) * grid.ny;
  // Fluid area from the open width of each cell column (cheap: nx calls).
  double open = 0.0;
  for (int i = 0; i < grid.nx; ++i)
    open += geo.open_width(geo.x_lo() + (i + 0.5) / grid.nx * geo.length()) / geo.width();
  const double fraction = std::clamp(open / grid.nx, 0.0, 1.0);
  e.fluid_cells = static_cast<long>(std::ceil(fraction * static_cast<double>(e.cells)));
  e.unknowns = 3 * e.fluid_cells;
  const double n = std::max(1.0, static_cast<double>(e.unknowns));
  const double ratio = n / kReferenceUnknowns;
  e.memory_bytes = kBaseBytes + kBytesPerUnknown * n * std::pow(ratio, kFillExponent);
  e.seconds = kReferenceSeconds * std::pow(ratio, kTimeExponent) *
              (inertia ? kInertiaTimeFactor : 1.0);
  return e;
}

void check_grid_solve_budget(const GridSolveEstimate& e, const GridSolveLimits& limits) {
  auto refuse = [&](const std::string& what) {
    throw GridSolveTooLarge("background-flow grid solve refused before it started: " +
                            e.summary() + "; " + what);
  };
  std::ostringstream s;
  s.precision(3);
  if (e.cells > limits.max_cells) {
    s << "exceeds max_cells = " << limits.max_cells;
    refuse(s.str());
  }
  if (e.memory_bytes > limits.max_memory_bytes) {
    s << "predicted memory exceeds the limit of " << limits.max_memory_bytes / 1e9
      << " GB";
    refuse(s.str());
  }
  if (e.seconds > limits.max_seconds) {
    s << "predicted time exceeds the limit of " << limits.max_seconds
      << " s";
    refuse(s.str());
  }
}

}  // namespace hsrod

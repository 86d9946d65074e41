// Bounded work for the background-flow grid solve: the cost of a
// solve is predicted from the grid alone, before anything is allocated, and
// checked against limits the caller can raise.
//
// The sparse LU of the MAC saddle-point system (brinkman_grid_solver.cpp)
// dominates time and memory. Its cost model (measured on this project's
// 2-core machines with Eigen 3.4 SparseLU/COLAMD; the fit and the figures
// are in flow/README.md, "Bounded work"):
//     unknowns  n = 3 x fluid cells (u, v, p per cell)
//     memory    M = n (a + b log2 n) bytes
//     time      T = c n^1.5 s (nested-dissection-like fill of a 2-D grid)
// The prediction is meant to be within a factor of ~2: enough to refuse a
// 10 GB / 13 min request before it starts, not a benchmark.
#pragma once

#include "flow/mac_grid.h"

#include <stdexcept>
#include <string>

namespace hsrod {

struct GridSolveEstimate {
  long cells = 0;          // nx * ny [-]
  long fluid_cells = 0;    // cells in the fluid (planform area / cell area) [-]
  long unknowns = 0;       // velocity and pressure unknowns [-]
  double memory_bytes = 0.0;  // predicted peak memory of the solve [bytes]
  double seconds = 0.0;       // predicted wall time on one core [s]
  std::string summary() const;  // "nx x ny cells, n unknowns, ~M GB, ~T s"
  int nx = 0, ny = 0;
};

struct GridSolveLimits {
  long max_cells = 4'000'000;         // [-]
  double max_memory_bytes = 2.0e9;    // [bytes]
  double max_seconds = 120.0;         // predicted wall time [s]
};

// Thrown by check_grid_solve_budget: the figures and which limit to raise.
class GridSolveTooLarge : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Predicted cost of solving on `grid` over `geometry` (the planform in any
// length unit; only area ratios are used). Allocates nothing of grid size.
GridSolveEstimate estimate_grid_solve(const ChannelGeometry& geometry, const MacGrid& grid,
                                      bool inertia);

// Throws GridSolveTooLarge naming the exceeded limit and the prediction
// (the caller knows which of its settings raises the limit).
void check_grid_solve_budget(const GridSolveEstimate& estimate, const GridSolveLimits& limits);

}  // namespace hsrod

// Finite-difference solver of the depth-averaged Brinkman equations on a MAC
// grid, in units of the gap height H (lengths), the mean inlet velocity U
// (velocities) and mu U / H (pressure):
//     -lap(u) + 12 u + grad p + (6/5) Re_H (u.grad)u = 0,   div u = 0,
// Re_H = rho U H / mu (the inertia term only when requested).
//
// Discretisation (see flow/README.md for the measured orders):
//  - staggered MAC grid (Harlow & Welch 1965, mac_grid.h): exact discrete
//    mass conservation, no spurious pressure modes;
//  - no-slip in the momentum equations through the Shortley-Weller stencil
//    (Shortley & Weller 1938; Gibou et al., J. Comput. Phys. 176, 2002): the
//    second difference along each grid line uses the exact distance from the
//    node to the wall where the line crosses one, so walls sit at their true
//    position, not on a staircase;
//  - cut faces in the continuity equation: the flux through a face the wall
//    cuts (or the sliver of a neighbouring face whose centre lies in the wall)
//    is integrated with the linear no-slip profile along the face
//    (Stencils::face_flux), which removes the first-order staircase error of
//    closed cut faces;
//  - second order where walls follow grid lines (side walls: measured order
//    1.9); near the cylinders second order away from the wall layer and about
//    1.5 in L2 including it (self-convergence, see README.md);
//  - inlet: the developed profile of the same discrete operator, scaled to
//    the exact flow rate (a straight channel is then exactly x-independent);
//    outlet: p = 0 and d(u, v)/dx = 0;
//  - one sparse direct solve of the saddle-point system (Eigen SparseLU,
//    COLAMD ordering); inertia by Picard (Oseen) iterations, each solved by
//    BiCGSTAB preconditioned with that LU.
#pragma once

#include "flow/mac_grid.h"

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace hsrod {

// Thrown when SolveControl::cancel_requested returned true during a solve.
class FlowSolveCancelled : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Hooks of a long grid solve, set by the caller (e.g. the LIGGGHTS glue,
// whose signal handler sets a flag the callback reads). drag-models itself
// installs no signal handler.
struct SolveControl {
  // Polled between the solve's phases and every 20 ms during the sparse
  // factorisation; returning true ends the solve with FlowSolveCancelled.
  std::function<bool()> cancel_requested;
  // Called with one line at each phase (factorisation, Picard iterations).
  std::function<void(const std::string&)> progress;
};

struct BrinkmanGridSolution {
  MacGrid grid;
  MacMasks masks;
  std::vector<double> u;         // per u node [U]; 0 at walls, profile at the inlet
  std::vector<double> v;         // per v node [U]
  std::vector<double> pressure;  // per cell [mu U / H]; NaN where the cell has none
  int picard_iterations = 0;     // 0 without inertia
  double picard_change = 0.0;    // last max |u^{k+1} - u^k| [U]
  int unknowns = 0;
};

struct BrinkmanGridSettings {
  double inertia_reynolds = 0.0;  // Re_H = rho U H / mu; 0 = no inertia term
  int max_picard_iterations = 50;
  double picard_tolerance = 1e-9;  // on max |u^{k+1} - u^k| [U]
  // Exponentially fitted wall layer (line_stencils.h): the second differences
  // and cut-face fluxes are exact for the Brinkman wall layer
  // u = U (1 - exp(-sqrt(12) n / H)), so the grid need not resolve the layer
  // H / sqrt(12) (thin gaps). Off: the plain Shortley-Weller scheme.
  bool exponential_wall_layer = false;
  SolveControl control;
};

// Solves on `grid` over `scaled_geometry` (planform in units of H, lower corner
// at the origin). Throws std::runtime_error if the factorisation fails or the
// Picard iterations do not converge, FlowSolveCancelled when cancelled.
BrinkmanGridSolution solve_brinkman_on_grid(const ChannelGeometry& scaled_geometry,
                                            const MacGrid& grid,
                                            const BrinkmanGridSettings& settings);

}  // namespace hsrod

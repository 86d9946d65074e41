// Extension of a solved MAC velocity component into the walls and beyond the
// inlet/outlet, so that a 4 x 4 interpolation stencil is available at every
// fluid point (staggered_field.h).
//
// Ghost nodes (inside walls or obstacles, or outside the side walls) within
// two nodes of the fluid along a grid line get the value of the polynomial
// that vanishes at the wall crossing of that line (no-slip) and passes
// through the fluid nodes on the line (Gibou et al., J. Comput. Phys. 176,
// 2002, ghost-fluid extrapolation): quadratic through the two nearest fluid
// nodes, or through the 2nd and 3rd when the nearest is closer than half a
// cell to the wall (keeps the extrapolation well conditioned), linear when
// only one fluid node exists. Several lines are averaged with weights
// 1/(0.1 + distance beyond the wall in cells)^2. Nodes no line reaches stay
// NaN (the interpolation counts them as 0, the wall's velocity).
#pragma once

#include "flow/brinkman_grid_solver.h"

#include <vector>

namespace hsrod {

// Node lattice of one extended component: node (i, j) for i in [i_min, i_max],
// j in [j_min, j_max], stored at (i - i_min) * ny_ext + (j - j_min).
struct ExtendedLattice {
  int i_min = 0, i_max = 0, j_min = 0, j_max = 0;
  double x0 = 0.0, y0 = 0.0;  // position of node (0, 0) [H]
  double hx = 0.0, hy = 0.0;  // spacing [H]
  int nx_ext() const { return i_max - i_min + 1; }
  int ny_ext() const { return j_max - j_min + 1; }
  int index(int i, int j) const { return (i - i_min) * ny_ext() + (j - j_min); }
  int size() const { return nx_ext() * ny_ext(); }
};

// Lattices of the extended u (i in [-2, nx+2], j in [-2, ny+1]) and v
// (i in [-2, nx+1], j in [-2, ny+2]) components of `grid`.
ExtendedLattice extended_u_lattice(const MacGrid& grid);
ExtendedLattice extended_v_lattice(const MacGrid& grid);

// Extended arrays of the solution's u and v: fluid and inlet nodes keep their
// values, wall nodes get ghost values, the columns beyond the inlet and outlet
// mirror the field (even for u and at the outlet, odd for v at the inlet where
// v = 0).
std::vector<double> extend_u(const BrinkmanGridSolution& solution, const ChannelGeometry& scaled_geometry);
std::vector<double> extend_v(const BrinkmanGridSolution& solution, const ChannelGeometry& scaled_geometry);

}  // namespace hsrod

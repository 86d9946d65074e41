// A solved MAC velocity/pressure field extended by one ring of ghost nodes,
// with interpolation at arbitrary planform points (units of the grid solver:
// lengths in H from the lower corner, velocities in U, pressure in mu U / H).
//
// Interpolation: bilinear on each staggered component (u on its x-face grid,
// v on its y-face grid), so the field is continuous and second-order accurate
// away from walls. Nodes inside walls or obstacles next to the fluid carry
// ghost values: the linear extrapolation, along the grid line, of the fluid
// neighbour through the wall point where the velocity is zero (weighted by
// the wall fraction when several lines give one). The interpolant therefore
// vanishes on grid-aligned walls exactly and on curved walls to O(h^2).
// The velocity gradient is the exact derivative of the bilinear interpolant
// (piecewise linear, first order, continuous along the cell edges it is
// aligned with).
#pragma once

#include "flow/brinkman_grid_solver.h"

#include <Eigen/Core>

#include <vector>

namespace hsrod {

class StaggeredField {
 public:
  StaggeredField() = default;
  // Builds the ghost-extended arrays from a solution on `scaled_geometry`.
  StaggeredField(const BrinkmanGridSolution& solution, const ChannelGeometry& scaled_geometry);
  // From stored arrays (cache); sizes must match the grid.
  StaggeredField(const MacGrid& grid, std::vector<double> u_ext, std::vector<double> v_ext,
                 std::vector<double> p_ext);

  const MacGrid& grid() const { return grid_; }
  // Velocity [U] at (x, y) [H] (no fluid test, x clamped to [0, L]).
  Eigen::Vector2d velocity(double x, double y) const;
  // d u_a / d x_b [U/H] of the interpolant.
  Eigen::Matrix2d velocity_gradient(double x, double y) const;
  // Pressure [mu U / H] (bilinear on cell centres with a linear ghost column
  // beyond the outlet so that p = 0 on x = L).
  double pressure(double x, double y) const;

  // Extended arrays: u_ext (nx+1) x (ny+2), row jj = j + 1; v_ext (nx+2) x
  // (ny+1), column ii = i + 1; p_ext (nx+2) x ny, column ii = i + 1.
  const std::vector<double>& u_ext() const { return u_ext_; }
  const std::vector<double>& v_ext() const { return v_ext_; }
  const std::vector<double>& p_ext() const { return p_ext_; }

 private:
  double u_at(int i, int jj) const { return u_ext_[i * (grid_.ny + 2) + jj]; }
  double v_at(int ii, int j) const { return v_ext_[ii * (grid_.ny + 1) + j]; }
  double p_at(int ii, int j) const { return p_ext_[ii * grid_.ny + j]; }

  MacGrid grid_;
  std::vector<double> u_ext_, v_ext_, p_ext_;
};

}  // namespace hsrod

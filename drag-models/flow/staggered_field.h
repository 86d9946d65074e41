// A solved MAC velocity/pressure field, extended into the walls
// (ghost_extension.h), with interpolation at arbitrary planform points. Units
// of the grid solver: lengths in H from the lower corner of the planform,
// velocities in U, pressure in mu U / H.
//
// Velocity: tensor-product Catmull-Rom (cubic convolution, Keys 1981) on each
// staggered component, over a 4 x 4 node stencil that includes ghost nodes.
// It reproduces quadratics, so the interpolation error is O(h^3) and the
// field is C1 (continuous velocity gradient, the exact derivative of the
// interpolant). A node that no ghost line reaches (deep in a wall, e.g. the
// diagonal of a curved wall's stencil) counts as 0, so one interpolant
// holds everywhere and the field stays continuous from cell to cell.
// No-slip: the ghost values make the interpolant vanish on walls to O(h^3).
// Pressure: bilinear on cell centres (a diagnostic).
#pragma once

#include "flow/brinkman_grid_solver.h"
#include "flow/ghost_extension.h"

#include <Eigen/Core>

#include <vector>

namespace hsrod {

class StaggeredField {
 public:
  StaggeredField() = default;
  // Builds the extended arrays from a solution on `scaled_geometry`.
  StaggeredField(const BrinkmanGridSolution& solution, const ChannelGeometry& scaled_geometry);
  // From stored arrays (cache); sizes must match the grid.
  StaggeredField(const MacGrid& grid, std::vector<double> u_ext, std::vector<double> v_ext,
                 std::vector<double> p_ext);

  const MacGrid& grid() const { return grid_; }
  // Velocity [U] at (x, y) [H] (no fluid test; x clamped to [0, L]).
  Eigen::Vector2d velocity(double x, double y) const;
  // d u_a / d x_b [U/H] of the interpolant.
  Eigen::Matrix2d velocity_gradient(double x, double y) const;
  // Both from one pass over the stencils (the same values as the two above).
  void velocity_and_gradient(double x, double y, Eigen::Vector2d& u, Eigen::Matrix2d& g) const;
  // Pressure [mu U / H], bilinear on cell centres (linear ghost column beyond
  // the outlet so that p = 0 on x = L).
  double pressure(double x, double y) const;

  // Extended arrays: u and v on extended_u_lattice / extended_v_lattice
  // (NaN where no ghost value exists); p_ext (nx+2) x ny, column ii = i + 1.
  const std::vector<double>& u_ext() const { return u_ext_; }
  const std::vector<double>& v_ext() const { return v_ext_; }
  const std::vector<double>& p_ext() const { return p_ext_; }

 private:
  // Value and gradient of one component on its lattice at (x, y).
  void interpolate(const ExtendedLattice& lat, const std::vector<double>& data, double x,
                   double y, double* value, Eigen::Vector2d* gradient) const;
  double p_at(int ii, int j) const { return p_ext_[ii * grid_.ny + j]; }

  MacGrid grid_;
  ExtendedLattice u_lat_, v_lat_;
  std::vector<double> u_ext_, v_ext_, p_ext_;
};

}  // namespace hsrod

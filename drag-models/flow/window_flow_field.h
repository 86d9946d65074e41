// The disturbance flow a BrinkmanWindow solves for given node forces, as a
// field over the planform (level 4's disturbed flow in the field output,
// flow_field_vtk.h). The velocity u' [m/s] (gap-averaged) is
// interpolated bilinearly from the MAC nodes, with u' = 0 on the window
// edges and at nodes in walls (the window's boundary conditions); the
// pressure p' [Pa] bilinearly between the cell centres, over the cells with
// fluid. Outside the window rectangle u' = 0.
//
// Pressure gauge: the window fixes p' at one cell; here p' is shifted so that
// its mean over the downstream (x = x_max) column of cells is zero. A window
// that, with the walls it covers, closes a cross-section of the channel (it
// spans the width, or a pore throat between its cylinders) blocks no net
// flux (u' = 0 on its edges), so at fixed flow rate the rod's pressure rise
// p'_up (the mean over the upstream column) holds for the whole channel
// upstream of that section: upstream_rise() is added there. Nothing is added
// outside a window that closes no section (its disturbance is taken to have
// decayed at its edges).
#pragma once

#include "flow/brinkman_window.h"

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace hsrod {

class WindowFlowField {
 public:
  // Solves `window` for `node_forces` [N] (the force on the fluid at each
  // node, rows as window.nodes()); `geometry` is the scene the window lies
  // in (for the full-width test). Keeps a copy of the window's lattice and
  // node map, not the window.
  WindowFlowField(const BrinkmanWindow& window, const Eigen::VectorXd& node_forces, const ChannelGeometry& geometry);

  const WindowLattice& lattice() const { return lattice_; }
  // True when (x, y) [m] lies in the window rectangle.
  bool covers(double x, double y) const;
  // u' [m/s] at (x, y) [m]; zero outside the window.
  Eigen::Vector2d velocity(double x, double y) const;
  // p' [Pa] at (x, y) [m]: the window's pressure inside it, upstream_rise()
  // outside it upstream of the first section it closes, 0 elsewhere.
  double pressure(double x, double y) const;
  // Mean p' over the upstream column of cells minus that over the downstream
  // one [Pa] (the rod's pressure rise across the window).
  double upstream_rise() const { return upstream_rise_; }
  // True when the window closes a cross-section of the channel.
  bool spans_channel() const { return !std::isnan(closed_section_x_); }
  // The solution per cell [Pa] (NaN without fluid), after the gauge shift.
  const std::vector<double>& cell_pressure() const { return cell_pressure_; }

 private:
  double node_value(int component, int i, int j) const;
  WindowLattice lattice_;
  std::vector<int> u_unknown_, v_unknown_;  // as BrinkmanWindow::u_unknown / v_unknown
  Eigen::VectorXd node_velocity_;
  std::vector<double> cell_pressure_;
  double upstream_rise_ = 0.0;
  double closed_section_x_;  // m, NaN if the window closes no section
};

// Sum of the disturbances of several windows at (x, y) [m] (Stokes flow is
// linear; each rod's window is solved alone, as level 4 does).
Eigen::Vector2d disturbance_velocity(const std::vector<WindowFlowField>& windows, double x, double y);
double disturbance_pressure(const std::vector<WindowFlowField>& windows, double x, double y);

}  // namespace hsrod

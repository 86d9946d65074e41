#include "flow/window_flow_field.h"

#include <cmath>
#include <limits>
#include <utility>

namespace hsrod {
namespace {

// Linear interpolation weights along one lattice axis with nodes 0..m-1 at
// coordinate r [cells]: up to two (node, weight) pairs. With `half_edges`
// the window edges lie half a cell outside the first and last nodes and
// carry the value 0; otherwise r is clamped to the nodes.
struct AxisWeights {
  int node[2] = {-1, -1};
  double weight[2] = {0.0, 0.0};
};

AxisWeights axis_weights(double r, int m, bool half_edges) {
  AxisWeights w;
  if (half_edges) {
    if (r < -0.5 || r > m - 0.5) return w;
    if (r < 0.0) {
      w.node[0] = 0;
      w.weight[0] = (r + 0.5) / 0.5;
      return w;
    }
    if (r > m - 1) {
      w.node[0] = m - 1;
      w.weight[0] = (m - 0.5 - r) / 0.5;
      return w;
    }
  }
  r = std::min(std::max(r, 0.0), static_cast<double>(m - 1));
  const int i0 = std::min(static_cast<int>(std::floor(r)), std::max(m - 2, 0));
  const double f = r - i0;
  w.node[0] = i0;
  w.weight[0] = 1.0 - f;
  if (i0 + 1 < m) {
    w.node[1] = i0 + 1;
    w.weight[1] = f;
  }
  return w;
}

}  // namespace

WindowFlowField::WindowFlowField(const BrinkmanWindow& window, const Eigen::VectorXd& node_forces,
                                 const ChannelGeometry& geometry)
    : lattice_(window.lattice()) {
  const WindowLattice& g = lattice_;
  u_unknown_.resize((g.nx + 1) * g.ny);
  v_unknown_.resize(g.nx * (g.ny + 1));
  for (int i = 0; i <= g.nx; ++i)
    for (int j = 0; j < g.ny; ++j) u_unknown_[i * g.ny + j] = window.u_unknown(i, j);
  for (int i = 0; i < g.nx; ++i)
    for (int j = 0; j <= g.ny; ++j) v_unknown_[i * (g.ny + 1) + j] = window.v_unknown(i, j);
  node_velocity_ = window.solve_with_pressure(node_forces, cell_pressure_);
  // Gauge: mean p' over the downstream column = 0.
  auto column_mean = [&](int i) {
    double sum = 0.0;
    int count = 0;
    for (int j = 0; j < g.ny; ++j) {
      const double p = cell_pressure_[i * g.ny + j];
      if (std::isnan(p)) continue;
      sum += p;
      ++count;
    }
    return count > 0 ? sum / count : 0.0;
  };
  const double downstream = column_mean(g.nx - 1);
  for (double& p : cell_pressure_)
    if (!std::isnan(p)) p -= downstream;
  upstream_rise_ = column_mean(0);
  // The most upstream section x = x0 + i h that has no fluid outside the
  // window's y range (sampled every h / 4 towards the side walls).
  closed_section_x_ = std::numeric_limits<double>::quiet_NaN();
  const double y1 = g.y1(), step = 0.25 * g.h;
  auto fluid_outside = [&](double x) {
    for (double y = geometry.y_lo() + 0.5 * step; y < g.y0; y += step)
      if (geometry.signed_distance(x, y) > 0.0) return true;
    for (double y = geometry.y_hi() - 0.5 * step; y > y1; y -= step)
      if (geometry.signed_distance(x, y) > 0.0) return true;
    return false;
  };
  for (int i = 0; i <= g.nx; ++i)
    if (!fluid_outside(g.x_face(i))) {
      closed_section_x_ = g.x_face(i);
      break;
    }
}

bool WindowFlowField::covers(double x, double y) const {
  const WindowLattice& g = lattice_;
  return x >= g.x0 && x <= g.x1() && y >= g.y0 && y <= g.y1();
}

double WindowFlowField::node_value(int component, int i, int j) const {
  const WindowLattice& g = lattice_;
  const int k = component == 0 ? u_unknown_[i * g.ny + j] : v_unknown_[i * (g.ny + 1) + j];
  return k >= 0 ? node_velocity_[k] : 0.0;
}

Eigen::Vector2d WindowFlowField::velocity(double x, double y) const {
  if (!covers(x, y)) return Eigen::Vector2d::Zero();
  const WindowLattice& g = lattice_;
  // u nodes: x on the faces (the edge columns i = 0, nx carry no unknown),
  // y at the cell centres, half a cell off the edges; v nodes the other way
  // round. Linear in x and y between nodes (graded lattices too).
  const AxisWeights ux = axis_weights(g.x_face_index(x), g.nx + 1, false);
  const AxisWeights uy = axis_weights(g.y_centre_index(y), g.ny, true);
  const AxisWeights vx = axis_weights(g.x_centre_index(x), g.nx, true);
  const AxisWeights vy = axis_weights(g.y_face_index(y), g.ny + 1, false);
  Eigen::Vector2d u = Eigen::Vector2d::Zero();
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      if (ux.node[a] >= 0 && uy.node[b] >= 0)
        u.x() += ux.weight[a] * uy.weight[b] * node_value(0, ux.node[a], uy.node[b]);
      if (vx.node[a] >= 0 && vy.node[b] >= 0)
        u.y() += vx.weight[a] * vy.weight[b] * node_value(1, vx.node[a], vy.node[b]);
    }
  return u;
}

double WindowFlowField::pressure(double x, double y) const {
  const WindowLattice& g = lattice_;
  if (!covers(x, y)) return x < closed_section_x_ ? upstream_rise_ : 0.0;  // false for NaN
  const AxisWeights px = axis_weights(g.x_centre_index(x), g.nx, false);
  const AxisWeights py = axis_weights(g.y_centre_index(y), g.ny, false);
  double sum = 0.0, total = 0.0;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      if (px.node[a] < 0 || py.node[b] < 0) continue;
      const double p = cell_pressure_[px.node[a] * g.ny + py.node[b]];
      const double w = px.weight[a] * py.weight[b];
      if (std::isnan(p) || w <= 0.0) continue;
      sum += w * p;
      total += w;
    }
  return total > 0.0 ? sum / total : 0.0;
}

Eigen::Vector2d disturbance_velocity(const std::vector<WindowFlowField>& windows, double x, double y) {
  Eigen::Vector2d u = Eigen::Vector2d::Zero();
  for (const WindowFlowField& w : windows) u += w.velocity(x, y);
  return u;
}

double disturbance_pressure(const std::vector<WindowFlowField>& windows, double x, double y) {
  double p = 0.0;
  for (const WindowFlowField& w : windows) p += w.pressure(x, y);
  return p;
}

}  // namespace hsrod

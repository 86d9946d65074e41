#include "flow/brinkman_window.h"
#include "flow/line_stencils.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>
#include <string>

namespace hsrod {

namespace {
// Fractional index of x among faces (uniform: first + i h); beyond the ends
// continued with the end cell's size.
double fractional_index(double x, int cells, double first, double h, const std::vector<double>& faces) {
  if (faces.empty()) return (x - first) / h;
  if (x <= faces.front()) return (x - faces[0]) / (faces[1] - faces[0]);
  if (x >= faces.back()) return cells + (x - faces[cells]) / (faces[cells] - faces[cells - 1]);
  const int i = static_cast<int>(std::upper_bound(faces.begin(), faces.end(), x) - faces.begin()) - 1;
  return i + (x - faces[i]) / (faces[i + 1] - faces[i]);
}

}  // namespace

double WindowLattice::x_face_index(double x) const { return fractional_index(x, nx, x0, h, x_faces); }
double WindowLattice::y_face_index(double y) const { return fractional_index(y, ny, y0, h, y_faces); }
double WindowLattice::x_centre_index(double x) const {
  // Between centres i and i + 1 (a distance (dx(i) + dx(i+1)) / 2 apart) the
  // index is linear in x; beyond the first/last centre, linear to the edge.
  if (x_faces.empty()) return (x - x0) / h - 0.5;
  const double f = x_face_index(x);
  int i = static_cast<int>(std::floor(f - 0.5));
  if (i < 0) return -0.5 + (x - x0) / dx(0);
  if (i >= nx - 1) return nx - 1 + (x - x_centre(nx - 1)) / dx(nx - 1);
  return i + (x - x_centre(i)) / (x_centre(i + 1) - x_centre(i));
}
double WindowLattice::y_centre_index(double y) const {
  if (y_faces.empty()) return (y - y0) / h - 0.5;
  const double f = y_face_index(y);
  int j = static_cast<int>(std::floor(f - 0.5));
  if (j < 0) return -0.5 + (y - y0) / dy(0);
  if (j >= ny - 1) return ny - 1 + (y - y_centre(ny - 1)) / dy(ny - 1);
  return j + (y - y_centre(j)) / (y_centre(j + 1) - y_centre(j));
}

WindowLattice WindowLattice::shifted(double dx_, double dy_) const {
  WindowLattice moved(*this);
  moved.x0 += dx_;
  moved.y0 += dy_;
  for (double& x : moved.x_faces) x += dx_;
  for (double& y : moved.y_faces) y += dy_;
  return moved;
}

BrinkmanWindow::BrinkmanWindow(const ChannelGeometry& geometry, const WindowLattice& lattice,
                               double viscosity)
    : lattice_(lattice), gap_height_(geometry.gap_height()), viscosity_(viscosity) {
  check_lattice(lattice_);
  if (!(viscosity > 0.0)) throw std::invalid_argument("BrinkmanWindow: viscosity must be > 0 Pa s");
  number_unknowns(geometry);
  const int n = unknowns_ + static_cast<int>(std::count_if(pressure_unknown_.begin(), pressure_unknown_.end(),
                                                           [](int k) { return k >= 0; }));
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(n) * 7);
  add_momentum_rows(geometry, t);
  add_continuity_rows(t);
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  lu_ = std::make_shared<const Factorisation>(a);
}

void BrinkmanWindow::check_lattice(const WindowLattice& g) {
  if (g.nx < 3 || g.ny < 3 || !(g.h > 0.0))
    throw std::invalid_argument("BrinkmanWindow: need at least 3 x 3 cells of positive size");
  if ((!g.x_faces.empty() && static_cast<int>(g.x_faces.size()) != g.nx + 1) ||
      (!g.y_faces.empty() && static_cast<int>(g.y_faces.size()) != g.ny + 1))
    throw std::invalid_argument("BrinkmanWindow: graded lattice needs nx + 1 x faces and ny + 1 y faces");
  for (int i = 0; i < g.nx; ++i)
    if (!(g.dx(i) > 0.0)) throw std::invalid_argument("BrinkmanWindow: x faces must increase");
  for (int j = 0; j < g.ny; ++j)
    if (!(g.dy(j) > 0.0)) throw std::invalid_argument("BrinkmanWindow: y faces must increase");
}

// Velocity unknowns: interior fluid nodes (the window edges carry u' = 0),
// then pressure unknowns: the cells with an open face. Control area of a
// velocity node: the spacing to its neighbours' midpoints.
void BrinkmanWindow::number_unknowns(const ChannelGeometry& geometry) {
  const WindowLattice& g = lattice_;
  const double H = gap_height_;
  auto fluid = [&](const Eigen::Vector2d& p) { return geometry.signed_distance(p.x(), p.y()) > 1e-6 * g.h; };
  std::vector<double> scale;
  u_unknown_.assign((g.nx + 1) * g.ny, -1);
  v_unknown_.assign(g.nx * (g.ny + 1), -1);
  for (int i = 1; i < g.nx; ++i)
    for (int j = 0; j < g.ny; ++j)
      if (fluid(g.u_position(i, j))) {
        u_unknown_[u_index(i, j)] = unknowns_;
        nodes_.push_back({g.u_position(i, j), 0, unknowns_++});
        scale.push_back(H / (viscosity_ * (g.x_centre(i) - g.x_centre(i - 1)) * g.dy(j)));
      } else {
        has_walls_ = true;
      }
  for (int i = 0; i < g.nx; ++i)
    for (int j = 1; j < g.ny; ++j)
      if (fluid(g.v_position(i, j))) {
        v_unknown_[v_index(i, j)] = unknowns_;
        nodes_.push_back({g.v_position(i, j), 1, unknowns_++});
        scale.push_back(H / (viscosity_ * g.dx(i) * (g.y_centre(j) - g.y_centre(j - 1))));
      } else {
        has_walls_ = true;
      }
  if (unknowns_ == 0) throw std::invalid_argument("BrinkmanWindow: the window holds no fluid");
  force_scale_ = Eigen::Map<const Eigen::VectorXd>(scale.data(), unknowns_);
  pressure_unknown_.assign(g.nx * g.ny, -1);
  int n = unknowns_;
  for (int i = 0; i < g.nx; ++i)
    for (int j = 0; j < g.ny; ++j)
      if (u_unknown_[u_index(i, j)] >= 0 || u_unknown_[u_index(i + 1, j)] >= 0 || v_unknown_[v_index(i, j)] >= 0 ||
          v_unknown_[v_index(i, j + 1)] >= 0)
        pressure_unknown_[cell_index(i, j)] = n++;
}

// Momentum row of node (i, j) of component comp at p: -lap(u) + 12 u (lengths
// in H). Along each axis the neighbours lie at the node spacings (unequal on
// a graded lattice: the three-point second difference of line_stencils.h),
// or at a wall crossing closer than that (Shortley-Weller), or at the window
// edge half a cell away (for the component parallel to the edge).
void BrinkmanWindow::add_momentum_row(const ChannelGeometry& geometry, int row, const Eigen::Vector2d& p, int comp,
                                      int i, int j, std::vector<Eigen::Triplet<double>>& t) {
  const WindowLattice& g = lattice_;
  const double H = gap_height_;
  double diag = 12.0;
  for (int axis = 0; axis < 2; ++axis) {
    double dist[2];
    int nb[2];
    for (int side = 0; side < 2; ++side) {
      const int s = side == 0 ? -1 : 1;
      const Eigen::Vector2d dir = axis == 0 ? Eigen::Vector2d(s, 0) : Eigen::Vector2d(0, s);
      const int ni = i + (axis == 0 ? s : 0), nj = j + (axis == 1 ? s : 0);
      // Distance to the neighbouring node along this line, or to the edge.
      bool edge = false;
      double spacing;
      if (comp == 0) {
        if (axis == 0) spacing = s < 0 ? g.dx(i - 1) : g.dx(i);  // u nodes on x faces 1..nx-1
        else if (nj < 0 || nj >= g.ny) edge = true, spacing = 0.5 * g.dy(j);
        else spacing = std::abs(g.y_centre(nj) - g.y_centre(j));
      } else {
        if (axis == 1) spacing = s < 0 ? g.dy(j - 1) : g.dy(j);
        else if (ni < 0 || ni >= g.nx) edge = true, spacing = 0.5 * g.dx(i);
        else spacing = std::abs(g.x_centre(ni) - g.x_centre(i));
      }
      nb[side] = -1;
      dist[side] = spacing;
      // A wall just beyond the window edge (within a cell) still counts.
      const double reach = edge ? 2.0 * spacing : spacing;
      const double wall = geometry.ray_distance_to_wall(p, dir, reach);
      if (wall <= reach) {
        has_walls_ = true;
        dist[side] = std::max(wall, kMinWallFraction * reach);
        continue;
      }
      if (edge) continue;
      nb[side] = comp == 0 ? u_unknown_[u_index(ni, nj)] : v_unknown_[v_index(ni, nj)];
    }
    const LineWeights w = second_difference(dist[0] / H, dist[1] / H);
    diag -= w.self;
    if (nb[0] >= 0) t.emplace_back(row, nb[0], -w.minus);
    if (nb[1] >= 0) t.emplace_back(row, nb[1], -w.plus);
  }
  t.emplace_back(row, row, diag);
}

// Momentum rows of every velocity unknown, with the pressure gradient (in H).
void BrinkmanWindow::add_momentum_rows(const ChannelGeometry& geometry, std::vector<Eigen::Triplet<double>>& t) {
  const WindowLattice& g = lattice_;
  const double H = gap_height_;
  const std::vector<int>& pressure = pressure_unknown_;
  for (int i = 1; i < g.nx; ++i)
    for (int j = 0; j < g.ny; ++j) {
      const int r = u_unknown_[u_index(i, j)];
      if (r < 0) continue;
      add_momentum_row(geometry, r, g.u_position(i, j), 0, i, j, t);
      const double inv = H / (g.x_centre(i) - g.x_centre(i - 1));
      t.emplace_back(r, pressure[cell_index(i, j)], inv);
      t.emplace_back(r, pressure[cell_index(i - 1, j)], -inv);
    }
  for (int i = 0; i < g.nx; ++i)
    for (int j = 1; j < g.ny; ++j) {
      const int r = v_unknown_[v_index(i, j)];
      if (r < 0) continue;
      add_momentum_row(geometry, r, g.v_position(i, j), 1, i, j, t);
      const double inv = H / (g.y_centre(j) - g.y_centre(j - 1));
      t.emplace_back(r, pressure[cell_index(i, j)], inv);
      t.emplace_back(r, pressure[cell_index(i, j - 1)], -inv);
    }
}

// Continuity (-div u' = 0), except one cell per closed fluid region, where
// p' = 0 fixes the free constant (the region's continuity rows sum to zero
// because no disturbance flux leaves the window).
void BrinkmanWindow::add_continuity_rows(std::vector<Eigen::Triplet<double>>& t) const {
  const WindowLattice& g = lattice_;
  const double H = gap_height_;
  const std::vector<int>& pressure = pressure_unknown_;
  std::vector<char> seen(g.nx * g.ny, 0);
  for (int c0 = 0; c0 < g.nx * g.ny; ++c0) {
    if (pressure[c0] < 0 || seen[c0]) continue;
    t.emplace_back(pressure[c0], pressure[c0], 1.0);
    seen[c0] = 1;
    std::deque<int> queue{c0};
    while (!queue.empty()) {
      const int c = queue.front();
      queue.pop_front();
      const int i = c / g.ny, j = c % g.ny;
      const int e = u_unknown_[u_index(i + 1, j)], w = u_unknown_[u_index(i, j)];
      const int no = v_unknown_[v_index(i, j + 1)], so = v_unknown_[v_index(i, j)];
      if (c != c0) {
        // Scaled by the cell area / h^2 (for a uniform lattice the rows of
        // the unscaled operator), so that the rows of coarse cells do not
        // dwarf the fine ones.
        const int r = pressure[c];
        const double ax = H * g.dy(j) / (g.h * g.h), ay = H * g.dx(i) / (g.h * g.h);
        if (e >= 0) t.emplace_back(r, e, -ax);
        if (w >= 0) t.emplace_back(r, w, ax);
        if (no >= 0) t.emplace_back(r, no, -ay);
        if (so >= 0) t.emplace_back(r, so, ay);
      }
      auto visit = [&](bool open, int ni, int nj) {
        if (!open) return;
        const int nc = cell_index(ni, nj);
        if (!seen[nc] && pressure[nc] >= 0) {
          seen[nc] = 1;
          queue.push_back(nc);
        }
      };
      visit(e >= 0 && i + 1 < g.nx, i + 1, j);
      visit(w >= 0 && i > 0, i - 1, j);
      visit(no >= 0 && j + 1 < g.ny, i, j + 1);
      visit(so >= 0 && j > 0, i, j - 1);
    }
  }
}

BrinkmanWindow BrinkmanWindow::translated(double dx, double dy, bool walls_move_along) const {
  if (has_walls_ && !walls_move_along) throw std::logic_error("BrinkmanWindow::translated: the window has walls");
  BrinkmanWindow moved(*this);
  moved.lattice_ = lattice_.shifted(dx, dy);
  for (WindowNode& node : moved.nodes_) node.position += Eigen::Vector2d(dx, dy);
  return moved;
}

std::vector<int> BrinkmanWindow::nodes_near(const Eigen::Vector2d& centre, double radius, int component) const {
  // Lattice range that can hold such nodes, then the unknowns within radius.
  const WindowLattice& g = lattice_;
  auto x_index = [&](double x) { return component == 0 ? g.x_face_index(x) : g.x_centre_index(x); };
  auto y_index = [&](double y) { return component == 0 ? g.y_centre_index(y) : g.y_face_index(y); };
  const int i_lo = std::max(0, static_cast<int>(std::floor(x_index(centre.x() - radius))));
  const int i_hi = std::min(g.nx, static_cast<int>(std::ceil(x_index(centre.x() + radius))));
  const int j_lo = std::max(0, static_cast<int>(std::floor(y_index(centre.y() - radius))));
  const int j_hi = std::min(g.ny, static_cast<int>(std::ceil(y_index(centre.y() + radius))));
  std::vector<int> found;
  for (int i = i_lo; i <= i_hi; ++i)
    for (int j = j_lo; j <= j_hi; ++j) {
      int k = -1;
      if (component == 0 && j < g.ny) k = u_unknown_[i * g.ny + j];
      if (component == 1 && i < g.nx) k = v_unknown_[i * (g.ny + 1) + j];
      if (k >= 0 && (nodes_[k].position - centre).norm() < radius) found.push_back(k);
    }
  return found;
}

Eigen::MatrixXd BrinkmanWindow::solve(const Eigen::MatrixXd& node_forces) const {
  if (node_forces.rows() != unknowns_)
    throw std::invalid_argument("BrinkmanWindow::solve: expected " + std::to_string(unknowns_) + " rows");
  const int n = static_cast<int>(lu_->rows());
  // Force per node -> force density F / (H A), scaled by H^2 / mu.
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, node_forces.cols());
  rhs.topRows(unknowns_) = force_scale_.asDiagonal() * node_forces;
  const Eigen::MatrixXd x = lu_->solve(rhs);
  return x.topRows(unknowns_);
}

Eigen::MatrixXd BrinkmanWindow::solve_at(const std::vector<NodeForces>& node_forces,
                                         const std::vector<int>& at_nodes) const {
  std::vector<SparseLuFactors::SparseColumn> rhs(node_forces.size());
  for (std::size_t c = 0; c < node_forces.size(); ++c) {
    rhs[c].reserve(node_forces[c].size());
    for (const auto& entry : node_forces[c]) {
      if (entry.first < 0 || entry.first >= unknowns_)
        throw std::invalid_argument("BrinkmanWindow::solve_at: node out of range");
      rhs[c].emplace_back(entry.first, force_scale_[entry.first] * entry.second);
    }
  }
  for (int k : at_nodes)
    if (k < 0 || k >= unknowns_) throw std::invalid_argument("BrinkmanWindow::solve_at: node out of range");
  return lu_->solve_selected(rhs, at_nodes);
}

Eigen::MatrixXd BrinkmanWindow::weighted_response(const std::vector<NodeForces>& node_forces,
                                                  const std::vector<NodeForces>& read_weights) const {
  std::vector<SparseLuFactors::SparseColumn> rhs(node_forces.size());
  for (std::size_t c = 0; c < node_forces.size(); ++c) {
    rhs[c].reserve(node_forces[c].size());
    for (const auto& entry : node_forces[c]) {
      if (entry.first < 0 || entry.first >= unknowns_)
        throw std::invalid_argument("BrinkmanWindow::weighted_response: node out of range");
      rhs[c].emplace_back(entry.first, force_scale_[entry.first] * entry.second);
    }
  }
  for (const auto& row : read_weights)
    for (const auto& entry : row)
      if (entry.first < 0 || entry.first >= unknowns_)
        throw std::invalid_argument("BrinkmanWindow::weighted_response: node out of range");
  return lu_->bilinear(read_weights, rhs);
}

int BrinkmanWindow::u_unknown(int i, int j) const {
  const WindowLattice& g = lattice_;
  if (i < 0 || i > g.nx || j < 0 || j >= g.ny) return -1;
  return u_unknown_[i * g.ny + j];
}

int BrinkmanWindow::v_unknown(int i, int j) const {
  const WindowLattice& g = lattice_;
  if (i < 0 || i >= g.nx || j < 0 || j > g.ny) return -1;
  return v_unknown_[i * (g.ny + 1) + j];
}

Eigen::VectorXd BrinkmanWindow::solve_with_pressure(const Eigen::VectorXd& node_forces,
                                                    std::vector<double>& cell_pressure) const {
  if (node_forces.size() != unknowns_)
    throw std::invalid_argument("BrinkmanWindow::solve_with_pressure: expected " + std::to_string(unknowns_) +
                                " forces");
  const int n = static_cast<int>(lu_->rows());
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  rhs.head(unknowns_) = force_scale_.asDiagonal() * node_forces;
  const Eigen::VectorXd x = lu_->solve(rhs);
  // The unknowns are p* = p H / mu (lengths in H, momentum rows times H^2 / mu).
  const double to_pascal = viscosity_ / gap_height_;
  cell_pressure.assign(pressure_unknown_.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t c = 0; c < pressure_unknown_.size(); ++c)
    if (pressure_unknown_[c] >= 0) cell_pressure[c] = to_pascal * x[pressure_unknown_[c]];
  return x.head(unknowns_);
}

}  // namespace hsrod

#include "flow/brinkman_window.h"
#include "flow/line_stencils.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>
#include <string>

namespace hsrod {

BrinkmanWindow::BrinkmanWindow(const ChannelGeometry& geometry, const WindowLattice& lattice,
                               double viscosity)
    : lattice_(lattice), gap_height_(geometry.gap_height()), viscosity_(viscosity) {
  const WindowLattice& g = lattice_;
  if (g.nx < 3 || g.ny < 3 || !(g.h > 0.0))
    throw std::invalid_argument("BrinkmanWindow: need at least 3 x 3 cells of positive size");
  if (!(viscosity > 0.0)) throw std::invalid_argument("BrinkmanWindow: viscosity must be > 0 Pa s");
  const double h = g.h, eta = h / gap_height_;  // cell size [m] and [H]
  const double eps = 1e-6 * h;
  auto fluid = [&](const Eigen::Vector2d& p) { return geometry.signed_distance(p.x(), p.y()) > eps; };
  auto u_at = [&](int i, int j) { return i * g.ny + j; };        // (nx+1) x ny
  auto v_at = [&](int i, int j) { return i * (g.ny + 1) + j; };  // nx x (ny+1)
  auto cell_at = [&](int i, int j) { return i * g.ny + j; };

  // Velocity unknowns: interior fluid nodes (the window edges carry u' = 0).
  u_unknown_.assign((g.nx + 1) * g.ny, -1);
  v_unknown_.assign(g.nx * (g.ny + 1), -1);
  for (int i = 1; i < g.nx; ++i)
    for (int j = 0; j < g.ny; ++j)
      if (fluid(g.u_position(i, j))) {
        u_unknown_[u_at(i, j)] = unknowns_;
        nodes_.push_back({g.u_position(i, j), 0, unknowns_++});
      } else {
        has_walls_ = true;
      }
  for (int i = 0; i < g.nx; ++i)
    for (int j = 1; j < g.ny; ++j)
      if (fluid(g.v_position(i, j))) {
        v_unknown_[v_at(i, j)] = unknowns_;
        nodes_.push_back({g.v_position(i, j), 1, unknowns_++});
      } else {
        has_walls_ = true;
      }
  if (unknowns_ == 0) throw std::invalid_argument("BrinkmanWindow: the window holds no fluid");

  // Pressure cells: those with an open face.
  std::vector<int> pressure(g.nx * g.ny, -1);
  int n = unknowns_;
  for (int i = 0; i < g.nx; ++i)
    for (int j = 0; j < g.ny; ++j)
      if (u_unknown_[u_at(i, j)] >= 0 || u_unknown_[u_at(i + 1, j)] >= 0 || v_unknown_[v_at(i, j)] >= 0 ||
          v_unknown_[v_at(i, j + 1)] >= 0)
        pressure[cell_at(i, j)] = n++;

  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(n) * 7);
  // Momentum rows: -lap(u) + 12 u + grad p (lengths in H).
  auto momentum = [&](int row, const Eigen::Vector2d& p, int comp, int i, int j) {
    double diag = 12.0;
    for (int axis = 0; axis < 2; ++axis) {
      double dist[2];
      int nb[2];
      for (int side = 0; side < 2; ++side) {
        const int s = side == 0 ? -1 : 1;
        const Eigen::Vector2d dir = axis == 0 ? Eigen::Vector2d(s, 0) : Eigen::Vector2d(0, s);
        const double wall = geometry.ray_distance_to_wall(p, dir, h);
        nb[side] = -1;
        dist[side] = h;
        if (wall <= h) {
          has_walls_ = true;
          dist[side] = std::max(wall, kMinWallFraction * h);
          continue;
        }
        const int ni = i + (axis == 0 ? s : 0), nj = j + (axis == 1 ? s : 0);
        if (comp == 0) {
          if (nj < 0 || nj >= g.ny) dist[side] = 0.5 * h;  // window edge between nodes
          else nb[side] = u_unknown_[u_at(ni, nj)];
        } else {
          if (ni < 0 || ni >= g.nx) dist[side] = 0.5 * h;
          else nb[side] = v_unknown_[v_at(ni, nj)];
        }
      }
      const LineWeights w = second_difference(dist[0] / gap_height_, dist[1] / gap_height_);
      diag -= w.self;
      if (nb[0] >= 0) t.emplace_back(row, nb[0], -w.minus);
      if (nb[1] >= 0) t.emplace_back(row, nb[1], -w.plus);
    }
    t.emplace_back(row, row, diag);
  };
  for (int i = 1; i < g.nx; ++i)
    for (int j = 0; j < g.ny; ++j) {
      const int r = u_unknown_[u_at(i, j)];
      if (r < 0) continue;
      momentum(r, g.u_position(i, j), 0, i, j);
      t.emplace_back(r, pressure[cell_at(i, j)], 1.0 / eta);
      t.emplace_back(r, pressure[cell_at(i - 1, j)], -1.0 / eta);
    }
  for (int i = 0; i < g.nx; ++i)
    for (int j = 1; j < g.ny; ++j) {
      const int r = v_unknown_[v_at(i, j)];
      if (r < 0) continue;
      momentum(r, g.v_position(i, j), 1, i, j);
      t.emplace_back(r, pressure[cell_at(i, j)], 1.0 / eta);
      t.emplace_back(r, pressure[cell_at(i, j - 1)], -1.0 / eta);
    }

  // Continuity (-div u' = 0), except one cell per closed fluid region, where
  // p' = 0 fixes the free constant (the region's continuity rows sum to zero
  // because no disturbance flux leaves the window).
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
      const int e = u_unknown_[u_at(i + 1, j)], w = u_unknown_[u_at(i, j)];
      const int no = v_unknown_[v_at(i, j + 1)], so = v_unknown_[v_at(i, j)];
      if (c != c0) {
        const int r = pressure[c];
        if (e >= 0) t.emplace_back(r, e, -1.0 / eta);
        if (w >= 0) t.emplace_back(r, w, 1.0 / eta);
        if (no >= 0) t.emplace_back(r, no, -1.0 / eta);
        if (so >= 0) t.emplace_back(r, so, 1.0 / eta);
      }
      auto visit = [&](bool open, int ni, int nj) {
        if (!open) return;
        const int nc = cell_at(ni, nj);
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
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  auto lu = std::make_shared<Factorisation>();
  // COLAMD fill-reducing ordering: 40 % faster than KLU's default AMD on
  // windows cut by the pore cylinders (0.61 vs 1.02 s, 14454 unknowns), the
  // same on wall-free ones.
  lu->kluCommon().ordering = 1;
  lu->compute(a);
  if (lu->info() != Eigen::Success) throw std::runtime_error("BrinkmanWindow: sparse LU factorisation failed");
  lu_ = std::move(lu);
  pressure_unknown_ = std::move(pressure);
}

BrinkmanWindow BrinkmanWindow::translated(double dx, double dy) const {
  if (has_walls_) throw std::logic_error("BrinkmanWindow::translated: the window has walls");
  BrinkmanWindow moved(*this);
  moved.lattice_.x0 += dx;
  moved.lattice_.y0 += dy;
  for (WindowNode& node : moved.nodes_) node.position += Eigen::Vector2d(dx, dy);
  return moved;
}

std::vector<int> BrinkmanWindow::nodes_near(const Eigen::Vector2d& centre, double radius, int component) const {
  // Lattice range that can hold such nodes, then the unknowns within radius.
  const WindowLattice& g = lattice_;
  const double ox = component == 0 ? 0.0 : 0.5, oy = component == 0 ? 0.5 : 0.0;
  const int i_lo = std::max(0, static_cast<int>(std::floor((centre.x() - radius - g.x0) / g.h - ox)));
  const int i_hi = std::min(g.nx, static_cast<int>(std::ceil((centre.x() + radius - g.x0) / g.h - ox)));
  const int j_lo = std::max(0, static_cast<int>(std::floor((centre.y() - radius - g.y0) / g.h - oy)));
  const int j_hi = std::min(g.ny, static_cast<int>(std::ceil((centre.y() + radius - g.y0) / g.h - oy)));
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
  // Force per node -> force density F / (H h^2), scaled by H^2 / mu.
  const double scale = gap_height_ / (viscosity_ * lattice_.h * lattice_.h);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, node_forces.cols());
  rhs.topRows(unknowns_) = scale * node_forces;
  const Eigen::MatrixXd x = lu_->solve(rhs);
  return x.topRows(unknowns_);
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
  const double scale = gap_height_ / (viscosity_ * lattice_.h * lattice_.h);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  rhs.head(unknowns_) = scale * node_forces;
  const Eigen::VectorXd x = lu_->solve(rhs);
  // The unknowns are p* = p H / mu (lengths in H, momentum rows times H^2 / mu).
  const double to_pascal = viscosity_ / gap_height_;
  cell_pressure.assign(pressure_unknown_.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t c = 0; c < pressure_unknown_.size(); ++c)
    if (pressure_unknown_[c] >= 0) cell_pressure[c] = to_pascal * x[pressure_unknown_[c]];
  return x.head(unknowns_);
}

}  // namespace hsrod

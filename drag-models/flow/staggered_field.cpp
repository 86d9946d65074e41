#include "flow/staggered_field.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hsrod {

StaggeredField::StaggeredField(const BrinkmanGridSolution& s, const ChannelGeometry& geo)
    : grid_(s.grid),
      u_lat_(extended_u_lattice(s.grid)),
      v_lat_(extended_v_lattice(s.grid)),
      u_ext_(extend_u(s, geo)),
      v_ext_(extend_v(s, geo)) {
  const MacGrid& g = grid_;
  p_ext_.assign((g.nx + 2) * g.ny, std::nan(""));
  for (int i = 0; i < g.nx; ++i)
    for (int j = 0; j < g.ny; ++j) p_ext_[(i + 1) * g.ny + j] = s.pressure[g.cell_index(i, j)];
  for (int j = 0; j < g.ny; ++j) {
    const double p0 = p_ext_[1 * g.ny + j], p1 = p_ext_[2 * g.ny + j];
    p_ext_[j] = std::isnan(p1) ? p0 : 2.0 * p0 - p1;          // linear towards the inlet
    p_ext_[(g.nx + 1) * g.ny + j] = -p_ext_[g.nx * g.ny + j];  // p = 0 on the outlet plane
  }
}

StaggeredField::StaggeredField(const MacGrid& grid, std::vector<double> u_ext,
                               std::vector<double> v_ext, std::vector<double> p_ext)
    : grid_(grid),
      u_lat_(extended_u_lattice(grid)),
      v_lat_(extended_v_lattice(grid)),
      u_ext_(std::move(u_ext)),
      v_ext_(std::move(v_ext)),
      p_ext_(std::move(p_ext)) {
  if (static_cast<long>(u_ext_.size()) != u_lat_.size() ||
      static_cast<long>(v_ext_.size()) != v_lat_.size() ||
      static_cast<long>(p_ext_.size()) != static_cast<long>(grid.nx + 2) * grid.ny)
    throw std::invalid_argument("StaggeredField: array sizes do not match the grid");
}

namespace {

// Catmull-Rom weights of the nodes -1, 0, 1, 2 at t in [0, 1], and their derivatives.
inline void catmull_rom(double t, double w[4], double dw[4]) {
  const double t2 = t * t, t3 = t2 * t;
  w[0] = 0.5 * (-t3 + 2.0 * t2 - t);
  w[1] = 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0);
  w[2] = 0.5 * (-3.0 * t3 + 4.0 * t2 + t);
  w[3] = 0.5 * (t3 - t2);
  dw[0] = 0.5 * (-3.0 * t2 + 4.0 * t - 1.0);
  dw[1] = 0.5 * (9.0 * t2 - 10.0 * t);
  dw[2] = 0.5 * (-9.0 * t2 + 8.0 * t + 1.0);
  dw[3] = 0.5 * (3.0 * t2 - 2.0 * t);
}

}  // namespace

void StaggeredField::interpolate(const ExtendedLattice& lat, const std::vector<double>& data,
                                 double x, double y, double* value,
                                 Eigen::Vector2d* gradient) const {
  const double fx = (x - lat.x0) / lat.hx, fy = (y - lat.y0) / lat.hy;
  const int i0 = std::clamp(static_cast<int>(std::floor(fx)), lat.i_min + 1, lat.i_max - 2);
  const int j0 = std::clamp(static_cast<int>(std::floor(fy)), lat.j_min + 1, lat.j_max - 2);
  const double tx = std::clamp(fx - i0, 0.0, 1.0), ty = std::clamp(fy - j0, 0.0, 1.0);
  // The 4 x 4 stencil: four runs of four nodes, one lattice row apart
  // (index(i, j) = (i - i_min) ny_ext + (j - j_min)). A node no ghost line
  // reaches (NaN, deep in a wall) counts as 0, the wall's own velocity:
  // one interpolant everywhere, so the field is continuous (C1) across the
  // cells of the wall band too. A bilinear fallback for stencils with such
  // a node used to switch interpolants from one cell to the next: jumps of
  // 0.02-0.03 of the mean speed along a pore cylinder's surface, which the
  // no-slip band's wall value carried into the field near the wall.
  double node[4][4];
  const double* corner = data.data() + lat.index(i0 - 1, j0 - 1);
  const int row = lat.ny_ext();
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const double v = corner[a * row + b];
      node[a][b] = std::isnan(v) ? 0.0 : v;
    }
  double wx[4], dwx[4], wy[4], dwy[4];
  catmull_rom(tx, wx, dwx);
  catmull_rom(ty, wy, dwy);
  // (value, d/dx) as the two lanes of one vector (each lane the same
  // products and sums in the same order as separate scalars).
  Eigen::Array2d v_gx = Eigen::Array2d::Zero();
  double gy = 0.0;
  for (int a = 0; a < 4; ++a) {
    const Eigen::Array2d w_a(wx[a], dwx[a]);
    for (int b = 0; b < 4; ++b) {
      v_gx += w_a * wy[b] * node[a][b];
      gy += wx[a] * dwy[b] * node[a][b];
    }
  }
  *value = v_gx[0];
  if (gradient) *gradient = Eigen::Vector2d(v_gx[1] / lat.hx, gy / lat.hy);
}

Eigen::Vector2d StaggeredField::velocity(double x, double y) const {
  x = std::clamp(x, 0.0, grid_.nx * grid_.hx);
  Eigen::Vector2d u;
  interpolate(u_lat_, u_ext_, x, y, &u.x(), nullptr);
  interpolate(v_lat_, v_ext_, x, y, &u.y(), nullptr);
  return u;
}

Eigen::Matrix2d StaggeredField::velocity_gradient(double x, double y) const {
  x = std::clamp(x, 0.0, grid_.nx * grid_.hx);
  double value;
  Eigen::Vector2d gu, gv;
  interpolate(u_lat_, u_ext_, x, y, &value, &gu);
  interpolate(v_lat_, v_ext_, x, y, &value, &gv);
  Eigen::Matrix2d grad;
  grad.row(0) = gu.transpose();
  grad.row(1) = gv.transpose();
  return grad;
}

void StaggeredField::velocity_and_gradient(double x, double y, Eigen::Vector2d& u, Eigen::Matrix2d& g) const {
  x = std::clamp(x, 0.0, grid_.nx * grid_.hx);
  Eigen::Vector2d gu, gv;
  interpolate(u_lat_, u_ext_, x, y, &u.x(), &gu);
  interpolate(v_lat_, v_ext_, x, y, &u.y(), &gv);
  g.row(0) = gu.transpose();
  g.row(1) = gv.transpose();
}

double StaggeredField::pressure(double x, double y) const {
  const MacGrid& g = grid_;
  x = std::clamp(x, 0.0, g.nx * g.hx);
  const double fx = x / g.hx + 0.5, fy = y / g.hy - 0.5;
  const int i0 = std::clamp(static_cast<int>(std::floor(fx)), 0, g.nx);
  const int j0 = std::clamp(static_cast<int>(std::floor(fy)), 0, std::max(g.ny - 2, 0));
  const double tx = std::clamp(fx - i0, 0.0, 1.0), ty = std::clamp(fy - j0, 0.0, 1.0);
  const double w[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
  const double p[4] = {p_at(i0, j0), p_at(i0 + 1, j0), p_at(i0, j0 + 1), p_at(i0 + 1, j0 + 1)};
  double num = 0.0, den = 0.0, plain = 0.0;
  int valid = 0;
  for (int k = 0; k < 4; ++k)
    if (!std::isnan(p[k])) {
      num += w[k] * p[k];
      den += w[k];
      plain += p[k];
      ++valid;
    }
  if (valid == 0) return 0.0;
  return den > 1e-12 ? num / den : plain / valid;
}

}  // namespace hsrod

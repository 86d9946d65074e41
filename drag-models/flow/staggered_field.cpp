#include "flow/staggered_field.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hsrod {
namespace {

// Ghost value of a wall node g from its fluid neighbours f along the grid
// lines: the line through (f, u_f) and (wall point, 0) evaluated at g, i.e.
// u_g = (theta - 1)/theta u_f with theta = |f - wall| / |f - g|; several lines
// are combined with weights theta (favouring the better-conditioned ones).
template <class Valued, class Value, class Position>
double ghost_value(const ChannelGeometry& geo, int i, int j, double hx, double hy,
                   Valued valued, Value value, Position position) {
  double num = 0.0, den = 0.0;
  const int dirs[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (const auto& d : dirs) {
    const int fi = i + d[0], fj = j + d[1];
    if (!valued(fi, fj)) continue;
    const double h = d[0] != 0 ? hx : hy;
    const double t = geo.ray_distance_to_wall(position(fi, fj), Eigen::Vector2d(-d[0], -d[1]), h);
    const double theta = t <= h ? std::max(t / h, 1e-3) : 1.0;
    num += (theta - 1.0) * value(fi, fj);
    den += theta;
  }
  return den > 0.0 ? num / den : 0.0;
}

}  // namespace

StaggeredField::StaggeredField(const BrinkmanGridSolution& s, const ChannelGeometry& geo)
    : grid_(s.grid) {
  const MacGrid& g = grid_;
  const int nu_y = g.ny + 2, nv_y = g.ny + 1;
  u_ext_.assign((g.nx + 1) * nu_y, 0.0);
  v_ext_.assign((g.nx + 2) * nv_y, 0.0);
  p_ext_.assign((g.nx + 2) * g.ny, std::nan(""));

  auto u_valued = [&](int i, int j) {
    return i >= 0 && i <= g.nx && j >= 0 && j < g.ny && s.masks.u[g.u_index(i, j)] != NodeKind::kWall;
  };
  auto u_value = [&](int i, int j) { return s.u[g.u_index(i, j)]; };
  auto u_pos = [&](int i, int j) { return g.u_position(i, j); };
  for (int i = 0; i <= g.nx; ++i)
    for (int j = -1; j <= g.ny; ++j)
      u_ext_[i * nu_y + j + 1] = u_valued(i, j) ? u_value(i, j)
                                                : ghost_value(geo, i, j, g.hx, g.hy, u_valued,
                                                              u_value, u_pos);

  auto v_valued = [&](int i, int j) {
    return i >= 0 && i < g.nx && j >= 0 && j <= g.ny && s.masks.v[g.v_index(i, j)] != NodeKind::kWall;
  };
  auto v_value = [&](int i, int j) { return s.v[g.v_index(i, j)]; };
  auto v_pos = [&](int i, int j) { return g.v_position(i, j); };
  for (int i = 0; i < g.nx; ++i)
    for (int j = 0; j <= g.ny; ++j)
      v_ext_[(i + 1) * nv_y + j] = v_valued(i, j) ? v_value(i, j)
                                                  : ghost_value(geo, i, j, g.hx, g.hy, v_valued,
                                                                v_value, v_pos);
  for (int j = 0; j <= g.ny; ++j) {
    v_ext_[0 * nv_y + j] = -v_ext_[1 * nv_y + j];                // v = 0 on the inlet plane
    v_ext_[(g.nx + 1) * nv_y + j] = v_ext_[g.nx * nv_y + j];     // dv/dx = 0 at the outlet
  }

  for (int i = 0; i < g.nx; ++i)
    for (int j = 0; j < g.ny; ++j) p_ext_[(i + 1) * g.ny + j] = s.pressure[g.cell_index(i, j)];
  for (int j = 0; j < g.ny; ++j) {
    const double p0 = p_ext_[1 * g.ny + j], p1 = p_ext_[2 * g.ny + j];
    p_ext_[j] = std::isnan(p1) ? p0 : 2.0 * p0 - p1;             // linear towards the inlet
    p_ext_[(g.nx + 1) * g.ny + j] = -p_ext_[g.nx * g.ny + j];     // p = 0 on the outlet plane
  }
}

StaggeredField::StaggeredField(const MacGrid& grid, std::vector<double> u_ext,
                               std::vector<double> v_ext, std::vector<double> p_ext)
    : grid_(grid), u_ext_(std::move(u_ext)), v_ext_(std::move(v_ext)), p_ext_(std::move(p_ext)) {
  if (static_cast<long>(u_ext_.size()) != static_cast<long>(grid.nx + 1) * (grid.ny + 2) ||
      static_cast<long>(v_ext_.size()) != static_cast<long>(grid.nx + 2) * (grid.ny + 1) ||
      static_cast<long>(p_ext_.size()) != static_cast<long>(grid.nx + 2) * grid.ny)
    throw std::invalid_argument("StaggeredField: array sizes do not match the grid");
}

namespace {
struct Cell {
  int i0, j0;
  double tx, ty;
};
// Cell of a node lattice with origin offset (ox, oy) [cells] containing (fx, fy).
Cell locate(double fx, double fy, int max_i0, int max_j0) {
  Cell c;
  c.i0 = std::clamp(static_cast<int>(std::floor(fx)), 0, max_i0);
  c.j0 = std::clamp(static_cast<int>(std::floor(fy)), 0, max_j0);
  c.tx = std::clamp(fx - c.i0, 0.0, 1.0);
  c.ty = std::clamp(fy - c.j0, 0.0, 1.0);
  return c;
}
}  // namespace

Eigen::Vector2d StaggeredField::velocity(double x, double y) const {
  const MacGrid& g = grid_;
  x = std::clamp(x, 0.0, g.nx * g.hx);
  const Cell cu = locate(x / g.hx, y / g.hy + 0.5, g.nx - 1, g.ny);
  const double u = (1 - cu.tx) * (1 - cu.ty) * u_at(cu.i0, cu.j0) +
                   cu.tx * (1 - cu.ty) * u_at(cu.i0 + 1, cu.j0) +
                   (1 - cu.tx) * cu.ty * u_at(cu.i0, cu.j0 + 1) +
                   cu.tx * cu.ty * u_at(cu.i0 + 1, cu.j0 + 1);
  const Cell cv = locate(x / g.hx + 0.5, y / g.hy, g.nx, g.ny - 1);
  const double v = (1 - cv.tx) * (1 - cv.ty) * v_at(cv.i0, cv.j0) +
                   cv.tx * (1 - cv.ty) * v_at(cv.i0 + 1, cv.j0) +
                   (1 - cv.tx) * cv.ty * v_at(cv.i0, cv.j0 + 1) +
                   cv.tx * cv.ty * v_at(cv.i0 + 1, cv.j0 + 1);
  return {u, v};
}

Eigen::Matrix2d StaggeredField::velocity_gradient(double x, double y) const {
  const MacGrid& g = grid_;
  x = std::clamp(x, 0.0, g.nx * g.hx);
  Eigen::Matrix2d grad;
  const Cell cu = locate(x / g.hx, y / g.hy + 0.5, g.nx - 1, g.ny);
  const double u00 = u_at(cu.i0, cu.j0), u10 = u_at(cu.i0 + 1, cu.j0);
  const double u01 = u_at(cu.i0, cu.j0 + 1), u11 = u_at(cu.i0 + 1, cu.j0 + 1);
  grad(0, 0) = ((1 - cu.ty) * (u10 - u00) + cu.ty * (u11 - u01)) / g.hx;
  grad(0, 1) = ((1 - cu.tx) * (u01 - u00) + cu.tx * (u11 - u10)) / g.hy;
  const Cell cv = locate(x / g.hx + 0.5, y / g.hy, g.nx, g.ny - 1);
  const double v00 = v_at(cv.i0, cv.j0), v10 = v_at(cv.i0 + 1, cv.j0);
  const double v01 = v_at(cv.i0, cv.j0 + 1), v11 = v_at(cv.i0 + 1, cv.j0 + 1);
  grad(1, 0) = ((1 - cv.ty) * (v10 - v00) + cv.ty * (v11 - v01)) / g.hx;
  grad(1, 1) = ((1 - cv.tx) * (v01 - v00) + cv.tx * (v11 - v10)) / g.hy;
  return grad;
}

double StaggeredField::pressure(double x, double y) const {
  const MacGrid& g = grid_;
  x = std::clamp(x, 0.0, g.nx * g.hx);
  const Cell c = locate(x / g.hx + 0.5, y / g.hy - 0.5, g.nx, std::max(g.ny - 2, 0));
  const double w[4] = {(1 - c.tx) * (1 - c.ty), c.tx * (1 - c.ty), (1 - c.tx) * c.ty, c.tx * c.ty};
  const double p[4] = {p_at(c.i0, c.j0), p_at(c.i0 + 1, c.j0), p_at(c.i0, c.j0 + 1),
                       p_at(c.i0 + 1, c.j0 + 1)};
  double num = 0.0, den = 0.0;
  for (int k = 0; k < 4; ++k)
    if (!std::isnan(p[k])) {
      num += w[k] * p[k];
      den += w[k];
    }
  return den > 0.0 ? num / den : 0.0;
}

}  // namespace hsrod

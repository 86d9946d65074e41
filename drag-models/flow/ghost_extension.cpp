#include "flow/ghost_extension.h"

#include <cmath>
#include <functional>
#include <limits>

namespace hsrod {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Value at signed wall distance s_g (< 0 in the wall) of p(s) = a s + b s^2
// through (s1, u1) and (s2, u2), s measured from the wall into the fluid.
double quadratic_through_wall(double s1, double u1, double s2, double u2, double s_g) {
  const double det = s1 * s2 * (s2 - s1);
  const double a = (u1 * s2 * s2 - u2 * s1 * s1) / det;
  const double b = (u2 * s1 - u1 * s2) / det;
  return a * s_g + b * s_g * s_g;
}

// Fills the in-range part (i in [i_lo, i_hi]) of an extended lattice.
// valued(i, j): node holds a solved (fluid or inlet) value; value(i, j) its value.
void fill_ghosts(const ChannelGeometry& geo, const ExtendedLattice& lat, int i_lo, int i_hi,
                 const std::function<bool(int, int)>& valued,
                 const std::function<double(int, int)>& value, std::vector<double>& out) {
  auto pos = [&](int i, int j) { return Eigen::Vector2d(lat.x0 + i * lat.hx, lat.y0 + j * lat.hy); };
  auto ok = [&](int i, int j) {
    return i >= i_lo && i <= i_hi && j >= lat.j_min && j <= lat.j_max && valued(i, j);
  };
  const int dirs[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (int i = i_lo; i <= i_hi; ++i)
    for (int j = lat.j_min; j <= lat.j_max; ++j) {
      double& target = out[lat.index(i, j)];
      if (ok(i, j)) {
        target = value(i, j);
        continue;
      }
      double num = 0.0, den = 0.0;
      for (const auto& d : dirs) {
        const double h = d[0] != 0 ? lat.hx : lat.hy;
        const Eigen::Vector2d towards_fluid(d[0], d[1]);
        int k = 1;
        while (k <= 2 && !ok(i + k * d[0], j + k * d[1])) ++k;
        if (k > 2) continue;
        const int i1 = i + k * d[0], j1 = j + k * d[1];
        // Wall crossing between the first fluid node and the ghost.
        const double t_hit = geo.ray_distance_to_wall(pos(i1, j1), -towards_fluid, k * h);
        const double t = std::isfinite(t_hit) ? t_hit : k * h;
        const double s_g = t - k * h;  // <= 0
        // Further fluid nodes on the line, with no other wall in between.
        const double free_run = geo.ray_distance_to_wall(pos(i1, j1), towards_fluid, 2.0 * h);
        const bool f2 = ok(i1 + d[0], j1 + d[1]) && free_run > h;
        const bool f3 = f2 && ok(i1 + 2 * d[0], j1 + 2 * d[1]) && free_run > 2.0 * h;
        const double u1 = value(i1, j1);
        double g;
        if (f2 && (t >= 0.5 * h || !f3)) {
          g = quadratic_through_wall(t, u1, t + h, value(i1 + d[0], j1 + d[1]), s_g);
        } else if (f3) {
          g = quadratic_through_wall(t + h, value(i1 + d[0], j1 + d[1]), t + 2.0 * h,
                                     value(i1 + 2 * d[0], j1 + 2 * d[1]), s_g);
        } else {
          const double s1 = std::max(t, 1e-3 * h);
          g = u1 * s_g / s1;
        }
        const double w = 1.0 / ((0.1 + -s_g / h) * (0.1 + -s_g / h));
        num += w * g;
        den += w;
      }
      target = den > 0.0 ? num / den : kNaN;
    }
}

}  // namespace

ExtendedLattice extended_u_lattice(const MacGrid& g) {
  ExtendedLattice l;
  l.i_min = -2;
  l.i_max = g.nx + 2;
  l.j_min = -2;
  l.j_max = g.ny + 1;
  l.x0 = 0.0;
  l.y0 = 0.5 * g.hy;
  l.hx = g.hx;
  l.hy = g.hy;
  return l;
}

ExtendedLattice extended_v_lattice(const MacGrid& g) {
  ExtendedLattice l;
  l.i_min = -2;
  l.i_max = g.nx + 1;
  l.j_min = -2;
  l.j_max = g.ny + 2;
  l.x0 = 0.5 * g.hx;
  l.y0 = 0.0;
  l.hx = g.hx;
  l.hy = g.hy;
  return l;
}

std::vector<double> extend_u(const BrinkmanGridSolution& s, const ChannelGeometry& geo) {
  const MacGrid& g = s.grid;
  const ExtendedLattice lat = extended_u_lattice(g);
  std::vector<double> out(lat.size(), kNaN);
  auto valued = [&](int i, int j) {
    return i >= 0 && i <= g.nx && j >= 0 && j < g.ny && s.masks.u[g.u_index(i, j)] != NodeKind::kWall;
  };
  auto value = [&](int i, int j) { return s.u[g.u_index(i, j)]; };
  fill_ghosts(geo, lat, 0, g.nx, valued, value, out);
  // Beyond the inlet and outlet the developed flow continues: even mirror.
  for (int m = 1; m <= 2; ++m)
    for (int j = lat.j_min; j <= lat.j_max; ++j) {
      out[lat.index(-m, j)] = out[lat.index(m, j)];
      out[lat.index(g.nx + m, j)] = out[lat.index(g.nx - m, j)];
    }
  return out;
}

std::vector<double> extend_v(const BrinkmanGridSolution& s, const ChannelGeometry& geo) {
  const MacGrid& g = s.grid;
  const ExtendedLattice lat = extended_v_lattice(g);
  std::vector<double> out(lat.size(), kNaN);
  auto valued = [&](int i, int j) {
    return i >= 0 && i < g.nx && j >= 0 && j <= g.ny && s.masks.v[g.v_index(i, j)] != NodeKind::kWall;
  };
  auto value = [&](int i, int j) { return s.v[g.v_index(i, j)]; };
  fill_ghosts(geo, lat, 0, g.nx - 1, valued, value, out);
  for (int m = 0; m <= 1; ++m)
    for (int j = lat.j_min; j <= lat.j_max; ++j) {
      out[lat.index(-1 - m, j)] = -out[lat.index(m, j)];              // v = 0 on the inlet plane
      out[lat.index(g.nx + m, j)] = out[lat.index(g.nx - 1 - m, j)];  // dv/dx = 0 at the outlet
    }
  return out;
}

}  // namespace hsrod

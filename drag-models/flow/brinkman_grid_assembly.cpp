// The discrete depth-averaged Brinkman system of the MAC grid solver: wall
// stencils, the developed inlet profile, and the assembly of the
// (Oseen-linearised) saddle-point system (brinkman_grid_solver.h: the scheme).
#include "flow/brinkman_grid_assembly.h"

#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsrod {
namespace brinkman_grid {

double Stencils::layer_rate(const Eigen::Vector2d& p, const Eigen::Vector2d& line) const {
  if (!fitted_) return 0.0;
  const double k = std::sqrt(12.0);
  if (!(geo_.signed_distance(p.x(), p.y()) * k < 10.0)) return 0.0;
  return k * std::abs(geo_.wall_normal(p.x(), p.y()).dot(line));
}

Neighbour Stencils::neighbour(Component c, int i, int j, int di, int dj) const {
  const double h = di != 0 ? g_.hx : g_.hy;
  const int ni = i + di, nj = j + dj;
  if (c == Component::kU && ni > g_.nx) return {g_.hx, g_.u_index(i - 1, j)};
  if (c == Component::kV && ni < 0) return {0.5 * g_.hx, -1};
  if (c == Component::kV && ni >= g_.nx) return {g_.hx, g_.v_index(i, j)};
  const Eigen::Vector2d p = position(c, i, j);
  const double t = geo_.ray_distance_to_wall(p, Eigen::Vector2d(di, dj), h);
  if (t <= h) return {std::max(t, kMinWallFraction * h), -1};
  const int ny_nodes = c == Component::kU ? g_.ny : g_.ny + 1;
  if (nj < 0 || nj >= ny_nodes) return {h, -1};
  const int n = index(c, ni, nj);
  if (kind(c, n) == NodeKind::kWall) return {h, -1};
  return {h, n};
}

Stencils::FaceFlux Stencils::face_flux(Component c, int i, int j) const {
  if (fitted_) return fitted_face_flux(c, i, j);
  const Eigen::Vector2d p = position(c, i, j);
  const bool is_u = c == Component::kU;
  const Eigen::Vector2d line = is_u ? Eigen::Vector2d(0, 1) : Eigen::Vector2d(1, 0);
  const double h = is_u ? g_.hy : g_.hx;
  const double dm = geo_.ray_distance_to_wall(p, -line, h);
  const double dp = geo_.ray_distance_to_wall(p, line, h);
  const bool wm = dm < h, wp = dp < h;
  FaceFlux f;
  if (!wm && !wp) return f;
  if (wm && wp) {  // narrow gap: plain aperture
    f.self = (std::min(dm, 0.5 * h) + std::min(dp, 0.5 * h)) / h;
    return f;
  }
  const double d = std::max(wm ? dm : dp, kMinWallFraction * h);
  if (d >= 0.5 * h) {
    f.self = 1.0 + (d - 0.5 * h) * (d - 0.5 * h) / (2.0 * d * h);
    return f;
  }
  const double span2 = (d + 0.5 * h) * (d + 0.5 * h) / (2.0 * h);
  const int step = wm ? 1 : -1;  // towards the fluid
  const int fi = is_u ? i : i + step, fj = is_u ? j + step : j;
  const int ny_nodes = is_u ? g_.ny : g_.ny + 1, nx_nodes = is_u ? g_.nx + 1 : g_.nx;
  const bool usable = fi >= 0 && fi < nx_nodes && fj >= 0 && fj < ny_nodes &&
                      kind(c, index(c, fi, fj)) == NodeKind::kUnknown;
  if (!usable) {
    f.self = span2 / d;
    return f;
  }
  const double w = 2.0 * d / h;
  f.self = span2 * w / d;
  f.other = index(c, fi, fj);
  f.other_weight = span2 * (1.0 - w) / (d + h);
  return f;
}

Stencils::FaceFlux Stencils::fitted_face_flux(Component c, int i, int j) const {
  const Eigen::Vector2d p = position(c, i, j);
  const bool is_u = c == Component::kU;
  const Eigen::Vector2d line = is_u ? Eigen::Vector2d(0, 1) : Eigen::Vector2d(1, 0);
  const double h = is_u ? g_.hy : g_.hx;
  const double dm = geo_.ray_distance_to_wall(p, -line, 2.0 * h);
  const double dp = geo_.ray_distance_to_wall(p, line, 2.0 * h);
  const bool wm = dm < h, wp = dp < h;
  FaceFlux f;
  if (wm && wp) {  // narrow gap: plain aperture
    f.self = (std::min(dm, 0.5 * h) + std::min(dp, 0.5 * h)) / h;
    return f;
  }
  const double kappa = layer_rate(p, line);
  if (!wm && !wp) {
    const double d = std::min(dm, dp);
    if (!(d < 2.0 * h)) return f;
    f.self = (wall_layer_shape_integral(d + 0.5 * h, kappa) -
              wall_layer_shape_integral(d - 0.5 * h, kappa)) /
             (h * wall_layer_shape(d, kappa));
    return f;
  }
  const double d = std::max(wm ? dm : dp, kMinWallFraction * h);
  const double span = wall_layer_shape_integral(d + 0.5 * h, kappa) / h;
  f.self = span / wall_layer_shape(d, kappa);
  if (d >= 0.5 * h) return f;
  const int step = wm ? 1 : -1;  // towards the fluid
  const int fi = is_u ? i : i + step, fj = is_u ? j + step : j;
  const int ny_nodes = is_u ? g_.ny : g_.ny + 1, nx_nodes = is_u ? g_.nx + 1 : g_.nx;
  const bool usable = fi >= 0 && fi < nx_nodes && fj >= 0 && fj < ny_nodes &&
                      kind(c, index(c, fi, fj)) == NodeKind::kUnknown;
  if (!usable) return f;
  const double w = 2.0 * d / h;
  f.self = span * w / wall_layer_shape(d, kappa);
  f.other = index(c, fi, fj);
  f.other_weight = span * (1.0 - w) / wall_layer_shape(d + h, kappa);
  return f;
}

LineWeights Stencils::second(Component c, int i, int j, int axis, double a, double b) const {
  if (!fitted_) return second_difference(a, b);
  const Eigen::Vector2d line = axis == 0 ? Eigen::Vector2d(1, 0) : Eigen::Vector2d(0, 1);
  return fitted_second_difference(a, b, layer_rate(position(c, i, j), line));
}

std::vector<double> discrete_inlet_profile(const Stencils& st, const MacGrid& g,
                                           const MacMasks& m, double width) {
  std::vector<int> id(g.ny, -1);
  int n = 0;
  for (int j = 0; j < g.ny; ++j)
    if (m.u[g.u_index(0, j)] == NodeKind::kInlet) id[j] = n++;
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd rhs = Eigen::VectorXd::Ones(n);
  for (int j = 0; j < g.ny; ++j) {
    if (id[j] < 0) continue;
    const Neighbour lo = st.neighbour(Component::kU, 0, j, 0, -1);
    const Neighbour hi = st.neighbour(Component::kU, 0, j, 0, +1);
    const LineWeights w = st.second(Component::kU, 0, j, 1, lo.dist, hi.dist);
    t.emplace_back(id[j], id[j], 12.0 - w.self);
    if (lo.node >= 0) t.emplace_back(id[j], id[lo.node % g.ny], -w.minus);
    if (hi.node >= 0) t.emplace_back(id[j], id[hi.node % g.ny], -w.plus);
  }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(a);
  const Eigen::VectorXd s = lu.solve(rhs);
  // Flux through the inlet: midpoint rule, or with the cut-face weights of
  // the exponential wall layer, as the continuity equations use them.
  double flux = s.sum() * g.hy;
  if (st.fitted()) {
    flux = 0.0;
    for (int j = 0; j < g.ny; ++j) {
      if (id[j] < 0) continue;
      const Stencils::FaceFlux f = st.face_flux(Component::kU, 0, j);
      flux += f.self * s[id[j]] * g.hy;
      if (f.other >= 0 && id[f.other % g.ny] >= 0) flux += f.other_weight * s[id[f.other % g.ny]] * g.hy;
    }
  }
  std::vector<double> profile(g.ny, 0.0);
  for (int j = 0; j < g.ny; ++j)
    if (id[j] >= 0) profile[j] = s[id[j]] * width / flux;
  return profile;
}

Assembler::Assembler(const ChannelGeometry& geo, const MacGrid& g, const MacMasks& m,
                     const std::vector<double>& inlet, bool exponential_wall_layer)
    : g_(g), m_(m), st_(geo, g, m, exponential_wall_layer), inlet_(inlet) {
  uid_.assign(g.u_count(), -1);
  vid_.assign(g.v_count(), -1);
  pid_.assign(g.cell_count(), -1);
  for (int k = 0; k < g.u_count(); ++k)
    if (m.u[k] == NodeKind::kUnknown) uid_[k] = n_++;
  for (int k = 0; k < g.v_count(); ++k)
    if (m.v[k] == NodeKind::kUnknown) vid_[k] = n_++;
  for (int k = 0; k < g.cell_count(); ++k)
    if (m.pressure[k]) pid_[k] = n_++;
  flux_u_.resize(g.u_count());
  flux_v_.resize(g.v_count());
  for (int i = 1; i <= g.nx; ++i)
    for (int j = 0; j < g.ny; ++j)
      if (uid_[g.u_index(i, j)] >= 0) flux_u_[g.u_index(i, j)] = st_.face_flux(Component::kU, i, j);
  if (exponential_wall_layer)  // inlet faces carry the same layer profile
    for (int j = 0; j < g.ny; ++j)
      if (m.u[g.u_index(0, j)] == NodeKind::kInlet)
        flux_u_[g.u_index(0, j)] = st_.face_flux(Component::kU, 0, j);
  for (int i = 0; i < g.nx; ++i)
    for (int j = 0; j <= g.ny; ++j)
      if (vid_[g.v_index(i, j)] >= 0) flux_v_[g.v_index(i, j)] = st_.face_flux(Component::kV, i, j);
}

void Assembler::assemble(const Eigen::VectorXd& advect, double inertia, Eigen::SparseMatrix<double>& a,
                         Eigen::VectorXd& rhs) const {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(n_) * 9);
  rhs.setZero(n_);
  for (int i = 0; i <= g_.nx; ++i)
    for (int j = 0; j < g_.ny; ++j) {
      const int r = uid_[g_.u_index(i, j)];
      if (r < 0) continue;
      const Eigen::Vector2d vel(advect[r], inertia > 0.0 ? v_around_u(advect, i, j) : 0.0);
      momentum_row(Component::kU, i, j, r, inertia * vel, t, rhs);
      if (i < g_.nx) {
        t.emplace_back(r, pid_[g_.cell_index(i, j)], 1.0 / g_.hx);
        t.emplace_back(r, pid_[g_.cell_index(i - 1, j)], -1.0 / g_.hx);
      } else {  // outlet face: p = 0 on x = L, half a cell from the last centre
        t.emplace_back(r, pid_[g_.cell_index(i - 1, j)], -2.0 / g_.hx);
      }
    }
  for (int i = 0; i < g_.nx; ++i)
    for (int j = 0; j <= g_.ny; ++j) {
      const int r = vid_[g_.v_index(i, j)];
      if (r < 0) continue;
      const Eigen::Vector2d vel(inertia > 0.0 ? u_around_v(advect, i, j) : 0.0, advect[r]);
      momentum_row(Component::kV, i, j, r, inertia * vel, t, rhs);
      t.emplace_back(r, pid_[g_.cell_index(i, j)], 1.0 / g_.hy);
      t.emplace_back(r, pid_[g_.cell_index(i, j - 1)], -1.0 / g_.hy);
    }
  // Continuity, written as -div u = 0 so that its block is minus the
  // transpose of the pressure gradient.
  for (int i = 0; i < g_.nx; ++i)
    for (int j = 0; j < g_.ny; ++j) {
      const int r = pid_[g_.cell_index(i, j)];
      if (r < 0) continue;
      const int e = g_.u_index(i + 1, j), w = g_.u_index(i, j);
      const int n = g_.v_index(i, j + 1), s = g_.v_index(i, j);
      add_flux(Component::kU, r, e, -1.0 / g_.hx, t, rhs);
      add_flux(Component::kU, r, w, 1.0 / g_.hx, t, rhs);
      add_flux(Component::kV, r, n, -1.0 / g_.hy, t, rhs);
      add_flux(Component::kV, r, s, 1.0 / g_.hy, t, rhs);
    }
  a.resize(n_, n_);
  a.setFromTriplets(t.begin(), t.end());
}

void Assembler::scatter(const Eigen::VectorXd& x, BrinkmanGridSolution& s) const {
  s.u.assign(g_.u_count(), 0.0);
  s.v.assign(g_.v_count(), 0.0);
  s.pressure.assign(g_.cell_count(), std::numeric_limits<double>::quiet_NaN());
  for (int k = 0; k < g_.u_count(); ++k)
    s.u[k] = uid_[k] >= 0 ? x[uid_[k]] : (m_.u[k] == NodeKind::kInlet ? inlet_[k % g_.ny] : 0.0);
  for (int k = 0; k < g_.v_count(); ++k)
    if (vid_[k] >= 0) s.v[k] = x[vid_[k]];
  for (int k = 0; k < g_.cell_count(); ++k)
    if (pid_[k] >= 0) s.pressure[k] = x[pid_[k]];
}

double Assembler::velocity_change(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
  const int nvel = n_ - static_cast<int>(std::count_if(pid_.begin(), pid_.end(),
                                                       [](int p) { return p >= 0; }));
  return (a.head(nvel) - b.head(nvel)).cwiseAbs().maxCoeff();
}

double Assembler::u_value(const Eigen::VectorXd& x, int node) const {
  if (uid_[node] >= 0) return x[uid_[node]];
  return m_.u[node] == NodeKind::kInlet ? inlet_[node % g_.ny] : 0.0;
}

double Assembler::v_value(const Eigen::VectorXd& x, int node) const {
  return vid_[node] >= 0 ? x[vid_[node]] : 0.0;
}

double Assembler::v_around_u(const Eigen::VectorXd& x, int i, int j) const {
  const int i0 = std::max(i - 1, 0), i1 = std::min(i, g_.nx - 1);
  return 0.25 * (v_value(x, g_.v_index(i0, j)) + v_value(x, g_.v_index(i1, j)) +
                 v_value(x, g_.v_index(i0, j + 1)) + v_value(x, g_.v_index(i1, j + 1)));
}

double Assembler::u_around_v(const Eigen::VectorXd& x, int i, int j) const {
  return 0.25 * (u_value(x, g_.u_index(i, j - 1)) + u_value(x, g_.u_index(i + 1, j - 1)) +
                 u_value(x, g_.u_index(i, j)) + u_value(x, g_.u_index(i + 1, j)));
}

void Assembler::add_u(int row, int node, double w, std::vector<Eigen::Triplet<double>>& t,
                      Eigen::VectorXd& rhs) const {
  if (uid_[node] >= 0)
    t.emplace_back(row, uid_[node], w);
  else if (m_.u[node] == NodeKind::kInlet)
    rhs[row] -= w * inlet_[node % g_.ny];
}

void Assembler::add_v(int row, int node, double w, std::vector<Eigen::Triplet<double>>& t,
                      Eigen::VectorXd&) const {
  if (vid_[node] >= 0) t.emplace_back(row, vid_[node], w);
}

void Assembler::add(Component c, int row, int node, double w, std::vector<Eigen::Triplet<double>>& t,
                    Eigen::VectorXd& rhs) const {
  if (node < 0) return;  // wall: value 0
  if (c == Component::kU)
    add_u(row, node, w, t, rhs);
  else
    add_v(row, node, w, t, rhs);
}

void Assembler::add_flux(Component c, int row, int node, double w, std::vector<Eigen::Triplet<double>>& t,
                         Eigen::VectorXd& rhs) const {
  const bool unknown = (c == Component::kU ? uid_[node] : vid_[node]) >= 0;
  const bool weighted_inlet =
      st_.fitted() && c == Component::kU && m_.u[node] == NodeKind::kInlet;
  if (!unknown && !weighted_inlet) {
    add(c, row, node, w, t, rhs);  // inlet value or nothing
    return;
  }
  const Stencils::FaceFlux& f = c == Component::kU ? flux_u_[node] : flux_v_[node];
  add(c, row, node, w * f.self, t, rhs);
  if (f.other >= 0) add(c, row, f.other, w * f.other_weight, t, rhs);
}

void Assembler::momentum_row(Component c, int i, int j, int row, const Eigen::Vector2d& advection,
                             std::vector<Eigen::Triplet<double>>& t, Eigen::VectorXd& rhs) const {
  const int self = st_.index(c, i, j);
  double diag = 12.0;
  for (int axis = 0; axis < 2; ++axis) {
    const int di = axis == 0 ? 1 : 0, dj = 1 - di;
    const Neighbour lo = st_.neighbour(c, i, j, -di, -dj);
    const Neighbour hi = st_.neighbour(c, i, j, di, dj);
    const LineWeights d2 = st_.second(c, i, j, axis, lo.dist, hi.dist);
    const LineWeights d1 = first_difference(lo.dist, hi.dist);
    const double a = advection[axis];
    diag += -d2.self + a * d1.self;
    add(c, row, lo.node, -d2.minus + a * d1.minus, t, rhs);
    add(c, row, hi.node, -d2.plus + a * d1.plus, t, rhs);
  }
  add(c, row, self, diag, t, rhs);
}

}  // namespace brinkman_grid
}  // namespace hsrod

#include "flow/brinkman_grid_solver.h"
#include "flow/line_stencils.h"

#include <Eigen/SparseCore>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseLU>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <thread>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace hsrod {
namespace {


enum class Component { kU, kV };

// Neighbour of a node along one grid direction: another node of the same
// component at distance `dist`, or the wall (node < 0, value 0) at `dist`.
struct Neighbour {
  double dist;
  int node;
};

class Stencils {
 public:
  Stencils(const ChannelGeometry& geo, const MacGrid& g, const MacMasks& m,
           bool exponential_wall_layer)
      : geo_(geo), g_(g), m_(m), fitted_(exponential_wall_layer) {}

  bool fitted() const { return fitted_; }

  // Decay rate [1/H] of the Brinkman wall layer along the unit direction
  // `line` at p: the layer decays as exp(-sqrt(12) n) in the wall distance n
  // (units of H; flow/README.md), i.e. at sqrt(12) |n_wall . line| along the
  // line. 0 without the exponential wall layer and beyond ten layer
  // thicknesses (exp(-10) = 5e-5), where the standard stencil is used.
  double layer_rate(const Eigen::Vector2d& p, const Eigen::Vector2d& line) const {
    if (!fitted_) return 0.0;
    const double k = std::sqrt(12.0);
    if (!(geo_.signed_distance(p.x(), p.y()) * k < 10.0)) return 0.0;
    return k * std::abs(geo_.wall_normal(p.x(), p.y()).dot(line));
  }

  Eigen::Vector2d position(Component c, int i, int j) const {
    return c == Component::kU ? g_.u_position(i, j) : g_.v_position(i, j);
  }
  int index(Component c, int i, int j) const {
    return c == Component::kU ? g_.u_index(i, j) : g_.v_index(i, j);
  }
  NodeKind kind(Component c, int node) const {
    return c == Component::kU ? m_.u[node] : m_.v[node];
  }

  // Neighbour of node (i, j) of component c in direction (di, dj), one of
  // (+-1, 0), (0, +-1). Handles the outlet (zero normal derivative: mirror
  // node), the inlet for v (v = 0 on x = 0) and walls crossed by the grid line
  // (exact distance from a ray cast).
  Neighbour neighbour(Component c, int i, int j, int di, int dj) const {
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

  // Flux through the face of node (i, j) as a combination of node values,
  // divided by the face length h. Where the face line crosses a wall within
  // h, the velocity along the line is taken linear in the distance from the
  // wall (the no-slip profile; exact for a linear near-wall profile), and
  // the fluid part of a neighbouring face whose centre lies in the wall is
  // carried by this face:
  //   no wall within h:       F/h = u_g                            (midpoint rule)
  //   wall at h/2 <= d < h:   F/h = [1 + (d - h/2)^2 / (2 d h)] u_g (neighbour sliver)
  //   wall at d < h/2:        F/h = (d + h/2)^2 / (2 h) * [w u_g / d + (1 - w) u_f / (d + h)]
  // In the last case the slope of the profile is taken from the node itself
  // and from the next node f along the line (distance d + h from the wall),
  // blended with w = 2d/h so that the weight of u_g stays bounded as d -> 0
  // (u_g is then a tiny value with an O(h^2) absolute error).
  struct FaceFlux {
    double self = 1.0;  // weight of the node's own value
    int other = -1;     // node f (same component), or -1
    double other_weight = 0.0;
  };
  FaceFlux face_flux(Component c, int i, int j) const {
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

  // face_flux with the exponential wall layer: the velocity along the face
  // line at distance s from the wall is taken as A phi(s), phi the layer
  // shape of line_stencils.h (decay rate layer_rate; linear for rate 0), A
  // fitted to the node value at distance d. The face [d - h/2, d + h/2]
  // plus the fluid sliver [0, d - h/2] of a neighbouring face whose centre
  // is in the wall carry F/h = Phi(d + h/2) / (h phi(d)); a face whose line
  // meets a wall within [h, 2h) carries [Phi(d + h/2) - Phi(d - h/2)] / (h
  // phi(d)). Close to the wall (d < h/2) A is blended with the next node's
  // estimate, as in face_flux.
  FaceFlux fitted_face_flux(Component c, int i, int j) const {
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

  // Second difference along `axis` (0: x, 1: y) at node (i, j) with
  // neighbours at distances a, b: Shortley-Weller, exponentially fitted to
  // the wall layer when that is on (line_stencils.h).
  LineWeights second(Component c, int i, int j, int axis, double a, double b) const {
    if (!fitted_) return second_difference(a, b);
    const Eigen::Vector2d line = axis == 0 ? Eigen::Vector2d(1, 0) : Eigen::Vector2d(0, 1);
    return fitted_second_difference(a, b, layer_rate(position(c, i, j), line));
  }

 private:
  const ChannelGeometry& geo_;
  const MacGrid& g_;
  const MacMasks& m_;
  bool fitted_;
};

// Developed inlet profile of the discrete operator: -u'' + 12 u = 1 along the
// inlet column with the same wall stencil, scaled to mean 1 over the width.
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

class Assembler {
 public:
  Assembler(const ChannelGeometry& geo, const MacGrid& g, const MacMasks& m,
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

  int size() const { return n_; }

  // Assembles the (Oseen-linearised) system; `advect` holds the previous
  // iterate (unknown vector) and `inertia` = (6/5) Re_H (0: Brinkman-Stokes).
  void assemble(const Eigen::VectorXd& advect, double inertia, Eigen::SparseMatrix<double>& a,
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

  // Scatters an unknown vector into per-node arrays.
  void scatter(const Eigen::VectorXd& x, BrinkmanGridSolution& s) const {
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

  // Largest change of the velocity unknowns (the pressure block is last).
  double velocity_change(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
    const int nvel = n_ - static_cast<int>(std::count_if(pid_.begin(), pid_.end(),
                                                         [](int p) { return p >= 0; }));
    return (a.head(nvel) - b.head(nvel)).cwiseAbs().maxCoeff();
  }

 private:
  double u_value(const Eigen::VectorXd& x, int node) const {
    if (uid_[node] >= 0) return x[uid_[node]];
    return m_.u[node] == NodeKind::kInlet ? inlet_[node % g_.ny] : 0.0;
  }
  double v_value(const Eigen::VectorXd& x, int node) const {
    return vid_[node] >= 0 ? x[vid_[node]] : 0.0;
  }
  // v interpolated to u node (i, j): mean of the four surrounding v nodes
  // (at the outlet the two inner ones, mirrored).
  double v_around_u(const Eigen::VectorXd& x, int i, int j) const {
    const int i0 = std::max(i - 1, 0), i1 = std::min(i, g_.nx - 1);
    return 0.25 * (v_value(x, g_.v_index(i0, j)) + v_value(x, g_.v_index(i1, j)) +
                   v_value(x, g_.v_index(i0, j + 1)) + v_value(x, g_.v_index(i1, j + 1)));
  }
  double u_around_v(const Eigen::VectorXd& x, int i, int j) const {
    return 0.25 * (u_value(x, g_.u_index(i, j - 1)) + u_value(x, g_.u_index(i + 1, j - 1)) +
                   u_value(x, g_.u_index(i, j)) + u_value(x, g_.u_index(i + 1, j)));
  }

  void add_u(int row, int node, double w, std::vector<Eigen::Triplet<double>>& t,
             Eigen::VectorXd& rhs) const {
    if (uid_[node] >= 0)
      t.emplace_back(row, uid_[node], w);
    else if (m_.u[node] == NodeKind::kInlet)
      rhs[row] -= w * inlet_[node % g_.ny];
  }
  void add_v(int row, int node, double w, std::vector<Eigen::Triplet<double>>& t,
             Eigen::VectorXd&) const {
    if (vid_[node] >= 0) t.emplace_back(row, vid_[node], w);
  }
  void add(Component c, int row, int node, double w, std::vector<Eigen::Triplet<double>>& t,
           Eigen::VectorXd& rhs) const {
    if (node < 0) return;  // wall: value 0
    if (c == Component::kU)
      add_u(row, node, w, t, rhs);
    else
      add_v(row, node, w, t, rhs);
  }

  // Flux of face `node` (weight w) into a continuity row; inlet values are
  // known, wall faces carry none.
  void add_flux(Component c, int row, int node, double w, std::vector<Eigen::Triplet<double>>& t,
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

  // -lap(u) + 12 u + (advection velocity) . grad u for one velocity node.
  void momentum_row(Component c, int i, int j, int row, const Eigen::Vector2d& advection,
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

  const MacGrid& g_;
  const MacMasks& m_;
  Stencils st_;
  const std::vector<double>& inlet_;  // inlet profile per row j [U]
  std::vector<int> uid_, vid_, pid_;
  std::vector<Stencils::FaceFlux> flux_u_, flux_v_;  // per fluid node (Stencils::face_flux)
  int n_ = 0;
};

// Eigen preconditioner interface around an existing sparse LU factorisation.
struct FrozenLuPreconditioner {
  const Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>>* lu = nullptr;
  template <class M>
  FrozenLuPreconditioner& analyzePattern(const M&) { return *this; }
  template <class M>
  FrozenLuPreconditioner& factorize(const M&) { return *this; }
  template <class M>
  FrozenLuPreconditioner& compute(const M&) { return *this; }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const { return lu->solve(b); }
  Eigen::ComputationInfo info() const { return Eigen::Success; }
};

using SparseLu = Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>>;

// A factorisation that may be abandoned: matrix and LU live in shared state
// so that a worker thread left running after a cancellation never touches
// freed memory (it finishes on its own; the process normally exits).
struct LuJob {
  Eigen::SparseMatrix<double> matrix;
  SparseLu lu;
  std::atomic<bool> done{false};
};

void report(const SolveControl& control, const std::string& what) {
  if (control.progress) control.progress(what);
}

void check_cancel(const SolveControl& control, const char* where) {
  if (control.cancel_requested && control.cancel_requested())
    throw FlowSolveCancelled(std::string("background-flow grid solve interrupted ") + where);
}

// Factorises job->matrix; with a cancel callback the factorisation runs in
// a worker thread while this thread polls the callback every 20 ms, so a
// request is honoured within ~20 ms even inside a long factorisation.
void factorise(const std::shared_ptr<LuJob>& job, const SolveControl& control) {
  if (!control.cancel_requested) {
    job->lu.compute(job->matrix);
    job->done = true;
    return;
  }
  std::thread worker([job] {
    job->lu.compute(job->matrix);
    job->done = true;
  });
  while (!job->done) {
    if (control.cancel_requested()) {
      worker.detach();
      throw FlowSolveCancelled(
          "background-flow grid solve interrupted during the sparse LU factorisation");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  worker.join();
}

}  // namespace

BrinkmanGridSolution solve_brinkman_on_grid(const ChannelGeometry& geo, const MacGrid& grid,
                                            const BrinkmanGridSettings& settings) {
  if (grid.nx < 2 || grid.ny < 2 || !(grid.hx > 0.0) || !(grid.hy > 0.0))
    throw std::invalid_argument("solve_brinkman_on_grid: need at least 2 x 2 cells");
  const SolveControl& control = settings.control;
  check_cancel(control, "before it started");
  BrinkmanGridSolution sol;
  sol.grid = grid;
  sol.masks = classify_mac_nodes(geo, grid);
  const bool fitted = settings.exponential_wall_layer;
  const Stencils stencils(geo, grid, sol.masks, fitted);
  const std::vector<double> inlet =
      discrete_inlet_profile(stencils, grid, sol.masks, geo.width());
  std::vector<double> inlet_by_node(inlet);  // indexed by j = node % ny for column 0
  check_cancel(control, "while classifying the grid");

  const Assembler asm_(geo, grid, sol.masks, inlet_by_node, fitted);
  sol.unknowns = asm_.size();
  Eigen::VectorXd rhs, x;
  // Brinkman-Stokes system: one sparse LU.
  auto stokes = std::make_shared<LuJob>();
  asm_.assemble(Eigen::VectorXd::Zero(asm_.size()), 0.0, stokes->matrix, rhs);
  check_cancel(control, "while assembling");
  {
    std::ostringstream msg;
    msg << "factorising the Brinkman system: " << grid.nx << " x " << grid.ny << " cells, "
        << sol.unknowns << " unknowns";
    report(control, msg.str());
  }
  factorise(stokes, control);
  const SparseLu& lu = stokes->lu;
  if (lu.info() != Eigen::Success)
    throw std::runtime_error("solve_brinkman_on_grid: sparse LU factorisation failed: " +
                             stokes->lu.lastErrorMessage());
  x = lu.solve(rhs);
  Eigen::SparseMatrix<double>& a = stokes->matrix;

  // Inertia: Picard (Oseen) iterations. Each Oseen system is solved by
  // BiCGSTAB preconditioned with the Brinkman-Stokes LU above (the advection
  // is a small perturbation at the cell Reynolds numbers of these scenes), so
  // no further factorisation is needed; a fresh LU is the fallback.
  const double inertia = 1.2 * settings.inertia_reynolds;  // (6/5) Re_H
  if (inertia > 0.0) {
    Eigen::BiCGSTAB<Eigen::SparseMatrix<double>, FrozenLuPreconditioner> krylov;
    krylov.preconditioner().lu = &lu;
    krylov.setTolerance(1e-3 * settings.picard_tolerance);
    krylov.setMaxIterations(200);
    for (int iter = 1; iter <= settings.max_picard_iterations; ++iter) {
      check_cancel(control, "during the Picard iterations");
      asm_.assemble(x, inertia, a, rhs);
      krylov.compute(a);
      Eigen::VectorXd next = krylov.solveWithGuess(rhs, x);
      if (krylov.info() != Eigen::Success) {
        auto oseen = std::make_shared<LuJob>();
        oseen->matrix = a;
        factorise(oseen, control);
        if (oseen->lu.info() != Eigen::Success)
          throw std::runtime_error("solve_brinkman_on_grid: Oseen factorisation failed: " +
                                   oseen->lu.lastErrorMessage());
        next = oseen->lu.solve(rhs);
      }
      sol.picard_iterations = iter;
      sol.picard_change = asm_.velocity_change(next, x);
      x = next;
      {
        std::ostringstream msg;
        msg << "Picard iteration " << iter << ": max velocity change " << sol.picard_change
            << " U (tolerance " << settings.picard_tolerance << ")";
        report(control, msg.str());
      }
      if (sol.picard_change < settings.picard_tolerance) break;
      if (iter == settings.max_picard_iterations) {
        std::ostringstream msg;
        msg << "solve_brinkman_on_grid: Picard iterations for the inertia term did not converge "
               "in "
            << iter << " iterations (last change " << sol.picard_change
            << " U, Re_H = " << settings.inertia_reynolds << ")";
        throw std::runtime_error(msg.str());
      }
    }
  }
  asm_.scatter(x, sol);
  return sol;
}

}  // namespace hsrod

#include "flow/brinkman_grid_solver.h"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace hsrod {
namespace {

// A wall closer to a node than this fraction of the cell is moved out to it:
// keeps the Shortley-Weller weights (~1/theta) bounded.
constexpr double kMinWallFraction = 1e-3;

enum class Component { kU, kV };

// Neighbour of a node along one grid direction: another node of the same
// component at distance `dist`, or the wall (node < 0, value 0) at `dist`.
struct Neighbour {
  double dist;
  int node;
};

class Stencils {
 public:
  Stencils(const ChannelGeometry& geo, const MacGrid& g, const MacMasks& m)
      : geo_(geo), g_(g), m_(m) {}

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

 private:
  const ChannelGeometry& geo_;
  const MacGrid& g_;
  const MacMasks& m_;
};

// Shortley-Weller second difference along one line with neighbours at
// distances a (minus side) and b (plus side):
//   u'' = 2/(a+b) [(u_p - u_0)/b - (u_0 - u_m)/a]
// and the matching three-point first difference (exact for quadratics)
//   u'  = [(u_p - u_0) a/b + (u_0 - u_m) b/a] / (a+b).
struct LineWeights {
  double minus, self, plus;
};
LineWeights second_difference(double a, double b) {
  const double wm = 2.0 / (a * (a + b)), wp = 2.0 / (b * (a + b));
  return {wm, -(wm + wp), wp};
}
LineWeights first_difference(double a, double b) {
  return {-b / (a * (a + b)), (b - a) / (a * b), a / (b * (a + b))};
}

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
    const LineWeights w = second_difference(lo.dist, hi.dist);
    t.emplace_back(id[j], id[j], 12.0 - w.self);
    if (lo.node >= 0) t.emplace_back(id[j], id[lo.node % g.ny], -w.minus);
    if (hi.node >= 0) t.emplace_back(id[j], id[hi.node % g.ny], -w.plus);
  }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(a);
  const Eigen::VectorXd s = lu.solve(rhs);
  const double flux = s.sum() * g.hy;
  std::vector<double> profile(g.ny, 0.0);
  for (int j = 0; j < g.ny; ++j)
    if (id[j] >= 0) profile[j] = s[id[j]] * width / flux;
  return profile;
}

class Assembler {
 public:
  Assembler(const ChannelGeometry& geo, const MacGrid& g, const MacMasks& m,
            const std::vector<double>& inlet)
      : g_(g), m_(m), st_(geo, g, m), inlet_(inlet) {
    uid_.assign(g.u_count(), -1);
    vid_.assign(g.v_count(), -1);
    pid_.assign(g.cell_count(), -1);
    for (int k = 0; k < g.u_count(); ++k)
      if (m.u[k] == NodeKind::kUnknown) uid_[k] = n_++;
    for (int k = 0; k < g.v_count(); ++k)
      if (m.v[k] == NodeKind::kUnknown) vid_[k] = n_++;
    for (int k = 0; k < g.cell_count(); ++k)
      if (m.pressure[k]) pid_[k] = n_++;
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
        add_u(r, g_.u_index(i + 1, j), -1.0 / g_.hx, t, rhs);
        add_u(r, g_.u_index(i, j), 1.0 / g_.hx, t, rhs);
        add_v(r, g_.v_index(i, j + 1), -1.0 / g_.hy, t, rhs);
        add_v(r, g_.v_index(i, j), 1.0 / g_.hy, t, rhs);
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

  // -lap(u) + 12 u + (advection velocity) . grad u for one velocity node.
  void momentum_row(Component c, int i, int j, int row, const Eigen::Vector2d& advection,
                    std::vector<Eigen::Triplet<double>>& t, Eigen::VectorXd& rhs) const {
    const int self = st_.index(c, i, j);
    double diag = 12.0;
    for (int axis = 0; axis < 2; ++axis) {
      const int di = axis == 0 ? 1 : 0, dj = 1 - di;
      const Neighbour lo = st_.neighbour(c, i, j, -di, -dj);
      const Neighbour hi = st_.neighbour(c, i, j, di, dj);
      const LineWeights d2 = second_difference(lo.dist, hi.dist);
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
  int n_ = 0;
};

}  // namespace

BrinkmanGridSolution solve_brinkman_on_grid(const ChannelGeometry& geo, const MacGrid& grid,
                                            const BrinkmanGridSettings& settings) {
  if (grid.nx < 2 || grid.ny < 2 || !(grid.hx > 0.0) || !(grid.hy > 0.0))
    throw std::invalid_argument("solve_brinkman_on_grid: need at least 2 x 2 cells");
  BrinkmanGridSolution sol;
  sol.grid = grid;
  sol.masks = classify_mac_nodes(geo, grid);
  const Stencils stencils(geo, grid, sol.masks);
  const std::vector<double> inlet =
      discrete_inlet_profile(stencils, grid, sol.masks, geo.width());
  std::vector<double> inlet_by_node(inlet);  // indexed by j = node % ny for column 0

  const Assembler asm_(geo, grid, sol.masks, inlet_by_node);
  sol.unknowns = asm_.size();
  Eigen::SparseMatrix<double> a;
  Eigen::VectorXd rhs, x = Eigen::VectorXd::Zero(asm_.size());
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;

  const double inertia = 1.2 * settings.inertia_reynolds;  // (6/5) Re_H
  const int max_iter = inertia > 0.0 ? std::max(1, settings.max_picard_iterations) : 0;
  for (int iter = 0; iter <= max_iter; ++iter) {
    asm_.assemble(x, iter == 0 ? 0.0 : inertia, a, rhs);
    if (iter == 0) lu.analyzePattern(a);
    lu.factorize(a);
    if (lu.info() != Eigen::Success)
      throw std::runtime_error("solve_brinkman_on_grid: sparse LU factorisation failed: " +
                               lu.lastErrorMessage());
    const Eigen::VectorXd next = lu.solve(rhs);
    if (iter > 0) {
      sol.picard_iterations = iter;
      sol.picard_change = asm_.velocity_change(next, x);
    }
    x = next;
    if (iter > 0 && sol.picard_change < settings.picard_tolerance) break;
    if (iter == max_iter && max_iter > 0) {
      std::ostringstream msg;
      msg << "solve_brinkman_on_grid: Picard iterations for the inertia term did not converge in "
          << max_iter << " iterations (last change " << sol.picard_change
          << " U, Re_H = " << settings.inertia_reynolds << ")";
      throw std::runtime_error(msg.str());
    }
  }
  asm_.scatter(x, sol);
  return sol;
}

}  // namespace hsrod

// The depth-averaged Brinkman (Stokes-Brinkman) operator on a small window
// of the planform, for the disturbance a rod makes in the background flow
// (level 4 of the fidelity ladder, hydro/twoway_window_model.h).
//
// Solves, for the disturbance velocity u' (gap-averaged) and pressure p',
//     mu lap(u') - (12 mu / H^2) u' - grad p' + f = 0,   div u' = 0,
// with f [N/m^3] a force density given per velocity node, u' = 0 on the walls
// and obstacles of the scene that cross the window and on the window's own
// edges (the disturbance is taken to have decayed there; the window margin
// sets that error, measured in tests/drag-models/hydro). Discretisation as
// the background solver (brinkman_grid_solver.h): MAC grid, Shortley-Weller
// no-slip at the true wall position; faces are closed where their node lies
// in a wall (first order at curved walls, enough for a disturbance). The
// system depends on the window and the walls only, so it is factorised once
// per window placement and reused for any number of right-hand sides.
#pragma once

#include "flow/sparse_lu_factors.h"
#include "geometry/channel_geometry.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <vector>

namespace hsrod {

// A window of the planform: nx x ny cells, lower left corner (x0, y0) [m].
// Uniform (x_faces, y_faces empty): square cells of size h [m]. Graded:
// cell faces at x_faces[0..nx], y_faces[0..ny] [m] (increasing, first =
// x0, y0), e.g. cells of size h near the rod growing geometrically towards
// the window's edges (hydro/twoway_window_model.h); h is then the finest
// cell. Nodes as in mac_grid.h: u(i, j) at (x face i, y centre j), v(i, j)
// at (x centre i, y face j).
struct WindowLattice {
  double x0 = 0.0, y0 = 0.0;  // m
  double h = 0.0;             // m
  int nx = 0, ny = 0;
  std::vector<double> x_faces, y_faces;  // m; empty: uniform
  bool graded() const { return !x_faces.empty() || !y_faces.empty(); }
  double x_face(int i) const { return x_faces.empty() ? x0 + i * h : x_faces[i]; }
  double y_face(int j) const { return y_faces.empty() ? y0 + j * h : y_faces[j]; }
  double x_centre(int i) const { return 0.5 * (x_face(i) + x_face(i + 1)); }
  double y_centre(int j) const { return 0.5 * (y_face(j) + y_face(j + 1)); }
  double dx(int i) const { return x_face(i + 1) - x_face(i); }  // cell width [m]
  double dy(int j) const { return y_face(j + 1) - y_face(j); }
  double x1() const { return x_face(nx); }  // upper corner [m]
  double y1() const { return y_face(ny); }
  Eigen::Vector2d u_position(int i, int j) const { return {x_face(i), y_centre(j)}; }
  Eigen::Vector2d v_position(int i, int j) const { return {x_centre(i), y_face(j)}; }
  // Fractional index of x [m] among the x faces (i at face i, linear in
  // between; beyond the window, continued with the edge cell), and among the
  // cell centres (i at centre i; -1/2 and nx - 1/2 at the window edges).
  double x_face_index(double x) const;
  double y_face_index(double y) const;
  double x_centre_index(double x) const;
  double y_centre_index(double y) const;
  // The same lattice moved by (dx, dy) [m].
  WindowLattice shifted(double dx, double dy) const;
  bool operator==(const WindowLattice& o) const {
    return x0 == o.x0 && y0 == o.y0 && h == o.h && nx == o.nx && ny == o.ny && x_faces == o.x_faces &&
           y_faces == o.y_faces;
  }
};

// One velocity unknown of the window system.
struct WindowNode {
  Eigen::Vector2d position;  // m
  int component = 0;         // 0: u (x-velocity), 1: v (y-velocity)
  int unknown = -1;          // row/column in the system
};

class BrinkmanWindow {
 public:
  // Factorises the window system. Throws std::invalid_argument for a lattice
  // with fewer than 3 x 3 cells or a non-positive cell size or viscosity,
  // std::runtime_error if the factorisation fails.
  BrinkmanWindow(const ChannelGeometry& geometry, const WindowLattice& lattice, double viscosity);
  BrinkmanWindow(const BrinkmanWindow&) = default;

  const WindowLattice& lattice() const { return lattice_; }
  // Fluid velocity nodes (the unknowns), u nodes first.
  const std::vector<WindowNode>& nodes() const { return nodes_; }
  int unknowns() const { return unknowns_; }
  // Index into nodes() of the fluid velocity nodes of one component within
  // `radius` [m] of `centre` [m].
  std::vector<int> nodes_near(const Eigen::Vector2d& centre, double radius, int component) const;

  // True when a wall or obstacle crosses the window. A window without one is
  // the same system wherever it lies: translated() reuses its factorisation.
  bool has_walls() const { return has_walls_; }
  // This window moved by (dx, dy) [m], sharing the factorisation. Only for
  // windows without walls (std::logic_error otherwise), and the caller must
  // know the translated window is wall-free too; with `walls_move_along`
  // the caller states that the walls are the same relative to the moved
  // window (a straight channel's side walls for a move along x).
  BrinkmanWindow translated(double dx, double dy, bool walls_move_along = false) const;

  // Disturbance velocities [m/s] at all nodes() for each column of
  // `node_forces`: the force [N] applied to the fluid at each node (rows as
  // nodes()), spread uniformly over the node's control area (the cell
  // spacings around it) and the gap height.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& node_forces) const;
  // The same for forces given by their non-zeros (column c: (node, force
  // [N]) pairs, nodes distinct), returning the velocities [m/s] only at
  // `at_nodes` (rows as at_nodes, one column per force column): bit for bit
  // the rows of solve(), without its dense window-sized matrices (a level-4
  // update needs the response at the spheres' footprints only).
  using NodeForces = std::vector<std::pair<int, double>>;
  Eigen::MatrixXd solve_at(const std::vector<NodeForces>& node_forces, const std::vector<int>& at_nodes) const;
  // Weighted means of the velocities for forces given as in solve_at:
  // out(r, c) = sum_k weight_k u_c(node_k) over the (node, weight) pairs of
  // `read_weights[r]` (nodes distinct within each), for every force column
  // c. The same values as weighting the rows of solve_at to round-off, at a
  // fraction of its work for footprints (SparseLuFactors::bilinear: no
  // back-substitution over the whole window).
  Eigen::MatrixXd weighted_response(const std::vector<NodeForces>& node_forces,
                                    const std::vector<NodeForces>& read_weights) const;

  // Read access for field output (flow/window_flow_field.h).
  // Unknown of the u node (i, j), 0 <= i <= nx, 0 <= j < ny, and of the v
  // node (i, j), 0 <= i < nx, 0 <= j <= ny; -1 for nodes in walls, on the
  // window edges or off the lattice.
  int u_unknown(int i, int j) const;
  int v_unknown(int i, int j) const;
  // As solve() for one force column, also returning the disturbance pressure
  // p' [Pa] per cell (index i * ny + j, centre (x_centre(i),
  // y_centre(j))), NaN in cells without an open face. p' is fixed to 0
  // at the first such cell of each closed fluid region (the system's
  // gauge).
  Eigen::VectorXd solve_with_pressure(const Eigen::VectorXd& node_forces, std::vector<double>& cell_pressure) const;

 private:
  WindowLattice lattice_;
  double gap_height_;  // H [m]
  double viscosity_;   // mu [Pa s]
  std::vector<WindowNode> nodes_;
  std::vector<int> u_unknown_, v_unknown_;  // per lattice node, -1 if not fluid
  std::vector<int> pressure_unknown_;        // per cell (i * ny + j), -1 without an open face
  Eigen::VectorXd force_scale_;          // per unknown: H / (mu A), A its control area [m/(N s)]
  int unknowns_ = 0;
  bool has_walls_ = false;
  // Sparse LU (SuiteSparse UMFPACK, flow/sparse_lu_factors.h): on the pore
  // scene's graded windows (27-29k unknowns) 3-4x faster to factorise than
  // KLU with COLAMD and 9-10x faster than KLU with AMD, with residuals
  // ~1e-14 where KLU's reached 1e-5..3e-3; its 2n right-hand sides are
  // solved as one block (flow/README.md). Shared by a window's copies and
  // translations.
  using Factorisation = SparseLuFactors;
  std::shared_ptr<const Factorisation> lu_;

  // Assembly of the system, phase by phase (the constructor).
  static void check_lattice(const WindowLattice& lattice);
  void number_unknowns(const ChannelGeometry& geometry);
  void add_momentum_row(const ChannelGeometry& geometry, int row, const Eigen::Vector2d& position, int component, int i,
                        int j, std::vector<Eigen::Triplet<double>>& triplets);
  void add_momentum_rows(const ChannelGeometry& geometry, std::vector<Eigen::Triplet<double>>& triplets);
  void add_continuity_rows(std::vector<Eigen::Triplet<double>>& triplets) const;
  // Indices of u nodes ((nx+1) x ny), v nodes (nx x (ny+1)) and cells (nx x ny).
  int u_index(int i, int j) const { return i * lattice_.ny + j; }
  int v_index(int i, int j) const { return i * (lattice_.ny + 1) + j; }
  int cell_index(int i, int j) const { return i * lattice_.ny + j; }
};

}  // namespace hsrod

// Staggered (MAC, Harlow & Welch 1965) grid over the channel planform, in the
// dimensionless units of the grid solver: lengths in units of the gap height
// H, origin at the lower corner (x_lo, y_lo) of the planform.
//
//   pressure p(i, j):  cell centres ((i + 1/2) hx, (j + 1/2) hy), i < nx, j < ny
//   u(i, j):           x-faces      (i hx, (j + 1/2) hy),         i <= nx, j < ny
//   v(i, j):           y-faces      ((i + 1/2) hx, j hy),         i < nx, j <= ny
//
// Column i = 0 of u is the inlet, i = nx the outlet; rows j = 0 and j = ny of
// v lie on the side walls.
#pragma once

#include "geometry/channel_geometry.h"

#include <Eigen/Core>

#include <vector>

namespace hsrod {

struct MacGrid {
  int nx = 0;       // cells along x [-]
  int ny = 0;       // cells along y [-]
  double hx = 0.0;  // cell size along x [H]
  double hy = 0.0;  // cell size along y [H]

  int u_count() const { return (nx + 1) * ny; }
  int v_count() const { return nx * (ny + 1); }
  int cell_count() const { return nx * ny; }
  int u_index(int i, int j) const { return i * ny + j; }
  int v_index(int i, int j) const { return i * (ny + 1) + j; }
  int cell_index(int i, int j) const { return i * ny + j; }
  Eigen::Vector2d u_position(int i, int j) const { return {i * hx, (j + 0.5) * hy}; }
  Eigen::Vector2d v_position(int i, int j) const { return {(i + 0.5) * hx, j * hy}; }
};

// Role of a velocity node in the discrete problem.
enum class NodeKind : unsigned char {
  kWall,     // in a wall or obstacle (or cut off from the outlet): value 0
  kInlet,    // inlet face: the developed profile is imposed
  kUnknown,  // fluid node: a momentum equation and an unknown
};

// Which nodes are fluid, inlet or wall, and which cells carry a pressure.
struct MacMasks {
  std::vector<NodeKind> u;    // per u node
  std::vector<NodeKind> v;    // per v node
  std::vector<char> pressure;  // per cell: 1 if the cell has a pressure unknown
};

// Classifies the nodes of `grid` over `scaled_geometry` (the planform in units
// of H with its lower corner at the origin): a velocity node is a fluid
// unknown when its own position lies in the fluid (signed distance >
// 1e-6 cell), a cell has a pressure when one of its faces is a fluid or inlet
// node; nodes and cells not connected to the outlet through fluid faces are
// turned into walls (closed pockets would leave the pressure undetermined).
MacMasks classify_mac_nodes(const ChannelGeometry& scaled_geometry, const MacGrid& grid);

}  // namespace hsrod

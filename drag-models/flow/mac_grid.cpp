#include "flow/mac_grid.h"

#include <algorithm>
#include <deque>
#include <stdexcept>

namespace hsrod {

MacMasks classify_mac_nodes(const ChannelGeometry& geo, const MacGrid& g) {
  const double eps = 1e-6 * std::min(g.hx, g.hy);
  MacMasks m;
  m.u.assign(g.u_count(), NodeKind::kWall);
  m.v.assign(g.v_count(), NodeKind::kWall);
  m.pressure.assign(g.cell_count(), 0);

  auto fluid = [&](const Eigen::Vector2d& p) { return geo.signed_distance(p.x(), p.y()) > eps; };
  for (int i = 0; i <= g.nx; ++i)
    for (int j = 0; j < g.ny; ++j)
      if (fluid(g.u_position(i, j)))
        m.u[g.u_index(i, j)] = i == 0 ? NodeKind::kInlet : NodeKind::kUnknown;
  for (int i = 0; i < g.nx; ++i)
    for (int j = 1; j < g.ny; ++j)  // rows 0 and ny lie on the side walls
      if (fluid(g.v_position(i, j))) m.v[g.v_index(i, j)] = NodeKind::kUnknown;

  // Cells adjacent to a fluid face carry a pressure and a continuity equation.
  for (int i = 0; i <= g.nx; ++i)
    for (int j = 0; j < g.ny; ++j) {
      if (m.u[g.u_index(i, j)] == NodeKind::kWall) continue;
      if (i > 0) m.pressure[g.cell_index(i - 1, j)] = 1;
      if (i < g.nx) m.pressure[g.cell_index(i, j)] = 1;
    }
  for (int i = 0; i < g.nx; ++i)
    for (int j = 1; j < g.ny; ++j) {
      if (m.v[g.v_index(i, j)] == NodeKind::kWall) continue;
      m.pressure[g.cell_index(i, j - 1)] = 1;
      m.pressure[g.cell_index(i, j)] = 1;
    }

  // Keep only what is connected to the outlet (breadth-first over fluid faces).
  std::vector<char> reached(g.cell_count(), 0);
  std::deque<int> queue;
  for (int j = 0; j < g.ny; ++j)
    if (m.u[g.u_index(g.nx, j)] == NodeKind::kUnknown) {
      reached[g.cell_index(g.nx - 1, j)] = 1;
      queue.push_back(g.cell_index(g.nx - 1, j));
    }
  while (!queue.empty()) {
    const int c = queue.front();
    queue.pop_front();
    const int i = c / g.ny, j = c % g.ny;
    auto visit = [&](bool open, int ni, int nj) {
      if (!open) return;
      const int n = g.cell_index(ni, nj);
      if (!reached[n]) {
        reached[n] = 1;
        queue.push_back(n);
      }
    };
    visit(i > 0 && m.u[g.u_index(i, j)] == NodeKind::kUnknown, i - 1, j);
    visit(i + 1 < g.nx && m.u[g.u_index(i + 1, j)] == NodeKind::kUnknown, i + 1, j);
    visit(j > 0 && m.v[g.v_index(i, j)] == NodeKind::kUnknown, i, j - 1);
    visit(j + 1 < g.ny && m.v[g.v_index(i, j + 1)] == NodeKind::kUnknown, i, j + 1);
  }
  for (int i = 0; i < g.nx; ++i)
    for (int j = 0; j < g.ny; ++j) {
      const int c = g.cell_index(i, j);
      if (reached[c] || !m.pressure[c]) continue;
      m.pressure[c] = 0;
      if (m.u[g.u_index(i, j)] == NodeKind::kInlet)
        throw std::logic_error("classify_mac_nodes: an inlet cell is cut off from the outlet");
      m.u[g.u_index(i, j)] = NodeKind::kWall;
      m.u[g.u_index(i + 1, j)] = NodeKind::kWall;
      m.v[g.v_index(i, j)] = NodeKind::kWall;
      m.v[g.v_index(i, j + 1)] = NodeKind::kWall;
    }
  return m;
}

}  // namespace hsrod

// Level 4's per-rod state as restart data (window placements, stored
// resistances, shared wall-free windows), and its work summary.
#include "hydro/twoway_window_model.h"

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace hsrod {

std::string TwoWayWindowState::work_summary() const {
  const TwoWayWindowStatistics& s = statistics;
  char line[320];
  std::snprintf(line, sizeof(line),
                "twoway: %ld evaluations, %ld resistance updates (%.3g s of solves), %ld window placements, "
                "%ld factorisations (%.3g s), last window %d cells of %.3g m",
                s.evaluations, s.updates, s.solve_seconds, s.placements, s.factorisations, s.factorisation_seconds,
                s.last_window_cells, spacing);
  return line;
}

namespace {
void put_lattice(std::vector<double>& out, const WindowLattice& g) {
  out.insert(out.end(), {g.x0, g.y0, g.h, static_cast<double>(g.nx), static_cast<double>(g.ny), g.graded() ? 1.0 : 0.0});
  if (!g.graded()) return;
  for (int i = 0; i <= g.nx; ++i) out.push_back(g.x_face(i));
  for (int j = 0; j <= g.ny; ++j) out.push_back(g.y_face(j));
}

// Reads the restart data back in order; throws on running past its end.
struct Reader {
  const std::vector<double>& data;
  std::size_t at = 0;
  double next() {
    if (at >= data.size()) throw std::invalid_argument("twoway: restart data ends early");
    return data[at++];
  }
  int integer() { return static_cast<int>(next()); }
  WindowLattice lattice() {
    WindowLattice g;
    g.x0 = next();
    g.y0 = next();
    g.h = next();
    g.nx = integer();
    g.ny = integer();
    if (next() != 0.0) {
      if (g.nx < 0 || g.ny < 0 || data.size() - at < static_cast<std::size_t>(g.nx) + g.ny + 2)
        throw std::invalid_argument("twoway: restart data ends early");
      for (int i = 0; i <= g.nx; ++i) g.x_faces.push_back(next());
      for (int j = 0; j <= g.ny; ++j) g.y_faces.push_back(next());
    }
    return g;
  }
};
constexpr double kStateTag = 4.0;  // first number: the model level that wrote the data
}  // namespace

std::vector<double> TwoWayWindowModel::save_state(const ModelState& base) const {
  const auto& state = dynamic_cast<const TwoWayWindowState&>(base);
  std::vector<double> out{kStateTag, static_cast<double>(state.free_windows.size())};
  for (const auto& entry : state.free_windows) put_lattice(out, entry.second->lattice());
  out.push_back(static_cast<double>(state.rods.size()));
  for (const auto& entry : state.rods) {
    const RodState& rod = entry.second;
    const int n = static_cast<int>(rod.solved_positions.size());
    out.insert(out.end(), {static_cast<double>(entry.first), rod.window ? 1.0 : 0.0, rod.translated ? 1.0 : 0.0});
    put_lattice(out, rod.placed);
    out.insert(out.end(), {static_cast<double>(n), static_cast<double>(rod.evaluations_since_update)});
    for (const auto& x : rod.solved_positions) out.insert(out.end(), {x.x(), x.y(), x.z()});
    for (int k = 0; k < rod.obstruction.size(); ++k) out.push_back(rod.obstruction.data()[k]);
  }
  const TwoWayWindowStatistics& s = state.statistics;
  out.insert(out.end(), {static_cast<double>(s.evaluations), static_cast<double>(s.updates),
                         static_cast<double>(s.placements), static_cast<double>(s.factorisations),
                         static_cast<double>(s.last_window_cells), s.factorisation_seconds, s.solve_seconds});
  return out;
}

void TwoWayWindowModel::restore_state(ModelState& base, const std::vector<double>& data,
                                      const BackgroundFlow& flow) const {
  auto& state = dynamic_cast<TwoWayWindowState&>(base);
  Reader in{data};
  if (in.next() != kStateTag) throw std::invalid_argument("twoway: restart data from another model");
  const ChannelGeometry& geometry = flow.geometry();
  state.rods.clear();
  state.free_windows.clear();
  for (int count = in.integer(); count > 0; --count) {
    const WindowLattice g = in.lattice();
    state.free_windows[{g.nx, g.ny}] = std::make_shared<const BrinkmanWindow>(geometry, g, parameters_.viscosity);
  }
  for (int count = in.integer(); count > 0; --count) {
    RodState& rod = state.rods[in.integer()];
    const bool has_window = in.next() != 0.0;
    rod.translated = in.next() != 0.0;
    rod.placed = in.lattice();
    const int n = in.integer();
    rod.evaluations_since_update = in.integer();
    rod.solved_positions.resize(n);
    for (auto& x : rod.solved_positions)
      for (int a = 0; a < 3; ++a) x[a] = in.next();
    rod.obstruction.resize(2 * n, 2 * n);
    for (int k = 0; k < rod.obstruction.size(); ++k) rod.obstruction.data()[k] = in.next();
    if (!has_window) continue;
    // Rebuilt as it was built: a translation of the shared wall-free window, or its own factorisation.
    const auto cached = state.free_windows.find({rod.placed.nx, rod.placed.ny});
    if (rod.translated && cached != state.free_windows.end()) {
      const WindowLattice& g = cached->second->lattice();
      rod.window = std::make_unique<BrinkmanWindow>(cached->second->translated(
          rod.placed.x0 - g.x0, rod.placed.y0 - g.y0, cached->second->has_walls()));
    } else {
      rod.window = std::make_unique<BrinkmanWindow>(geometry, rod.placed, parameters_.viscosity);
    }
  }
  TwoWayWindowStatistics& s = state.statistics;
  s.evaluations = static_cast<long>(in.next());
  s.updates = static_cast<long>(in.next());
  s.placements = static_cast<long>(in.next());
  s.factorisations = static_cast<long>(in.next());
  s.last_window_cells = in.integer();
  s.factorisation_seconds = in.next();
  s.solve_seconds = in.next();
  if (in.at != data.size()) throw std::invalid_argument("twoway: restart data longer than expected");
}

std::unique_ptr<ModelState> TwoWayWindowModel::make_state() const {
  auto state = std::make_unique<TwoWayWindowState>();
  state->spacing = window_spacing_;
  return state;
}

}  // namespace hsrod

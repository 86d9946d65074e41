#include "screen_scene.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>

namespace hsrod::screen {
namespace {
std::map<LAMMPS_NS::LAMMPS *, ScreenState *> &states() {
  static std::map<LAMMPS_NS::LAMMPS *, ScreenState *> registry;
  return registry;
}
}  // namespace

ScreenState *state_of(LAMMPS_NS::LAMMPS *lmp) {
  const auto it = states().find(lmp);
  return it == states().end() ? nullptr : it->second;
}

void set_state(LAMMPS_NS::LAMMPS *lmp, ScreenState *state) {
  if (state)
    states()[lmp] = state;
  else
    states().erase(lmp);
}

SceneFile read_scene_file(const std::string &path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("hsrod screen: cannot open scene file '" + path + "'");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const std::exception &e) {
    throw std::runtime_error("hsrod screen: scene file '" + path + "' is not JSON: " + e.what());
  }
  SceneFile s;
  s.path = path;
  const auto need = [&](const nlohmann::json &node, const char *key, const std::string &where) -> const nlohmann::json & {
    if (!node.contains(key)) throw std::runtime_error("hsrod screen: scene file '" + path + "' lacks " + where + key);
    return node.at(key);
  };
  if (j.contains("fluid")) {
    const auto &f = j["fluid"];
    s.fluid_density = f.value("rho", s.fluid_density);
    if (f.contains("mu")) s.viscosity = f["mu"].get<double>();
    else if (f.contains("nu")) s.viscosity = f["nu"].get<double>() * s.fluid_density;
  }
  const auto &inflow = need(j, "inflow", "");
  if (inflow.value("type", std::string("meanVelocity")) != "meanVelocity")
    throw std::runtime_error("hsrod screen: scene file '" + path + "': inflow type must be meanVelocity");
  s.mean_velocity = need(inflow, "U", "inflow.").get<double>();
  if (!(s.mean_velocity > 0.0))
    throw std::runtime_error("hsrod screen: scene file '" + path + "': inflow.U must be > 0 m/s");
  if (j.contains("pore")) {
    s.has_pore = true;
    s.pore_radius = need(j["pore"], "R", "pore.").get<double>();
    s.pore_x = need(j["pore"], "x", "pore.").get<double>();
  }
  if (j.contains("control")) s.end_time = j["control"].value("end_time", 0.0);
  // Resolved cells (an estimate, the mesh is made later by the case's
  // Allrun): the base mesh (nx ny nz, or cell size h over the channel) plus,
  // with "refine" {levels, margin} and a "rod", the refined box around the
  // rod (rod bounding box + margin, cells h / 2^levels) replacing its base cells.
  if (j.contains("mesh") && j.contains("channel")) {
    const auto &m = j["mesh"];
    const auto &c = j["channel"];
    const double L = c.value("L", 0.0), W = c.value("W", 0.0), H = c.value("H", 0.0);
    double h = 0.0;
    if (m.contains("nx")) {
      s.cells = m.value("nx", 0L) * m.value("ny", 0L) * m.value("nz", 0L);
      h = L / std::max(1L, m.value("nx", 1L));
    } else if (m.contains("h")) {
      h = m["h"].get<double>();
      s.cells = static_cast<long>(std::ceil(L / h) * std::ceil(W / h) * std::ceil(H / h));
    }
    if (h > 0.0 && j.contains("refine") && j.contains("rod")) {
      const int levels = j["refine"].value("levels", 0);
      const double margin = j["refine"].value("margin", 0.0);
      const double d = j["rod"].value("d", 0.0);
      const double n = j["rod"].value("n", 1.0);
      const double box = (n * d + 2 * margin) * (d + 2 * margin) * std::min(H, d + 2 * margin);
      const double fine = h / std::pow(2.0, levels);
      s.cells += static_cast<long>(box / (fine * fine * fine) - box / (h * h * h));
    }
  }
  if (j.contains("screen")) {
    s.reduced_dt = j["screen"].value("dt", s.reduced_dt);
    s.reduced_t_max = j["screen"].value("t_max", 0.0);
  }
  return s;
}

}  // namespace hsrod::screen

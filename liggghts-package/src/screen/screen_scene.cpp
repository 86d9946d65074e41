#include "screen_scene.h"

#include "flow/inflow.h"

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
  const std::string file = "hsrod screen: scene file '" + path + "': ";
  // Every value through these: a missing required key, a value of another
  // type or a non-finite number is named with its file and key (the JSON
  // library's own type_error.302 named neither).
  const auto has = [](const nlohmann::json &node, const char *key) { return node.is_object() && node.contains(key); };
  const auto number = [&](const nlohmann::json &node, const char *key, const std::string &where,
                          const double *fallback) {
    if (!has(node, key)) {
      if (fallback) return *fallback;
      throw std::runtime_error("hsrod screen: scene file '" + path + "' lacks " + where + key);
    }
    const nlohmann::json &v = node.at(key);
    if (!v.is_number())
      throw std::runtime_error(file + where + key + " must be a number, got " + v.type_name() + " " + v.dump());
    const double x = v.get<double>();
    if (!std::isfinite(x)) throw std::runtime_error(file + where + key + " must be a finite number");
    return x;
  };
  const auto required = [&](const nlohmann::json &node, const char *key, const std::string &where) {
    return number(node, key, where, nullptr);
  };
  const auto optional = [&](const nlohmann::json &node, const char *key, const std::string &where, double fallback) {
    return number(node, key, where, &fallback);
  };
  SceneFile s;
  s.path = path;
  if (has(j, "fluid")) {
    const auto &f = j["fluid"];
    s.fluid_density = optional(f, "rho", "fluid.", s.fluid_density);
    if (has(f, "mu")) s.viscosity = required(f, "mu", "fluid.");
    else if (has(f, "nu")) s.viscosity = required(f, "nu", "fluid.") * s.fluid_density;
    if (!(s.fluid_density > 0.0 && s.viscosity > 0.0))
      throw std::runtime_error(file + "fluid.rho and fluid.mu (or nu) must be > 0");
  }
  if (!has(j, "inflow")) throw std::runtime_error("hsrod screen: scene file '" + path + "' lacks inflow");
  const auto &inflow = j["inflow"];
  if (has(inflow, "type") && !(inflow["type"].is_string() && inflow["type"].get<std::string>() == "meanVelocity"))
    throw std::runtime_error(file + "inflow.type must be \"meanVelocity\", got " + inflow["type"].dump());
  s.mean_velocity = required(inflow, "U", "inflow.");
  if (!(s.mean_velocity > 0.0)) throw std::runtime_error(file + "inflow.U must be > 0 m/s");
  if (has(j, "pore")) {
    s.has_pore = true;
    s.pore_radius = required(j["pore"], "R", "pore.");
    s.pore_x = required(j["pore"], "x", "pore.");
  }
  if (has(j, "control")) s.end_time = optional(j["control"], "end_time", "control.", 0.0);
  if (has(j, "channel")) {
    const auto &c = j["channel"];
    const double L = optional(c, "L", "channel.", 0.0), W = optional(c, "W", "channel.", 0.0),
                 H = optional(c, "H", "channel.", 0.0);
    // The inflow in the model's regime, before the script runs (an inflow.U
    // of 1e300 m/s failed later as a sphere moving inf d per step).
    if (L > 0.0 && W > 0.0 && H > 0.0) {
      try {
        check_inflow_regime(s.mean_velocity, ChannelGeometry(L, W, H), FluidProperties{s.viscosity, s.fluid_density});
      } catch (const std::invalid_argument &e) {
        throw std::runtime_error(file + "inflow.U: " + e.what());
      }
    }
    // Resolved cells (an estimate, the mesh is made later by the case's
    // Allrun): the base mesh (nx ny nz, or cell size h over the channel) plus,
    // with "refine" {levels, margin} and a "rod", the refined box around the
    // rod (rod bounding box + margin, cells h / 2^levels) replacing its base cells.
    if (has(j, "mesh")) {
      const auto &m = j["mesh"];
      double h = 0.0;
      if (has(m, "nx")) {
        const double nx = required(m, "nx", "mesh."), ny = optional(m, "ny", "mesh.", 0.0),
                     nz = optional(m, "nz", "mesh.", 0.0);
        s.cells = static_cast<long>(nx * ny * nz);
        h = L / std::max(1.0, nx);
      } else if (has(m, "h")) {
        h = required(m, "h", "mesh.");
        if (!(h > 0.0)) throw std::runtime_error(file + "mesh.h must be > 0 m");
        s.cells = static_cast<long>(std::ceil(L / h) * std::ceil(W / h) * std::ceil(H / h));
      }
      if (h > 0.0 && has(j, "refine") && has(j, "rod")) {
        const double levels = optional(j["refine"], "levels", "refine.", 0.0);
        const double margin = optional(j["refine"], "margin", "refine.", 0.0);
        const double d = optional(j["rod"], "d", "rod.", 0.0);
        const double n = optional(j["rod"], "n", "rod.", 1.0);
        const double box = (n * d + 2 * margin) * (d + 2 * margin) * std::min(H, d + 2 * margin);
        const double fine = h / std::pow(2.0, levels);
        s.cells += static_cast<long>(box / (fine * fine * fine) - box / (h * h * h));
      }
    }
  }
  if (has(j, "screen")) {
    s.reduced_dt = optional(j["screen"], "dt", "screen.", s.reduced_dt);
    s.reduced_t_max = optional(j["screen"], "t_max", "screen.", 0.0);
    if (!(s.reduced_dt > 0.0 && s.reduced_t_max >= 0.0))
      throw std::runtime_error(file + "screen.dt must be > 0 s and screen.t_max >= 0 s");
  }
  return s;
}

}  // namespace hsrod::screen

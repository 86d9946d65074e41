#include "common/math_constants.h"
#include "scene_crosscheck.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "flow/uniform_flow.h"
#include "flow/make_background_flow.h"
#include "hydro/hydrodynamic_model.h"
#include "hydro/local_models.h"
#include "hydro/rigid_rod_load.h"
#include "level_crosscheck.h"
#include "resolved_campaign.h"

namespace hsrod::calib {

namespace {

using hsrod::kPi;

double number(const CsvRow& r, const std::string& k) {
  const auto it = r.find(k);
  if (it == r.end()) throw std::runtime_error("scene cross-check table: no column " + k);
  return std::stod(it->second);
}

// An optional column: NaN when the table has none (tables written before it).
double optional_number(const CsvRow& r, const std::string& k) {
  const auto it = r.find(k);
  return it == r.end() || it->second.empty() ? std::nan("") : std::stod(it->second);
}

ChannelGeometry channel_of(const SceneCase& c) {
  std::vector<ZCylinder> cylinders;
  if (c.geometry == "pore")
    cylinders = {{c.pore_x, 0.0, c.pore_radius}, {c.pore_x, c.channel_width, c.pore_radius}};
  return ChannelGeometry(c.channel_length, c.channel_width, c.gap_height(), 0.0, 0.0, cylinders);
}

}  // namespace

std::vector<SceneCase> read_scene_cases(const std::string& path) {
  std::map<std::pair<std::string, std::string>, SceneCase> cases;
  std::map<std::pair<std::string, std::string>, std::map<int, std::pair<Eigen::Vector2d, Eigen::Vector2d>>> loads;
  std::map<std::pair<std::string, std::string>, std::map<int, Eigen::Vector3d>> centres;
  std::map<std::pair<std::string, std::string>, std::map<int, std::pair<double, double>>> torques;
  for (const CsvRow& r : read_csv_rows(path)) {
    if (number(r, "finest") != 1.0) continue;
    const auto key = std::make_pair(r.at("case"), r.at("load"));
    SceneCase& c = cases[key];
    c.name = r.at("case");
    c.geometry = r.at("geometry");
    c.load = r.at("load");
    if (const auto role = r.find("role"); role != r.end()) c.role = role->second;
    c.beta = number(r, "beta");
    c.gap_over_d = number(r, "gap_over_d");
    c.row_angle_deg = number(r, "row_angle_deg");
    c.bend_deg = number(r, "bend_deg");
    c.drag_angle_deg = number(r, "drag_angle_deg");
    c.d = number(r, "d");
    c.mu = number(r, "mu");
    c.U = number(r, "U");
    c.channel_length = number(r, "channel_L");
    c.channel_width = number(r, "channel_W");
    c.pore_radius = number(r, "pore_R");
    c.pore_x = number(r, "pore_x");
    const int id = static_cast<int>(number(r, "sphere"));
    centres[key][id] = {number(r, "x"), number(r, "y"), number(r, "z")};
    loads[key][id] = {{number(r, "fx"), number(r, "fy")}, {number(r, "dfx"), number(r, "dfy")}};
    torques[key][id] = {optional_number(r, "tz"), optional_number(r, "dtz")};
  }
  std::vector<SceneCase> out;
  for (auto& [key, c] : cases) {
    if (c.geometry != "bent" && c.geometry != "wall" && c.geometry != "pore")
      throw std::runtime_error(path + ": case " + c.name + ": geometry must be bent, wall or pore");
    for (const auto& [id, x] : centres[key]) c.positions.push_back(x);
    for (const auto& [id, f] : loads[key]) {
      c.resolved.push_back(f.first);
      c.mesh_change.push_back(f.second);
    }
    for (const auto& [id, t] : torques[key]) {
      c.resolved_torque.push_back(t.first);
      c.torque_mesh_change.push_back(t.second);
    }
    const bool turning = c.load == "rotation" || c.load == "orbit";
    if (turning && c.geometry == "bent")
      throw std::runtime_error(path + ": case " + c.name + ": load " + c.load + " needs a wall or pore channel");
    if (!turning && c.load != "friction" && c.load != "driving")
      throw std::runtime_error(path + ": case " + c.name + ": load must be friction, driving, rotation or orbit");
    out.push_back(c);
  }
  return out;
}

SceneLoad scene_load(const SceneCase& c) {
  SceneLoad load;
  load.rod.sphere_diameter = c.d;
  load.rod.positions = c.positions;
  const int n = load.rod.size();
  const double a = c.drag_angle_deg * kPi / 180.0;
  const Eigen::Vector2d e(std::cos(a), std::sin(a));
  if (c.geometry == "bent") {
    // the wide slit: a planform 1000 H wide around the rod (no side wall within reach)
    const double big = 1000.0 * c.gap_height();
    const ChannelGeometry slit(big, big, c.gap_height(), -0.5 * big, -0.5 * big);
    load.flow =
        // The wide slit of the bent rods: a planform far larger than the rod.
        std::make_unique<UniformFlow>(slit, c.load == "driving" ? Eigen::Vector2d(c.U * e) : Eigen::Vector2d::Zero());
  } else if (c.load == "driving") {
    load.flow = make_background_flow(channel_of(c), FluidProperties{c.mu, 1000.0}, Inflow::mean_velocity(c.U));
  } else {
    // Fluid at rest in the channel of a wall / pore case: its walls and pore
    // cylinders stay in the geometry, where level 4 reflects off them.
    load.flow = std::make_unique<UniformFlow>(channel_of(c), Eigen::Vector2d::Zero());
  }
  load.velocities = Eigen::VectorXd::Zero(3 * n);
  load.spins = Eigen::VectorXd::Zero(n);
  if (c.load == "friction")
    for (int i = 0; i < n; ++i) load.velocities.segment<2>(3 * i) = -c.U * e;
  if (c.load == "rotation" || c.load == "orbit") {
    // rigid rotation at U / d about the centroid (hsrod_case.py channelBody, load rotation / orbit)
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const auto& x : c.positions) centre += x.head<2>() / n;
    const double omega = c.U / c.d;
    load.velocities = rigid_sphere_velocities(load.rod, centre, Eigen::Vector3d(0.0, 0.0, omega));
    if (c.load == "rotation") load.spins.setConstant(omega);
  }
  load.force_scale = 3.0 * kPi * c.mu * c.d * c.U;
  return load;
}

namespace {
std::vector<Eigen::Vector2d> scaled(const RodDrag& drag, const SceneLoad& load) {
  const Eigen::VectorXd f = drag.forces(load.velocities);
  std::vector<Eigen::Vector2d> out;
  for (int i = 0; i < load.rod.size(); ++i)
    out.emplace_back(f(3 * i) / load.force_scale, f(3 * i + 1) / load.force_scale);
  return out;
}
}  // namespace

SceneSphereLoads scene_sphere_loads(const std::string& model_name, const SceneCase& c, const ConfinementTable& table,
                                    const NearFieldCalibration& near_field, const WallProximityCalibration& wall) {
  const HydrodynamicParameters p{c.mu, c.gap_height(), c.d};
  const std::unique_ptr<HydrodynamicModel> model = make_level_model(model_name, p, table, near_field);
  if (auto* local = dynamic_cast<LocalDragBase*>(model.get()))
    local->set_wall_proximity(wall.for_level(model->level()));
  const SceneLoad load = scene_load(c);
  RodDrag drag;
  model->evaluate(load.rod, *load.flow, drag);
  SceneSphereLoads out;
  out.forces = scaled(drag, load);
  for (int i = 0; i < load.rod.size(); ++i)
    out.torques.push_back(drag.torque(i, Eigen::Vector3d(0.0, 0.0, load.spins(i))).z() / (load.force_scale * c.d));
  return out;
}

std::vector<Eigen::Vector2d> scene_forces(const std::string& model_name, const SceneCase& c,
                                          const ConfinementTable& table, const NearFieldCalibration& near_field,
                                          const WallProximityCalibration& wall) {
  return scene_sphere_loads(model_name, c, table, near_field, wall).forces;
}

double rod_torque(const std::vector<Eigen::Vector3d>& positions, double d, const std::vector<Eigen::Vector2d>& forces,
                  const std::vector<double>& torques) {
  if (positions.size() != forces.size() || positions.size() != torques.size() || positions.empty())
    throw std::invalid_argument("rod_torque: positions, forces and torques differ in length");
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const auto& x : positions) centre += x.head<2>() / static_cast<double>(positions.size());
  double t = 0.0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Eigen::Vector2d r = (positions[i].head<2>() - centre) / d;
    t += r.x() * forces[i].y() - r.y() * forces[i].x() + torques[i];
  }
  return t;
}

std::vector<Eigen::Vector2d> wall_proximity_forces(const WallProximityLaw& law, const SceneCase& c,
                                                   const SceneLoad& load) {
  RodDrag drag;
  drag.resize(load.rod.size());
  add_wall_proximity(law, load.rod, *load.flow, c.mu, c.gap_height(), drag);
  return scaled(drag, load);
}

double profile_rms(const std::vector<Eigen::Vector2d>& model, const std::vector<Eigen::Vector2d>& resolved) {
  if (model.size() != resolved.size() || resolved.empty())
    throw std::invalid_argument("profile_rms: model and resolved profiles differ in length");
  double se = 0.0, mean = 0.0;
  for (std::size_t i = 0; i < resolved.size(); ++i) {
    se += (model[i] - resolved[i]).squaredNorm();
    mean += resolved[i].norm();
  }
  const double n = static_cast<double>(resolved.size());
  return std::sqrt(se / n) / (mean / n);
}

}  // namespace hsrod::calib

#include "hydro/hydrodynamic_model.h"

#include <stdexcept>

namespace hsrod {

std::vector<Eigen::Vector3d> RodGeometry::section_tangents() const {
  const int ns = sections();
  std::vector<Eigen::Vector3d> centres(ns, Eigen::Vector3d::Zero());
  for (int i = 0; i < size(); ++i) centres[section_of(i)] += positions[i] / spheres_per_section;
  std::vector<Eigen::Vector3d> tangents(ns, Eigen::Vector3d::UnitX());
  for (int s = 0; s < ns; ++s) {
    const int a = s > 0 ? s - 1 : s;
    const int b = s + 1 < ns ? s + 1 : s;
    Eigen::Vector3d t = centres[b] - centres[a];
    t.z() = 0.0;  // in-plane: the rods lie in the mid-plane of the gap
    const double norm = t.norm();
    if (norm > 0.0) tangents[s] = t / norm;
  }
  return tangents;
}

void RodDrag::resize(int n) {
  resistance.assign(n, Eigen::Matrix3d::Zero());
  coupled_resistance.resize(0, 0);
  driving_force.assign(n, Eigen::Vector3d::Zero());
  rotational_resistance.assign(n, 0.0);
  driving_torque.assign(n, Eigen::Vector3d::Zero());
}

Eigen::VectorXd RodDrag::forces(const Eigen::VectorXd& velocities) const {
  const int n = static_cast<int>(driving_force.size());
  Eigen::VectorXd f(3 * n);
  for (int i = 0; i < n; ++i) f.segment<3>(3 * i) = driving_force[i];
  if (coupled()) {
    f -= coupled_resistance * velocities;
  } else {
    for (int i = 0; i < n; ++i) f.segment<3>(3 * i) -= resistance[i] * velocities.segment<3>(3 * i);
  }
  return f;
}

void RodDrag::forces(const std::vector<Eigen::Vector3d>& velocities, std::vector<Eigen::Vector3d>& out,
                     Eigen::VectorXd& scratch) const {
  const int n = static_cast<int>(driving_force.size());
  out.resize(n);
  if (coupled()) {
    scratch.resize(6 * n);  // stacked v, then R v
    for (int i = 0; i < n; ++i) scratch.segment<3>(3 * i) = velocities[i];
    scratch.tail(3 * n).noalias() = coupled_resistance * scratch.head(3 * n);
    for (int i = 0; i < n; ++i) out[i] = driving_force[i] - scratch.segment<3>(3 * (n + i));
  } else {
    for (int i = 0; i < n; ++i) out[i] = driving_force[i] - resistance[i] * velocities[i];
  }
}

void HydrodynamicModel::evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out) const {
  const std::unique_ptr<ModelState> state = make_state();
  evaluate(rod, flow, out, state.get());
}

void HydrodynamicModel::evaluate_rods(const std::vector<RodGeometry>& rods, const BackgroundFlow& flow, RodDrag& out,
                                      ModelState* state) const {
  std::vector<RodDrag> parts(rods.size());
  for (std::size_t k = 0; k < rods.size(); ++k) evaluate(rods[k], flow, parts[k], state);
  join_rod_drags(parts, out);
}

void join_rod_drags(const std::vector<RodDrag>& parts, RodDrag& out) {
  int n = 0;
  bool coupled = false;
  for (const RodDrag& p : parts) {
    n += static_cast<int>(p.driving_force.size());
    coupled = coupled || p.coupled();
  }
  out.resize(n);
  if (coupled) out.coupled_resistance.setZero(3 * n, 3 * n);
  int offset = 0;
  for (const RodDrag& p : parts) {
    const int m = static_cast<int>(p.driving_force.size());
    for (int i = 0; i < m; ++i) {
      out.resistance[offset + i] = p.resistance[i];
      out.driving_force[offset + i] = p.driving_force[i];
      out.rotational_resistance[offset + i] = p.rotational_resistance[i];
      out.driving_torque[offset + i] = p.driving_torque[i];
      if (coupled && !p.coupled()) out.coupled_resistance.block<3, 3>(3 * (offset + i), 3 * (offset + i)) = p.resistance[i];
    }
    if (p.coupled()) out.coupled_resistance.block(3 * offset, 3 * offset, 3 * m, 3 * m) = p.coupled_resistance;
    offset += m;
  }
}

std::vector<double> HydrodynamicModel::save_state(const ModelState&) const { return {}; }

void HydrodynamicModel::restore_state(ModelState&, const std::vector<double>& data, const BackgroundFlow&) const {
  if (!data.empty()) throw std::invalid_argument(name() + ": restart data for a model that keeps no state");
}

RodGeometry joined_rods(const std::vector<RodGeometry>& rods, int id) {
  RodGeometry all;
  all.sphere_diameter = rods.empty() ? 0.0 : rods.front().sphere_diameter;
  all.id = id;
  for (const RodGeometry& rod : rods) all.positions.insert(all.positions.end(), rod.positions.begin(), rod.positions.end());
  return all;
}

}  // namespace hsrod

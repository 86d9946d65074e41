// Level 4's entry points: construction, the evaluation of one rod or of
// several in one window, and the cost control that decides when a rod's
// resistance is re-solved.
#include "hydro/twoway_window_model.h"
#include "common/math_constants.h"
#include "hydro/nonlocal_model.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hsrod {

TwoWayWindowModel::TwoWayWindowModel(const HydrodynamicParameters& p, const ConfinementTable& table,
                                     const TwoWayWindowOptions& options)
    : LocalDragBase(p, table), options_(options) {
  if (!(options_.cells_per_diameter >= 2.0) || options_.cells_per_diameter > 16.0)
    throw std::invalid_argument("twoway: cells per diameter must be in [2, 16]");
  if (options_.margin < 0.0) throw std::invalid_argument("twoway: window margin must be >= 0 m");
  if (options_.update_distance < 0.0) throw std::invalid_argument("twoway: update distance must be >= 0 m");
  if (options_.update_every < 0) throw std::invalid_argument("twoway: update interval must be >= 0 steps");
  if (options_.fine_margin < 0.0) throw std::invalid_argument("twoway: window fine margin must be >= 0 m");
  if (options_.grading != 0.0 && (!(options_.grading > 1.0) || options_.grading > 2.0))
    throw std::invalid_argument("twoway: window grading must be in (1, 2]");
  if (options_.margin > 0.0 && options_.fine_margin > options_.margin)
    throw std::invalid_argument("twoway: window fine margin must not exceed the window margin");
  const double d = p.sphere_diameter;
  if (options_.update_distance == 0.0) options_.update_distance = 0.5 * d;
  spacing_ = d / options_.cells_per_diameter;
  if (options_.reflection_cells_per_diameter == 0.0)
    options_.reflection_cells_per_diameter = std::min(kReflectionCellsPerDiameter, options_.cells_per_diameter);
  if (!(options_.reflection_cells_per_diameter >= 1.0) ||
      options_.reflection_cells_per_diameter > options_.cells_per_diameter)
    throw std::invalid_argument("twoway: reflection cells per diameter must be in [1, cells per diameter]");
  window_spacing_ = d / options_.reflection_cells_per_diameter;
  if (options_.grading == 0.0) options_.grading = two_scales() ? kTwoScaleGrading : kOneScaleGrading;
  if (two_scales()) build_two_scale_tables();
  obstruction_ = LocalDragBase::obstruction_friction();
  film_friction_ = sphere_friction_ - obstruction_;
  free_self_mobility_ = measure_free_self_mobility();
  // c m_free < 1/zeta_o is not required: the rod's matrix
  // I/zeta_o + c (M - m_free I) stays positive definite while the spheres'
  // mutual mobilities stay below 1/(c zeta_o) (checked at each update).
}

double TwoWayWindowModel::interaction_reach() const {
  return depth_averaged_interaction_reach(parameters_.gap_height, parameters_.viscosity, obstruction_,
                                          NonlocalRodModel::kInteractionTolerance);
}

void TwoWayWindowModel::evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out,
                                 ModelState* state) const {
  if (!state) {
    TwoWayWindowState fresh;
    fresh.spacing = window_spacing_;
    evaluate_with(rod, flow, out, fresh);
    return;
  }
  auto* own = dynamic_cast<TwoWayWindowState*>(state);
  if (!own) throw std::invalid_argument("twoway: the state given is not a level-4 state (make_state())");
  evaluate_with(rod, flow, out, *own);
}

int TwoWayWindowModel::joint_key(const std::vector<RodGeometry>& rods) {
  int smallest = rods.empty() ? 0 : rods.front().id;
  for (const RodGeometry& rod : rods) smallest = std::min(smallest, rod.id);
  return -(1 + smallest);
}

void TwoWayWindowModel::evaluate_rods(const std::vector<RodGeometry>& rods, const BackgroundFlow& flow, RodDrag& out,
                                      ModelState* state) const {
  if (rods.size() == 1) {
    evaluate(rods.front(), flow, out, state);
    return;
  }
  const RodGeometry all = joined_rods(rods, joint_key(rods));
  std::vector<int> members;
  for (const RodGeometry& rod : rods) members.push_back(rod.id);
  if (auto* own = dynamic_cast<TwoWayWindowState*>(state)) {
    // A window kept under this key for another set of rods is dropped (a
    // restored one, members unknown, is kept: it was saved for these rods).
    const auto it = own->rods.find(all.id);
    if (it != own->rods.end() && !it->second.members.empty() && it->second.members != members) own->rods.erase(it);
    own->rods[all.id].members = members;
  }
  evaluate(all, flow, out, state);  // virtual: the registered model adds its near field
}

// Cost control: whether the rod's stored resistance must be re-solved now.
// If not, `turn` [rad] is the rod's in-plane turn since its last solve (the
// stored resistance is used turned with it); 0 otherwise.
bool TwoWayWindowModel::needs_update(const RodGeometry& rod, const ChannelGeometry& geometry, const RodState& state,
                                     double& turn) const {
  const int n = rod.size();
  bool update = !state.window || static_cast<int>(state.solved_positions.size()) != n ||
                (options_.update_every > 0 && state.evaluations_since_update >= options_.update_every);
  turn = 0.0;
  if (!update) {
    // Away from walls the window system is translation invariant: only a
    // change of the rod's shape or orientation (sphere displacements
    // relative to the centroid's) calls for a new solve (measured on the pore
    // passage: x changes by 0.13 d, within the grid's sub-cell noise of
    // 0.1-0.3 % in R). A rigid shift changes only the walls' reflection,
    // which falls off as 1/s^2 with the distance s to the nearest wall: a
    // shift by s/8 changes it by ~25 % of itself (a fraction of a percent
    // of R once s is several l), so the rod is re-solved after a shift of
    // max(update distance, s/8); along a straight channel (no pore cylinder
    // in the window) a shift along x changes nothing.
    Eigen::Vector2d shift = Eigen::Vector2d::Zero();
    for (int i = 0; i < n; ++i) shift += (rod.positions[i] - state.solved_positions[i]).head<2>() / n;
    double wall_distance = std::numeric_limits<double>::infinity();
    if (state.window->has_walls())
      for (const auto& x : rod.positions)
        wall_distance = std::min(wall_distance, geometry.signed_distance(x.x(), x.y()));
    Eigen::Vector2d rigid = shift;
    if (window_clear_of_cylinders(state.window->lattice(), geometry)) rigid.x() = 0.0;
    update = rigid.norm() > std::max(options_.update_distance, kWallShiftFraction * wall_distance);
    for (int i = 0; !update && i < n; ++i) {
      const Eigen::Vector2d moved = (rod.positions[i] - state.solved_positions[i]).head<2>() - shift;
      update = moved.norm() > options_.update_distance;
    }
    update = update || !window_holds(rod, geometry, *state.window);
    // Between solves the rod turns (its ends up to the update distance from
    // the centroid's move: ~6 deg for a 10-sphere rod); the stored
    // resistance is turned with it (Q R Q^T, exact for the continuous
    // problem away from walls), by the angle of the rigid motion that best
    // carries the solved positions onto the current ones. Kept unturned,
    // level 4's pore passage ended 0.036 deg off one re-solved at every
    // evaluation (window_every 1); turned, 0.003 deg.
    if (!update && n > 1) {
      Eigen::Vector2d solved_centre = Eigen::Vector2d::Zero(), centre = Eigen::Vector2d::Zero();
      for (int i = 0; i < n; ++i) {
        solved_centre += state.solved_positions[i].head<2>() / n;
        centre += rod.positions[i].head<2>() / n;
      }
      double dot = 0.0, cross = 0.0;
      for (int i = 0; i < n; ++i) {
        const Eigen::Vector2d a = state.solved_positions[i].head<2>() - solved_centre;
        const Eigen::Vector2d b = rod.positions[i].head<2>() - centre;
        dot += a.dot(b);
        cross += a.x() * b.y() - a.y() * b.x();
      }
      turn = std::atan2(cross, dot);
      update = !(std::fabs(turn) <= kMaxTurn);
    }
  }
  if (update) turn = 0.0;
  return update;
}

// Footprint-averaged background flow at the rod's current positions (x, y
// per sphere: 2n entries) [m/s].
Eigen::VectorXd TwoWayWindowModel::footprint_background(const RodGeometry& rod, const BackgroundFlow& flow,
                                                        const BrinkmanWindow& window) const {
  const int n = rod.size();
  Eigen::VectorXd background(2 * n);
  for (int i = 0; two_scales() && i < n; ++i) {
    // On the fine lattice (the sphere's own footprint), not the window's.
    const Eigen::Vector2d anchor(flow.geometry().x_lo(), flow.geometry().y_lo());
    const LatticeFootprint f =
        lattice_footprint(rod.positions[i].head<2>(), anchor, spacing_, kernel_width(), &flow.geometry());
    for (int a = 0; a < 2; ++a) {
      double u = f.nodes[a].empty() ? flow.velocity(rod.positions[i].x(), rod.positions[i].y())[a] : 0.0;
      for (std::size_t k = 0; k < f.nodes[a].size(); ++k) {
        const Eigen::Vector2d p = lattice_node_position(f.nodes[a][k], anchor, spacing_);
        u += f.weights[a][k] * flow.velocity(p.x(), p.y())[a];
      }
      background[2 * i + a] = u;
    }
  }
  for (int i = 0; !two_scales() && i < n; ++i) {
    const Footprint f = footprint(window, rod.positions[i]);
    for (int a = 0; a < 2; ++a) {
      if (f.nodes[a].empty()) {
        background[2 * i + a] = flow.velocity(rod.positions[i].x(), rod.positions[i].y())[a];
        continue;
      }
      double u = 0.0;
      for (std::size_t k = 0; k < f.nodes[a].size(); ++k) {
        const Eigen::Vector2d& p = window.nodes()[f.nodes[a][k]].position;
        u += f.weights[a][k] * flow.velocity(p.x(), p.y())[a];
      }
      background[2 * i + a] = u;
    }
  }
  return background;
}

void TwoWayWindowModel::evaluate_with(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out,
                                      TwoWayWindowState& rods) const {
  ++rods.statistics.evaluations;
  if (std::abs(flow.geometry().gap_height() - parameters_.gap_height) > 1e-9 * parameters_.gap_height)
    throw std::invalid_argument("twoway: the flow's gap height differs from the model's");
  const int n = rod.size();
  RodState& state = rods.rods[rod.id];
  double turn = 0.0;
  const bool update = needs_update(rod, flow.geometry(), state, turn);
  if (update) {
    if (!state.window || !window_holds(rod, flow.geometry(), *state.window))
      place_window(rod, flow, state, rods);
    update_resistance(rod, flow.geometry(), state, rods.statistics);
  } else {
    ++state.evaluations_since_update;
  }
  const Eigen::VectorXd background = footprint_background(rod, flow, *state.window);
  // The stored resistance turned with the rod: Q R Q^T block by block.
  const Eigen::MatrixXd* obstruction = &state.obstruction;
  Eigen::MatrixXd turned;
  if (turn != 0.0) {
    const Eigen::Matrix2d q = Eigen::Rotation2Dd(turn).toRotationMatrix();
    turned.resize(2 * n, 2 * n);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k)
        turned.block<2, 2>(2 * i, 2 * k) = q * state.obstruction.block<2, 2>(2 * i, 2 * k) * q.transpose();
    obstruction = &turned;
  }
  const Eigen::VectorXd driving = kMidplaneFactor * (*obstruction * background);

  out.resize(n);
  out.coupled_resistance = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < n; ++k)
      out.coupled_resistance.block<2, 2>(3 * i, 3 * k) = obstruction->block<2, 2>(2 * i, 2 * k);
    out.coupled_resistance(3 * i, 3 * i) += film_friction_;
    out.coupled_resistance(3 * i + 1, 3 * i + 1) += film_friction_;
    out.coupled_resistance(3 * i + 2, 3 * i + 2) = sphere_friction_;
    out.driving_force[i] = Eigen::Vector3d(driving[2 * i], driving[2 * i + 1], 0.0);
    out.resistance[i] = out.coupled_resistance.block<3, 3>(3 * i, 3 * i);
  }
  add_rotation(rod, flow, out);
}

}  // namespace hsrod

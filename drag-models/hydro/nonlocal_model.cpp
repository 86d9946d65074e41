#include "hydro/nonlocal_model.h"
#include "common/dense_cholesky.h"
#include "common/dense_lu.h"
#include "common/math_constants.h"

#include "hydro/brinkman_green.h"
#include "hydro/cross_rod_disturbance.h"
#include "hydro/dense_model_budget.h"
#include "hydro/wall_images.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace hsrod {

NonlocalRodModel::NonlocalRodModel(const HydrodynamicParameters& p, const ConfinementTable& table)
    : NonlocalRodModel(p, table, NearFieldCalibration::built_in().nonlocal.at(p.sphere_diameter / p.gap_height)) {}

NonlocalRodModel::NonlocalRodModel(const HydrodynamicParameters& p, const ConfinementTable& table,
                                   const NearFieldAtBeta& near_field)
    : LocalDragBase(p, table), near_field_(near_field) {
  const std::string problem = NearFieldCalibration::range_problem(near_field);
  if (!problem.empty()) throw std::invalid_argument("nonlocal: near field: " + problem);
  obstruction_friction_ = LocalDragBase::obstruction_friction();
  film_friction_ = sphere_friction_ - obstruction_friction_;
}

bool NonlocalRodModel::own_driving() const {
  return near_field_.driving.blend_length != near_field_.friction.blend_length ||
         near_field_.driving.reflection != near_field_.friction.reflection ||
         near_field_.driving.reflection_along != near_field_.friction.reflection_along;
}

namespace {

// zo a^-1 into `out` for the symmetric positive definite a (Cholesky), or
// through a partial-pivoting LU should a pivot not be positive.
void scaled_inverse(const Eigen::MatrixXd& a, double zo, Eigen::MatrixXd& out) {
  Eigen::MatrixXd factor;
  if (!cholesky_inverse(a, factor, out)) {
    DenseLu lu;
    Eigen::MatrixXd work = a;
    lu.compute_in_place(work);
    lu.inverse(out);
  }
  out *= zo;
}

// The rigid in-plane motion that best carries `reference` onto `now` (least
// squares, turn about the centroids: the 2-D Kabsch solution) as the turn's
// cosine and sine, and the largest distance [m] of a centre of `now` from
// its carried reference place.
double rigid_misfit(const std::vector<Eigen::Vector2d>& reference, const RodGeometry& now, double& cos_turn,
                    double& sin_turn) {
  const int n = static_cast<int>(reference.size());
  Eigen::Vector2d c_ref = Eigen::Vector2d::Zero(), c_now = Eigen::Vector2d::Zero();
  for (int i = 0; i < n; ++i) {
    c_ref += reference[i];
    c_now += now.positions[i].head<2>();
  }
  c_ref /= n;
  c_now /= n;
  double dot = 0.0, cross = 0.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = reference[i] - c_ref, b = now.positions[i].head<2>() - c_now;
    dot += a.dot(b);
    cross += a.x() * b.y() - a.y() * b.x();
  }
  const double norm = std::hypot(dot, cross);
  cos_turn = norm > 0.0 ? dot / norm : 1.0;
  sin_turn = norm > 0.0 ? cross / norm : 0.0;
  double misfit = 0.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = reference[i] - c_ref;
    const Eigen::Vector2d carried(cos_turn * a.x() - sin_turn * a.y(), sin_turn * a.x() + cos_turn * a.y());
    misfit = std::max(misfit, (carried - (now.positions[i].head<2>() - c_now)).norm());
  }
  return misfit;
}

// Q_b m Q_b^T into `out`, Q_b = diag(Q, ..., Q), Q the turn (cos c, sin s):
// each 2x2 block [a b; e f] turned on its own, written out (Eigen's
// dynamic-matrix 2x2 block products cost ~5x more here).
void turned(const Eigen::MatrixXd& m, double c, double s, Eigen::MatrixXd& out) {
  const Eigen::Index size = m.rows();
  out.resize(size, size);
  for (Eigen::Index k = 0; k < size; k += 2) {
    for (Eigen::Index i = 0; i < size; i += 2) {
      const double a = m(i, k), b = m(i, k + 1), e = m(i + 1, k), f = m(i + 1, k + 1);
      // Q [a b; e f]: rows (c a - s e, c b - s f), (s a + c e, s b + c f); then times Q^T.
      const double qa = c * a - s * e, qb = c * b - s * f, qe = s * a + c * e, qf = s * b + c * f;
      out(i, k) = qa * c - qb * s;
      out(i, k + 1) = qa * s + qb * c;
      out(i + 1, k) = qe * c - qf * s;
      out(i + 1, k + 1) = qe * s + qf * c;
    }
  }
}

}  // namespace

WallReflection wall_reflection_from_name(const std::string& name) {
  if (name == "none") return WallReflection::none;
  if (name == "images") return WallReflection::images;
  if (name == "self_images") return WallReflection::self_images;
  if (name == "reflections") return WallReflection::reflections;
  throw std::invalid_argument("nonlocal: wall reflection '" + name +
                              "': accepted values are none, images, self_images, reflections");
}

void NonlocalRodModel::pair_mobility(const Eigen::Vector2d& offset, Eigen::Matrix2d& friction,
                                     Eigen::Matrix2d* driving) const {
  const double mu = parameters_.viscosity, H = parameters_.gap_height, d = parameters_.sphere_diameter;
  const double zo = obstruction_friction_;
  const Eigen::Matrix2d depth_averaged = kMidplaneFactor * brinkman_green_function(offset, mu, H);
  friction = near_field_pair_mobility(depth_averaged, offset, mu, H, d, 1.0 / zo, near_field_.friction);
  if (driving) *driving = near_field_pair_mobility(depth_averaged, offset, mu, H, d, 1.0 / zo, near_field_.driving);
}

void NonlocalRodModel::solve_coupling(const RodGeometry& rod, const ChannelGeometry* walls,
                                      Eigen::MatrixXd& obstruction, Eigen::MatrixXd& driving) const {
  const int n = rod.size();
  const double zo = obstruction_friction_;
  // Coupling matrix I + zeta_o M of the in-plane components, M_ik = c G or,
  // within a few H, blended into the 3-D near field. z is uncoupled (its
  // block is the identity), so only the 2n x 2n in-plane part is inverted:
  // (2/3)^3 of the 3n x 3n LU's work, the same result to round-off.
  // G(r) = G(-r) is symmetric (brinkman_green.h): one evaluation per pair
  // fills both blocks (i,k) and (k,i). The held load has its own near field
  // (NearFieldAtBeta), so its coupling matrix is built beside the friction's
  // from the same G when the two differ.
  const bool own = own_driving();
  Eigen::MatrixXd coupling = Eigen::MatrixXd::Identity(2 * n, 2 * n);
  Eigen::MatrixXd coupling_driving;
  if (own) coupling_driving = Eigen::MatrixXd::Identity(2 * n, 2 * n);
  for (int i = 0; i < n; ++i) {
    for (int k = i + 1; k < n; ++k) {
      const Eigen::Vector2d offset = (rod.positions[i] - rod.positions[k]).head<2>();
      if (offset.norm() <= 0.0) continue;
      Eigen::Matrix2d m, md;
      pair_mobility(offset, m, own ? &md : nullptr);
      const Eigen::Matrix2d g = zo * m;
      coupling.block<2, 2>(2 * i, 2 * k) += g;
      coupling.block<2, 2>(2 * k, 2 * i) += g;
      if (!own) continue;
      const Eigen::Matrix2d gd = zo * md;
      coupling_driving.block<2, 2>(2 * i, 2 * k) += gd;
      coupling_driving.block<2, 2>(2 * k, 2 * i) += gd;
    }
  }
  if (walls) add_wall_images(rod, *walls, coupling, coupling_driving);
  // R_o itself is an output (it enters the implicit step's matrix), so the
  // inverse is what is wanted here. I + zeta_o M is symmetric (G and the
  // near field are) and, R_o being a resistance, positive definite: the
  // Cholesky inverse (common/dense_cholesky.h, ~1/2 the flops of an LU and
  // its inverse, ~1/5 of Eigen's blocked ones at this size); a partial-
  // pivoting LU should a pivot not be positive. The held load's coupling
  // the same way (kept with the rod's state, it is reused like R_o).
  scaled_inverse(coupling, zo, obstruction);
  if (own)
    scaled_inverse(coupling_driving, zo, driving);
  else
    driving.resize(0, 0);
}

void NonlocalRodModel::add_wall_images(const RodGeometry& rod, const ChannelGeometry& walls,
                                       Eigen::MatrixXd& coupling, Eigen::MatrixXd& coupling_driving) const {
  const int n = rod.size();
  const double scale = obstruction_friction_ * kMidplaneFactor;
  const double mu = parameters_.viscosity, H = parameters_.gap_height;
  std::vector<ImageSeries> series;  // multiple reflections: each sphere's series, built once
  if (wall_reflection_ == WallReflection::reflections)
    for (int i = 0; i < n; ++i) series.push_back(reflected_force_images(walls, rod.positions[i].head<2>()));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d xi = rod.positions[i].head<2>();
    const int last = wall_reflection_ == WallReflection::self_images ? i + 1 : n;
    for (int k = i; k < last; ++k) {
      const Eigen::Vector2d xk = rod.positions[k].head<2>();
      // reciprocal to round-off (wall_images.h): symmetrised; the self-image
      // (k = i) is one evaluation and its transpose
      const Eigen::Matrix2d ik = series.empty() ? image_mobility(walls, xi, xk, mu, H) : image_mobility(series[k], xi, mu, H);
      const Eigen::Matrix2d ki =
          k == i ? ik : (series.empty() ? image_mobility(walls, xk, xi, mu, H) : image_mobility(series[i], xk, mu, H));
      const Eigen::Matrix2d g = 0.5 * scale * (ik + ki.transpose());
      coupling.block<2, 2>(2 * i, 2 * k) += g;
      if (k != i) coupling.block<2, 2>(2 * k, 2 * i) += g.transpose();
      if (coupling_driving.size() == 0) continue;
      coupling_driving.block<2, 2>(2 * i, 2 * k) += g;
      if (k != i) coupling_driving.block<2, 2>(2 * k, 2 * i) += g.transpose();
    }
  }
}

void NonlocalRodModel::evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out,
                                ModelState* state) const {
  NonlocalState* own = nullptr;
  if (state) {
    own = dynamic_cast<NonlocalState*>(state);
    if (!own) throw std::invalid_argument("nonlocal: the state given is not a level-3 state (make_state())");
  }
  evaluate_with(rod, flow, out, own, rod.id);
}

void NonlocalRodModel::evaluate_with(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out,
                                     NonlocalState* state, int key, UnitObstruction* unit) const {
  const int n = rod.size();
  out.resize(n);
  const double zo = obstruction_friction_;
  Eigen::MatrixXd solved_obstruction, solved_driving;
  const Eigen::MatrixXd* obstruction = &solved_obstruction;  // R_o in the plane, 2n x 2n
  const Eigen::MatrixXd* driving = &solved_driving;          // its held-load twin (empty: R_o)
  const ChannelGeometry* walls = wall_reflection_ != WallReflection::none ? &flow.geometry() : nullptr;
  if (!state) {
    solve_coupling(rod, walls, solved_obstruction, solved_driving);
  } else {
    ++state->evaluations;
    NonlocalState::Rod& kept = state->rods[key];
    double c = 1.0, s = 0.0;
    const bool reuse = !walls && static_cast<int>(kept.reference.size()) == n && n > 0 &&
                       rigid_misfit(kept.reference, rod, c, s) <= kShapeTolerance * parameters_.sphere_diameter;
    if (!reuse) {
      ++state->solves;
      solve_coupling(rod, walls, kept.obstruction, kept.driving);
      kept.reference.resize(n);
      for (int i = 0; i < n; ++i) kept.reference[i] = rod.positions[i].head<2>();
      obstruction = &kept.obstruction;
      driving = &kept.driving;
    } else {
      turned(kept.obstruction, c, s, kept.turned_obstruction);
      obstruction = &kept.turned_obstruction;
      driving = &kept.driving;  // empty: the held load uses R_o
      if (kept.driving.size() > 0) {
        turned(kept.driving, c, s, kept.turned_driving);
        driving = &kept.turned_driving;
      }
    }
  }
  const Eigen::MatrixXd& inverse = *obstruction;
  // R = zeta_f I + R_o, symmetrised: R_o = zeta_o (I + zeta_o M)^-1 in the
  // plane, zeta_o along z.
  Eigen::MatrixXd& resistance = out.coupled_resistance;
  resistance.setZero(3 * n, 3 * n);
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < 2; ++c)
      for (int i = 0; i < n; ++i)
        for (int r = 0; r < 2; ++r)
          resistance(3 * i + r, 3 * k + c) =
              0.5 * (inverse(2 * i + r, 2 * k + c) + inverse(2 * k + c, 2 * i + r));
  for (int i = 0; i < n; ++i) resistance(3 * i + 2, 3 * i + 2) = zo;
  for (int i = 0; i < 3 * n; ++i) resistance(i, i) += film_friction_;

  sample_flow(rod, flow, out);
  Eigen::VectorXd u(2 * n);
  for (int i = 0; i < n; ++i) u.segment<2>(2 * i) = out.driving_force[i].head<2>();
  // In-plane driving c R_o u, or, when the held load has its own near field,
  // c zo (I + zo M^D)^-1 u.
  const Eigen::VectorXd in_plane = kMidplaneFactor * ((driving->size() > 0 ? *driving : inverse) * u);
  if (unit) {
    unit->friction = inverse;
    if (driving->size() > 0) unit->driving = *driving;
    else unit->driving.resize(0, 0);
    unit->lone_driving = in_plane;
  }
  for (int i = 0; i < n; ++i) {
    out.driving_force[i] << in_plane.segment<2>(2 * i), kMidplaneFactor * (zo * out.driving_force[i].z());
    out.resistance[i] = resistance.block<3, 3>(3 * i, 3 * i);
  }
  apply_wall_proximity(rod, flow, out);
}

void NonlocalRodModel::evaluate_rods(const std::vector<RodGeometry>& rods, const BackgroundFlow& flow, RodDrag& out,
                                     ModelState* state) const {
  if (rods.size() == 1) {
    evaluate(rods.front(), flow, out, state);
    return;
  }
  NonlocalState* own = nullptr;
  if (state) {
    own = dynamic_cast<NonlocalState*>(state);
    if (!own) throw std::invalid_argument("nonlocal: the state given is not a level-3 state (make_state())");
  }
  // Rods evaluated together keep their coupling under a key no single rod
  // has (ids are >= 0): that of the smallest id, negated.
  int smallest = rods.front().id;
  for (const RodGeometry& r : rods) smallest = std::min(smallest, r.id);
  evaluate_with(joined_rods(rods, rods.front().id), flow, out, own, -(1 + smallest));
}

std::string NonlocalState::work_summary() const {
  char line[200];
  std::snprintf(line, sizeof(line), "nonlocal: %ld evaluations, %ld coupling solves, %ld reused turned with the rod",
                evaluations, solves, evaluations - solves);
  return line;
}

std::unique_ptr<ModelState> NonlocalRodModel::make_state() const { return std::make_unique<NonlocalState>(); }

namespace {
constexpr double kNonlocalStateTag = 3.0;  // first number: the model level that wrote the data
}

std::vector<double> NonlocalRodModel::save_state(const ModelState& base) const {
  const auto& state = dynamic_cast<const NonlocalState&>(base);
  std::vector<double> out{kNonlocalStateTag, static_cast<double>(state.evaluations),
                          static_cast<double>(state.solves), static_cast<double>(state.rods.size())};
  for (const auto& entry : state.rods) {
    const NonlocalState::Rod& rod = entry.second;
    out.insert(out.end(), {static_cast<double>(entry.first), static_cast<double>(rod.reference.size()),
                           rod.driving.size() > 0 ? 1.0 : 0.0});
    for (const auto& x : rod.reference) out.insert(out.end(), {x.x(), x.y()});
    out.insert(out.end(), rod.obstruction.data(), rod.obstruction.data() + rod.obstruction.size());
    out.insert(out.end(), rod.driving.data(), rod.driving.data() + rod.driving.size());
  }
  return out;
}

void NonlocalRodModel::restore_state(ModelState& base, const std::vector<double>& data, const BackgroundFlow&) const {
  auto& state = dynamic_cast<NonlocalState&>(base);
  std::size_t at = 0;
  const auto next = [&]() {
    if (at >= data.size()) throw std::invalid_argument("nonlocal: restart data ends early");
    return data[at++];
  };
  if (next() != kNonlocalStateTag) throw std::invalid_argument("nonlocal: restart data from another model");
  state.rods.clear();
  state.evaluations = static_cast<long>(next());
  state.solves = static_cast<long>(next());
  for (long count = static_cast<long>(next()); count > 0; --count) {
    NonlocalState::Rod& rod = state.rods[static_cast<int>(next())];
    const double size = next();
    if (!(size >= 0.0 && size <= 1e6)) throw std::invalid_argument("nonlocal: restart data: bad sphere count");
    const int n = static_cast<int>(size);
    const bool has_driving = next() != 0.0;
    rod.reference.resize(n);
    for (auto& x : rod.reference) {
      x.x() = next();
      x.y() = next();
    }
    rod.obstruction.resize(2 * n, 2 * n);
    for (Eigen::Index k = 0; k < rod.obstruction.size(); ++k) rod.obstruction.data()[k] = next();
    rod.driving.resize(has_driving ? 2 * n : 0, has_driving ? 2 * n : 0);
    for (Eigen::Index k = 0; k < rod.driving.size(); ++k) rod.driving.data()[k] = next();
  }
  if (at != data.size()) throw std::invalid_argument("nonlocal: restart data longer than written");
}

double depth_averaged_interaction_reach(double gap_height, double viscosity, double obstruction_friction,
                                        double tolerance) {
  const double screening = gap_height / std::sqrt(12.0);
  const double dipole = std::sqrt(kMidplaneFactor * obstruction_friction * gap_height / (24.0 * kPi * viscosity * tolerance));
  return std::max(10.0 * screening, dipole);
}

double NonlocalRodModel::interaction_reach() const {
  return depth_averaged_interaction_reach(parameters_.gap_height, parameters_.viscosity, obstruction_friction_,
                                          kInteractionTolerance);
}

std::string NonlocalRodModel::resource_problem(const RodGeometry& rod, const BackgroundFlow& /*flow*/,
                                               const ResourceLimits& limits) const {
  return nonlocal_model_budget_problem(rod.size(), limits.dense_memory_bytes);
}

}  // namespace hsrod

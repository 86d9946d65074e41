#include "hydro/twoway_near_field.h"

#include <Eigen/Dense>

#include <stdexcept>
#include <string>

namespace hsrod {

void add_near_field(const RodGeometry& rod, const HydrodynamicParameters& p, double film_friction,
                    double obstruction_friction, const NearFieldAtBeta& coupling, RodDrag& drag) {
  const int n = rod.size();
  if (n < 2 || !coupling.active()) return;
  if (!drag.coupled() || drag.coupled_resistance.rows() != 3 * n)
    throw std::invalid_argument("near field: a coupled load of " + std::to_string(n) + " spheres is needed");
  // In-plane obstruction resistance R_o (2n x 2n) and driving.
  Eigen::MatrixXd obstruction(2 * n, 2 * n);
  Eigen::VectorXd driving(2 * n);
  for (int i = 0; i < n; ++i) {
    driving.segment<2>(2 * i) = drag.driving_force[i].head<2>();
    for (int k = 0; k < n; ++k)
      obstruction.block<2, 2>(2 * i, 2 * k) = drag.coupled_resistance.block<2, 2>(3 * i, 3 * k);
  }
  obstruction.diagonal().array() -= film_friction;
  const Eigen::MatrixXd mobility = obstruction.partialPivLu().inverse();
  Eigen::MatrixXd blended = mobility, blended_driving = mobility;
  const double self_mobility = 1.0 / obstruction_friction;  // 1 / zeta_o [m/(N s)]
  bool changed = false;
  for (int i = 0; i < n; ++i)
    for (int k = i + 1; k < n; ++k) {
      const Eigen::Vector2d offset = (rod.positions[i] - rod.positions[k]).head<2>();
      if ((near_field_weight(offset.norm(), p.gap_height, coupling.friction) == 0.0 &&
           near_field_weight(offset.norm(), p.gap_height, coupling.driving) == 0.0) ||
          offset.norm() <= 0.0)
        continue;
      // The window's blocks (i,k) and (k,i) are transposes up to round-off: blend their mean.
      const Eigen::Matrix2d level =
          0.5 * (mobility.block<2, 2>(2 * i, 2 * k) + mobility.block<2, 2>(2 * k, 2 * i).transpose());
      const Eigen::Matrix2d m = near_field_pair_mobility(level, offset, p.viscosity, p.gap_height, p.sphere_diameter,
                                                         self_mobility, coupling.friction);
      blended.block<2, 2>(2 * i, 2 * k) = m;
      blended.block<2, 2>(2 * k, 2 * i) = m.transpose();
      const Eigen::Matrix2d md = near_field_pair_mobility(level, offset, p.viscosity, p.gap_height, p.sphere_diameter,
                                                          self_mobility, coupling.driving);
      blended_driving.block<2, 2>(2 * i, 2 * k) = md;
      blended_driving.block<2, 2>(2 * k, 2 * i) = md.transpose();
      changed = true;
    }
  if (!changed) return;
  const Eigen::MatrixXd resistance = blended.partialPivLu().inverse();
  const Eigen::VectorXd new_driving = blended_driving.partialPivLu().solve(mobility * driving);
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < n; ++k)
      drag.coupled_resistance.block<2, 2>(3 * i, 3 * k) =
          0.5 * (resistance.block<2, 2>(2 * i, 2 * k) + resistance.block<2, 2>(2 * k, 2 * i).transpose());
    drag.coupled_resistance(3 * i, 3 * i) += film_friction;
    drag.coupled_resistance(3 * i + 1, 3 * i + 1) += film_friction;
    drag.driving_force[i].head<2>() = new_driving.segment<2>(2 * i);
    drag.resistance[i] = drag.coupled_resistance.block<3, 3>(3 * i, 3 * i);
  }
}

NearFieldTwoWayModel::NearFieldTwoWayModel(const HydrodynamicParameters& p, const ConfinementTable& table,
                                           const TwoWayWindowOptions& options, const NearFieldAtBeta& near_field)
    : TwoWayWindowModel(p, table, options), near_field_(near_field) {
  const std::string problem = NearFieldCalibration::range_problem(near_field);
  if (!problem.empty()) throw std::invalid_argument("twoway: near field: " + problem);
}

NearFieldTwoWayModel::NearFieldTwoWayModel(const HydrodynamicParameters& p, const ConfinementTable& table,
                                           const TwoWayWindowOptions& options)
    : NearFieldTwoWayModel(p, table, options, NearFieldCalibration::built_in().twoway.at(p.sphere_diameter / p.gap_height)) {}

void NearFieldTwoWayModel::evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out,
                                    ModelState* state) const {
  TwoWayWindowModel::evaluate(rod, flow, out, state);
  add_near_field(rod, parameters_, film_friction(), obstruction_friction(), near_field_, out);
  apply_wall_proximity(rod, flow, out);
}

}  // namespace hsrod

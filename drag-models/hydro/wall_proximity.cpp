#include "hydro/wall_proximity.h"

#include "common/math_constants.h"
#include "hydro/hydrodynamic_model.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hsrod {

WallProximityCalibration WallProximityCalibration::off() {
  WallProximityCalibration c;
  c.source = "off";
  return c;
}

const WallProximityLaw& WallProximityCalibration::for_level(int level) const {
  if (level == 1 || level == 2) return local;
  if (level == 3) return nonlocal;
  if (level == 4) return twoway;
  throw std::invalid_argument("wall proximity: level must be 1-4, not " + std::to_string(level));
}

double wall_normal_rise(double g) {
  // Bevan & Prieve (2000): f_n = (6 g^2 + 2 g) / (6 g^2 + 9 g + 2) with g = delta / a
  return (7.0 * g + 2.0) / (6.0 * g * g + 2.0 * g);
}

double wall_along_rise(double g) {
  const double x = 1.0 / (1.0 + g);  // a / h
  const double x3 = x * x * x;
  return 1.0 / (1.0 - 9.0 / 16.0 * x + x3 / 8.0 - 45.0 / 256.0 * x3 * x - x3 * x * x / 16.0) - 1.0;
}

namespace {

// The neighbour pairs' squeeze flow along the wall (wall_proximity.h): symmetric
// blocks of the coupled R, k = k_p 3 pi mu d sqrt(s_i s_j) s_ij,
//   R_ii += k (t n^T + n t^T),  R_jj -= k (t n^T + n t^T),  R_ij = R_ji^T += k (n t^T - t n^T).
void add_pair_squeeze(const WallProximityLaw& law, const RodGeometry& rod, const ChannelGeometry& walls,
                      double gap_height, double reach, double unit, RodDrag& out) {
  const double d = rod.sphere_diameter, a = 0.5 * d;
  for (int i = 0; i + 1 < rod.size(); ++i) {
    const int j = i + 1;
    const Eigen::Vector2d pi = rod.positions[i].head<2>(), pj = rod.positions[j].head<2>();
    const Eigen::Vector2d r = pj - pi;
    const double dist = r.norm();
    if (!(dist > 0.0) || dist >= 1.5 * d) continue;
    const double gi = walls.signed_distance(pi.x(), pi.y()) - a, gj = walls.signed_distance(pj.x(), pj.y()) - a;
    if (gi > reach || gj > reach) continue;
    const Eigen::Vector2d ni = walls.wall_normal(pi.x(), pi.y()), nj = walls.wall_normal(pj.x(), pj.y());
    const Eigen::Vector2d mean = ni + nj;
    if (!(mean.norm() > 1e-12)) continue;
    const Eigen::Vector2d nrm = mean.normalized();
    const Eigen::Vector2d tan(-nrm.y(), nrm.x());
    const double floor_gap = WallProximityLaw::kMinimumGapOverD * d;
    const double screen = std::exp(-0.5 * (std::max(gi, floor_gap) + std::max(gj, floor_gap)) /
                                   (law.screening * gap_height));
    const double k = unit * law.pair_squeeze * screen * tan.dot(r) / dist;
    const Eigen::Matrix2d sym = tan * nrm.transpose() + nrm * tan.transpose();
    const Eigen::Matrix2d skew = nrm * tan.transpose() - tan * nrm.transpose();
    out.coupled_resistance.block<2, 2>(3 * i, 3 * i) += k * sym;
    out.coupled_resistance.block<2, 2>(3 * j, 3 * j) -= k * sym;
    out.coupled_resistance.block<2, 2>(3 * i, 3 * j) += k * skew;
    out.coupled_resistance.block<2, 2>(3 * j, 3 * i) += k * skew.transpose();
    out.resistance[i].topLeftCorner<2, 2>() += k * sym;
    out.resistance[j].topLeftCorner<2, 2>() -= k * sym;
  }
}

}  // namespace

void add_wall_proximity(const WallProximityLaw& law, const RodGeometry& rod, const BackgroundFlow& flow,
                        double viscosity, double gap_height, RodDrag& out) {
  if (!law.active) return;
  const ChannelGeometry& walls = flow.geometry();
  const int n = rod.size();
  const double d = rod.sphere_diameter, a = 0.5 * d;
  const double unit = 3.0 * kPi * viscosity * d;  // 3 pi mu d [N s/m]
  // Beyond this gap the correction is below 1e-4 of 3 pi mu d for every
  // sphere (phi <= 7 a / (6 delta) + ..., row gains <= 2): skipped.
  const double largest = std::max({std::abs(law.normal) * (1.0 + 2.0 * std::abs(law.normal_row_gain)),
                                   std::abs(law.along) * (1.0 + 2.0 * std::abs(law.along_row_gain)),
                                   std::abs(law.normal_held) * (1.0 + 2.0 * std::abs(law.normal_row_gain)),
                                   std::abs(law.along_held) * (1.0 + 2.0 * std::abs(law.along_row_gain)),
                                   std::abs(law.squeeze), std::abs(law.squeeze_held), std::abs(law.pair_squeeze)});
  if (!(largest > 0.0)) return;
  const double reach = law.screening * gap_height * std::log(std::max(1.0, 1e4 * 2.0 * largest));
  const bool coupled = out.coupled();
  for (int i = 0; i < n; ++i) {
    const double x = rod.positions[i].x(), y = rod.positions[i].y();
    const double gap = walls.signed_distance(x, y) - a;
    if (gap > reach) continue;
    const Eigen::Vector2d nrm = walls.wall_normal(x, y);
    const Eigen::Vector2d tan(-nrm.y(), nrm.x());
    // chain neighbours along the wall (S_i) and the row's end side (E_i)
    double along_neighbours = 0.0, end_side = 0.0;
    for (int j : {i - 1, i + 1}) {
      if (j < 0 || j >= n) continue;
      const Eigen::Vector2d r = (rod.positions[j] - rod.positions[i]).head<2>();
      const double dist = r.norm();
      if (!(dist > 0.0) || dist >= 1.5 * d) continue;
      along_neighbours += std::abs(tan.dot(r)) / dist;
      end_side += tan.dot(r) / dist;
    }
    const double g = std::max(gap, WallProximityLaw::kMinimumGapOverD * d) / a;
    const double screen = std::exp(-g * a / (law.screening * gap_height));
    const double pn = wall_normal_rise(g) * screen, pt = wall_along_rise(g) * screen;
    const Eigen::Matrix2d nn = nrm * nrm.transpose(), tt = tan * tan.transpose();
    const Eigen::Matrix2d tn = tan * nrm.transpose() + nrm * tan.transpose();
    // dR, capped so that it stays positive semi-definite (|q| <= sqrt(a_n a_t))
    const double an = std::max(0.0, law.normal * pn * (1.0 + law.normal_row_gain * along_neighbours));
    const double at = std::max(0.0, law.along * pt * (1.0 + law.along_row_gain * along_neighbours));
    const double qmax = std::sqrt(an * at);
    const double q = std::clamp(law.squeeze * pn * end_side, -qmax, qmax);
    const Eigen::Matrix2d dR = unit * (an * nn + at * tt + q * tn);
    const Eigen::Matrix2d dD =
        unit * (law.normal_held * pn * (1.0 + law.normal_row_gain * along_neighbours) * nn +
                law.along_held * pt * (1.0 + law.along_row_gain * along_neighbours) * tt +
                law.squeeze_held * pn * end_side * tn);
    out.resistance[i].topLeftCorner<2, 2>() += dR;
    if (coupled) out.coupled_resistance.block<2, 2>(3 * i, 3 * i) += dR;
    out.driving_force[i].head<2>() += dD * flow.velocity(x, y);
  }
  if (coupled && law.pair_squeeze != 0.0) add_pair_squeeze(law, rod, walls, gap_height, reach, unit, out);
}

}  // namespace hsrod

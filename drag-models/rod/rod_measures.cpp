#include "rod/rod_measures.h"
#include "common/math_constants.h"

#include <cmath>

namespace hsrod {

double rod_angle_eq1(const Eigen::Vector2d& end1, const Eigen::Vector2d& end2) {
  const double pi = kPi;
  const double dx = end1.x() - end2.x();
  const double dy = end1.y() - end2.y();
  // arctan(|dx|/|dy|) written with atan2 so that dy = 0 gives pi/2.
  const double base = std::atan2(std::fabs(dx), std::fabs(dy));
  if (dx >= 0.0 && dy >= 0.0) return base;
  if (dx >= 0.0 && dy < 0.0) return pi - base;
  if (dx < 0.0 && dy < 0.0) return -pi + base;
  return -base;  // dx < 0, dy >= 0
}

double relative_deflection_eq2(const Eigen::Vector2d& end1, const Eigen::Vector2d& end2,
                               const std::vector<Eigen::Vector2d>& centres, double rod_length) {
  const Eigen::Vector2d chord = end2 - end1;
  const double chord_length = chord.norm();
  if (chord_length <= 0.0 || rod_length <= 0.0) return 0.0;
  double largest = 0.0;
  for (const auto& p : centres) {
    // |(x2-x1)(y1-y0) - (x1-x0)(y2-y1)| / |x2 - x1|, eq. (2)
    const double cross = chord.x() * (end1.y() - p.y()) - (end1.x() - p.x()) * chord.y();
    largest = std::max(largest, std::fabs(cross) / chord_length);
  }
  return largest / rod_length;
}

}  // namespace hsrod

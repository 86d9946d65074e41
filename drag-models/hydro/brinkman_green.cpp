#include "hydro/brinkman_green.h"
#include "common/math_constants.h"

#include <cmath>

namespace hsrod {

Eigen::Matrix2d brinkman_green_function(const Eigen::Vector2d& offset, double viscosity, double gap_height) {
  const double screening_length = gap_height / std::sqrt(12.0);  // l [m]
  const double r = offset.norm();
  const double R = r / screening_length;
  double a, b;
  if (R < 1e-3) {
    // Small-R expansions (the 1/R^2 terms cancel): the 2-D Stokeslet,
    // A ~ -(ln(R/2) + gamma + 1/2) / 2, B ~ 1/2.
    const double euler_gamma = 0.57721566490153286;
    a = -0.5 * (std::log(0.5 * R) + euler_gamma + 0.5);
    b = 0.5;
  } else {
    const double k0 = std::cyl_bessel_k(0.0, R);
    const double k1 = std::cyl_bessel_k(1.0, R);
    a = k0 + k1 / R - 1.0 / (R * R);
    b = -k0 - 2.0 * k1 / R + 2.0 / (R * R);
  }
  const Eigen::Vector2d rhat = offset / r;
  return (a * Eigen::Matrix2d::Identity() + b * rhat * rhat.transpose()) / (2.0 * kPi * viscosity * gap_height);
}

}  // namespace hsrod

#include "flow/brinkman_profile.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hsrod {

BrinkmanChannelProfile::BrinkmanChannelProfile(double width, double gap_height)
    : width_(width) {
  if (!(std::isfinite(width) && width > 0.0 && std::isfinite(gap_height) && gap_height > 0.0)) {
    std::ostringstream msg;
    msg << "BrinkmanChannelProfile: width W and gap_height H must be finite and > 0 m (got W = "
        << width << ", H = " << gap_height << ")";
    throw std::invalid_argument(msg.str());
  }
  k_ = std::sqrt(12.0) / gap_height;
  a_ = 0.5 * k_ * width;
  // 1 - tanh(a)/a loses digits for small a: series a^2/3 - 2 a^4/15 + 17 a^6/315.
  const double a2 = a_ * a_;
  mean_factor_ = a_ < 1e-3 ? a2 / 3.0 - 2.0 * a2 * a2 / 15.0 + 17.0 * a2 * a2 * a2 / 315.0
                           : 1.0 - std::tanh(a_) / a_;
}

// cosh(k s)/cosh(a) and sinh(k s)/cosh(a) for |k s| <= a, written with
// decaying exponentials so that wide channels (a of several hundred) do not
// overflow.
double BrinkmanChannelProfile::shape(double y) const {
  if (y <= 0.0 || y >= width_) return 0.0;
  const double ks = k_ * std::abs(y - 0.5 * width_);
  const double ratio =
      std::exp(ks - a_) * (1.0 + std::exp(-2.0 * ks)) / (1.0 + std::exp(-2.0 * a_));
  if (a_ < 1e-2) {
    // Narrow channel: 1 - cosh(b)/cosh(a) with b = k s <= a would cancel; use
    // (cosh a - cosh b)/cosh a = (a^2 - b^2)/2 [1 + (a^2 + b^2)/12
    // + (a^4 + a^2 b^2 + b^4)/360] / cosh a (next term ~ a^6/20160).
    const double a2 = a_ * a_, b2 = ks * ks;
    return 0.5 * (a2 - b2) * (1.0 + (a2 + b2) / 12.0 + (a2 * a2 + a2 * b2 + b2 * b2) / 360.0) /
           std::cosh(a_) / mean_factor_;
  }
  return (1.0 - ratio) / mean_factor_;
}

double BrinkmanChannelProfile::shape_slope(double y) const {
  if (y < 0.0 || y > width_) return 0.0;
  const double s = y - 0.5 * width_;
  const double ks = k_ * std::abs(s);
  const double sinh_ratio =
      std::exp(ks - a_) * (1.0 - std::exp(-2.0 * ks)) / (1.0 + std::exp(-2.0 * a_));
  return -(s < 0.0 ? -1.0 : 1.0) * k_ * sinh_ratio / mean_factor_;
}

}  // namespace hsrod

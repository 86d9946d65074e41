#include "load_extrapolation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hsrod::calib {

namespace {

double norm(const std::array<double, 3>& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// Aitken's estimate of one vector from three samples a window apart
// (x0 oldest); ok = false when the contraction q is not below q_max.
std::array<double, 3> aitken(const std::array<double, 3>& x0, const std::array<double, 3>& x1,
                             const std::array<double, 3>& x2, double q_max, bool& ok) {
  std::array<double, 3> d1{}, d0{};
  for (int i = 0; i < 3; ++i) {
    d1[i] = x2[i] - x1[i];
    d0[i] = x1[i] - x0[i];
  }
  const double n1 = norm(d1), n0 = norm(d0);
  if (n1 == 0.0) return x2;  // converged exactly
  const double q = n0 > 0.0 ? n1 / n0 : std::numeric_limits<double>::infinity();
  if (!(q < q_max)) {
    ok = false;
    return x2;
  }
  std::array<double, 3> out{};
  for (int i = 0; i < 3; ++i) out[i] = x2[i] + d1[i] * q / (1.0 - q);
  return out;
}

}  // namespace

LoadExtrapolation::LoadExtrapolation(int window, double length, double q_max)
    : window_(window), length_(length), q_max_(q_max) {
  if (window < 1) throw std::invalid_argument("LoadExtrapolation: window must be >= 1");
  if (!(length > 0.0)) throw std::invalid_argument("LoadExtrapolation: length scale must be > 0");
  if (!(q_max > 0.0 && q_max < 1.0)) throw std::invalid_argument("LoadExtrapolation: q_max must be in (0, 1)");
}

void LoadExtrapolation::add(const std::vector<SphereLoad>& loads) {
  if (!history_.empty() && loads.size() != history_.back().size())
    throw std::invalid_argument("LoadExtrapolation: sphere count changed");
  history_.push_back(loads);
  while (static_cast<int>(history_.size()) > 3 * window_ + 1) history_.pop_front();
}

bool LoadExtrapolation::ready() const { return static_cast<int>(history_.size()) == 3 * window_ + 1; }

std::vector<SphereLoad> LoadExtrapolation::estimate(int back, bool& ok) const {
  ok = true;
  const int n = static_cast<int>(history_.size()) - 1 - back * window_;
  if (n - 2 * window_ < 0) {
    ok = false;
    return history_.empty() ? std::vector<SphereLoad>{} : history_.back();
  }
  const auto& h0 = history_[n - 2 * window_];
  const auto& h1 = history_[n - window_];
  const auto& h2 = history_[n];
  std::vector<SphereLoad> out(h2.size());
  for (std::size_t k = 0; k < h2.size(); ++k) {
    out[k].force = aitken(h0[k].force, h1[k].force, h2[k].force, q_max_, ok);
    out[k].torque = aitken(h0[k].torque, h1[k].torque, h2[k].torque, q_max_, ok);
  }
  return out;
}

std::vector<SphereLoad> LoadExtrapolation::extrapolated() const {
  bool ok = false;
  return estimate(0, ok);
}

double LoadExtrapolation::scale_force() const {
  double s = 0.0;
  for (const auto& l : history_.back()) s = std::max(s, norm(l.force));
  return s > 0.0 ? s : 1.0;
}

double LoadExtrapolation::relative_change() const {
  if (!ready()) return std::numeric_limits<double>::infinity();
  bool ok0 = false, ok1 = false;
  const auto a = estimate(0, ok0), b = estimate(1, ok1);
  if (!ok0 || !ok1) return std::numeric_limits<double>::infinity();
  const double sf = scale_force(), st = sf * length_;
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    std::array<double, 3> df{}, dt{};
    for (int i = 0; i < 3; ++i) {
      df[i] = a[k].force[i] - b[k].force[i];
      dt[i] = a[k].torque[i] - b[k].torque[i];
    }
    worst = std::max({worst, norm(df) / sf, norm(dt) / st});
  }
  return worst;
}

double LoadExtrapolation::relative_remainder() const {
  bool ok = false;
  const auto a = estimate(0, ok);
  if (!ok) return std::numeric_limits<double>::infinity();
  const auto& raw = history_.back();
  const double sf = scale_force(), st = sf * length_;
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    std::array<double, 3> df{}, dt{};
    for (int i = 0; i < 3; ++i) {
      df[i] = a[k].force[i] - raw[k].force[i];
      dt[i] = a[k].torque[i] - raw[k].torque[i];
    }
    worst = std::max({worst, norm(df) / sf, norm(dt) / st});
  }
  return worst;
}

}  // namespace hsrod::calib

// hsrod calibration: geometric (Aitken-type) extrapolation of the sphere
// loads of a pseudo-time steady run.
//
// Plain C++17. The pseudo-time (SIMPLEC) iteration of a linear Stokes problem
// converges like a geometric series once one slow mode dominates: for each
// load vector X (force or torque of one sphere), with a window of m
// iterations, d1 = X(n) - X(n-m), d0 = X(n-m) - X(n-2m), q = |d1| / |d0|,
//     X_inf = X(n) + d1 q / (1 - q)       (Aitken's delta-squared, window m;
//                                          e.g. Brezinski & Redivo Zaglia 1991)
// The run may stop once X_inf no longer moves: the largest change of X_inf
// over one window, relative to the force scale max_k |F_k| (torques relative
// to force scale x length), is below a tolerance. A window with q >= q_max
// (convergence too slow for the estimate, or divergence) gives no estimate.
#pragma once

#include <array>
#include <deque>
#include <vector>

namespace hsrod::calib {

struct SphereLoad {
  std::array<double, 3> force{};   // [N]
  std::array<double, 3> torque{};  // [N m]
};

class LoadExtrapolation {
 public:
  // window: m iterations (>= 1); length: torque-to-force scale [m] (e.g. the
  // smallest sphere diameter); q_max: largest accepted contraction per window.
  LoadExtrapolation(int window, double length, double q_max = 0.95);

  // Loads of all spheres after one more iteration (same sphere count each call).
  void add(const std::vector<SphereLoad>& loads);

  // True once 3 windows of history exist (the estimate and its change).
  bool ready() const;
  // Extrapolated loads at the latest iteration (the latest loads where a
  // window gives no estimate).
  std::vector<SphereLoad> extrapolated() const;
  // max over spheres of |X_inf(n) - X_inf(n-m)| over the scale; +inf if not
  // ready or any window gives no estimate.
  double relative_change() const;
  // max over spheres of |X_inf(n) - X(n)| over the scale: the estimated
  // iteration error of the latest raw loads (+inf if no estimate).
  double relative_remainder() const;

 private:
  // extrapolation at history offset `back` windows (0 = latest); ok = false if none
  std::vector<SphereLoad> estimate(int back, bool& ok) const;
  double scale_force() const;

  int window_;
  double length_, q_max_;
  std::deque<std::vector<SphereLoad>> history_;  // newest at the back, at most 3 m + 1
};

}  // namespace hsrod::calib

// Finite-difference weights along one grid line with unequal neighbour
// distances, shared by the background solver (brinkman_grid_solver.cpp) and
// the level-4 window solver (brinkman_window.cpp).
#pragma once

#include <cmath>

namespace hsrod {

// A wall closer to a node than this fraction of the cell is moved out to it:
// keeps the Shortley-Weller weights (~1/theta) bounded.
constexpr double kMinWallFraction = 1e-3;

// Shortley-Weller second difference along one line with neighbours at
// distances a (minus side) and b (plus side) (Shortley & Weller 1938):
//   u'' = 2/(a+b) [(u_p - u_0)/b - (u_0 - u_m)/a]
// and the matching three-point first difference (exact for quadratics)
//   u'  = [(u_p - u_0) a/b + (u_0 - u_m) b/a] / (a+b).
struct LineWeights {
  double minus, self, plus;
};
inline LineWeights second_difference(double a, double b) {
  const double wm = 2.0 / (a * (a + b)), wp = 2.0 / (b * (a + b));
  return {wm, -(wm + wp), wp};
}
inline LineWeights first_difference(double a, double b) {
  return {-b / (a * (a + b)), (b - a) / (a * b), a / (b * (a + b))};
}

// Exponentially fitted second difference (Allen & Southwell 1955; Il'in 1969;
// for reaction-diffusion layers see Roos, Stynes & Tobiska, "Robust Numerical
// Methods for Singularly Perturbed Differential Equations", 2008, ch. I.2):
// weights exact for u = 1, exp(+kappa x) and exp(-kappa x), i.e. for the
// Brinkman wall layer u = U (1 - exp(-kappa n)) along a line whose decay rate
// is kappa [1/length], whatever kappa a or kappa b. Reduces to
// second_difference for kappa -> 0 (error O((kappa h)^2) in the weights).
inline LineWeights fitted_second_difference(double a, double b, double kappa) {
  if (!(kappa * (a + b) > 1e-3)) return second_difference(a, b);
  const double a11 = std::expm1(-kappa * a), a12 = std::expm1(kappa * b);
  const double a21 = std::expm1(kappa * a), a22 = std::expm1(-kappa * b);
  const double det = a11 * a22 - a12 * a21, k2 = kappa * kappa;
  const double wm = k2 * (a22 - a12) / det, wp = k2 * (a11 - a21) / det;
  return {wm, -(wm + wp), wp};
}

// Wall-layer profile along a line leaving a wall at rate kappa [1/length]:
// phi(s) = (1 - exp(-kappa s)) / kappa and its integral Phi(s) = int_0^s phi,
// both normalised so that kappa -> 0 gives the linear no-slip profile
// (phi = s, Phi = s^2 / 2).
inline double wall_layer_shape(double s, double kappa) {
  return kappa * s > 1e-8 ? -std::expm1(-kappa * s) / kappa : s;
}
inline double wall_layer_shape_integral(double s, double kappa) {
  const double x = kappa * s;
  if (x < 1e-2) return s * s * (0.5 - x / 6.0 + x * x / 24.0);
  return (s - wall_layer_shape(s, kappa)) / kappa;
}

}  // namespace hsrod

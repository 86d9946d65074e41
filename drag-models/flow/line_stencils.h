// Finite-difference weights along one grid line with unequal neighbour
// distances, shared by the background solver (brinkman_grid_solver.cpp) and
// the level-4 window solver (brinkman_window.cpp).
#pragma once

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

}  // namespace hsrod

// Peskin's 4-point regularised delta function (Peskin, Acta Numerica 11,
// 2002), r in kernel widths (lattice cells): sum_j phi(r - j) = 1,
// sum_j (r - j) phi(r - j) = 0 and sum_j phi(r - j)^2 = 3/8 for every r.
// Spreads a sphere's force onto level 4's window lattice and interpolates
// the window's velocity back (hydro/twoway_window_model.cpp,
// hydro/twoway_lattice_green.cpp).
#pragma once

#include <algorithm>
#include <cmath>

namespace hsrod {

inline double peskin_kernel(double r) {
  r = std::abs(r);
  if (r < 1.0) return (3.0 - 2.0 * r + std::sqrt(1.0 + 4.0 * r - 4.0 * r * r)) / 8.0;
  if (r < 2.0) return (5.0 - 2.0 * r - std::sqrt(std::max(0.0, -7.0 + 12.0 * r - 4.0 * r * r))) / 8.0;
  return 0.0;
}

}  // namespace hsrod

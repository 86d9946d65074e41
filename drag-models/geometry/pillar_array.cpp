#include "geometry/pillar_array.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace hsrod {
namespace {

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("pillars: " + what); }

std::string num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

void check_lattice(const PillarLattice& p, double length, double x_lo) {
  if (!(std::isfinite(p.radius) && p.radius > 0.0))
    fail("pillar radius R must be a finite number > 0 m (got " + num(p.radius) + ")");
  if (!(std::isfinite(p.spacing_x) && p.spacing_x > 2.0 * p.radius))
    fail("column spacing spacing_x must be > 2R = " + num(2.0 * p.radius) +
         " m, else neighbouring columns overlap (got " + num(p.spacing_x) + " m)");
  if (!(std::isfinite(p.spacing_y) && p.spacing_y > 2.0 * p.radius))
    fail("pillar spacing spacing_y must be > 2R = " + num(2.0 * p.radius) +
         " m, else the pillars of a column overlap (got " + num(p.spacing_y) + " m)");
  if (!(std::isfinite(p.row_shift) && p.row_shift >= 0.0 && p.row_shift < 1.0))
    fail("row_shift (lateral shift per column / spacing_y) must be in [0, 1) (got " + num(p.row_shift) + ")");
  if (!(std::isfinite(p.x_first) && std::isfinite(p.x_last) && p.x_first <= p.x_last))
    fail("the x-range of the columns must have x0 <= x1 (got x0 = " + num(p.x_first) + " m, x1 = " +
         num(p.x_last) + " m)");
  const double x_hi = x_lo + length;
  if (!(p.x_first - p.radius > x_lo && p.x_last + p.radius < x_hi))
    fail("the columns must stay clear of the inlet and outlet: x0 and x1 in (" + num(x_lo + p.radius) + ", " +
         num(x_hi - p.radius) + ") m for R = " + num(p.radius) + " m (got x0 = " + num(p.x_first) + " m, x1 = " +
         num(p.x_last) + " m)");
}

}  // namespace

std::vector<ZCylinder> pillar_array(const PillarLattice& p, double length, double width, double x_lo,
                                    double y_lo) {
  check_lattice(p, length, x_lo);
  const double gap = pillar_gap(p), centre = y_lo + 0.5 * width;
  // A pillar is kept when it leaves >= G/2 to each side wall.
  const double y_min = y_lo + p.radius + 0.5 * gap, y_max = y_lo + width - p.radius - 0.5 * gap;
  if (y_min > y_max)
    fail("no pillar fits across the channel: width W = " + num(width) + " m must be >= 2R + G = " +
         num(2.0 * p.radius + gap) + " m (R = " + num(p.radius) + " m, gap G = spacing_y - 2R = " + num(gap) +
         " m)");
  std::vector<ZCylinder> pillars;
  // Tolerance on the column count: x_last given as x_first + n spacing_x
  // must include column n despite rounding.
  const int columns = static_cast<int>(std::floor((p.x_last - p.x_first) / p.spacing_x + 1e-9)) + 1;
  for (int i = 0; i < columns; ++i) {
    const double x = p.x_first + i * p.spacing_x;
    const double shift = i * p.row_shift - std::floor(i * p.row_shift);  // in [0, 1)
    const double first = centre + shift * p.spacing_y;
    const int j_lo = static_cast<int>(std::ceil((y_min - first) / p.spacing_y - 1e-12));
    const int j_hi = static_cast<int>(std::floor((y_max - first) / p.spacing_y + 1e-12));
    for (int j = j_lo; j <= j_hi; ++j) pillars.push_back({x, first + j * p.spacing_y, p.radius});
  }
  return pillars;
}

double narrowest_pillar_gap(const PillarLattice& p) {
  // Neighbouring columns: the nearest pillar is offset by the shift s or
  // s - 1 (in units of spacing_y), s = row_shift.
  const double s = p.row_shift;
  const double dy = std::min(s, 1.0 - s) * p.spacing_y;
  const double between_columns = std::hypot(p.spacing_x, dy) - 2.0 * p.radius;
  return std::min(pillar_gap(p), between_columns);
}

}  // namespace hsrod

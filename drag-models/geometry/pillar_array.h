// A lattice of pillars (z-cylinders spanning the gap) tilted as in
// deterministic lateral displacement (DLD; Huang et al., Science 304, 987,
// 2004; Inglis et al., Lab Chip 6, 655, 2006): columns of pillars across the
// channel, spaced spacing_x along the flow (x) and spacing_y across it (y);
// each column is shifted in y by row_shift * spacing_y against the one
// upstream, so the pattern repeats after 1 / row_shift columns. Inglis's
// critical diameter for the gap G = spacing_y - 2R is D_c = 2 beta with the
// first-streamline width beta carrying the fraction row_shift of the gap's flux.
#pragma once

#include "geometry/channel_geometry.h"

#include <vector>

namespace hsrod {

struct PillarLattice {
  double radius = 0.0;     // pillar radius R [m], > 0
  double x_first = 0.0;    // x of the first column of centres [m]
  double x_last = 0.0;     // columns at x_first + i spacing_x <= x_last [m]
  double spacing_x = 0.0;  // column spacing along the flow lambda_x [m], > 2R
  double spacing_y = 0.0;  // pillar spacing within a column lambda_y [m], > 2R
  double row_shift = 0.0;  // epsilon: y-shift per column / spacing_y [-], in [0, 1)
};

// Gap between neighbouring pillars of one column, G = spacing_y - 2R [m].
inline double pillar_gap(const PillarLattice& p) { return p.spacing_y - 2.0 * p.radius; }

// The pillars of `lattice` in the channel [x_lo, x_lo + length] x
// [y_lo, y_lo + width] [m]. Column 0 has a pillar on the channel's centre
// line y_lo + width/2; column i's pillars sit at
// y_lo + width/2 + (j + i row_shift) spacing_y for every integer j that
// leaves at least G/2 between the pillar and each side wall (so no gap of the
// array is narrower than G/2). Throws std::invalid_argument naming the
// parameter and its accepted range: R <= 0, spacing <= 2R (overlapping
// pillars), row_shift outside [0, 1), x_first > x_last, a column not clear of
// the inlet or outlet (x_lo < x - R, x + R < x_lo + length), or no pillar
// fitting across the channel.
std::vector<ZCylinder> pillar_array(const PillarLattice& lattice, double length, double width,
                                    double x_lo = 0.0, double y_lo = 0.0);

// Smallest surface-to-surface distance [m] between two pillars of the array
// (within a column G, between neighbouring columns
// min over the shifted neighbours of the centre distance minus 2R).
double narrowest_pillar_gap(const PillarLattice& lattice);

}  // namespace hsrod

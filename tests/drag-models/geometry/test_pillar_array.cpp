// The DLD pillar lattice (geometry/pillar_array.h), measured pillar by
// pillar: the column spacing, the lateral shift per column, the gaps between
// all pillar pairs against narrowest_pillar_gap, the clearance to the side
// walls, and the refusals of overlapping pillars, pillars at the inlet or
// outlet, a row shift outside [0, 1) and a channel too narrow for one pillar.
#include "geometry/pillar_array.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

using namespace hsrod;

namespace {

constexpr double um = 1e-6;
// A realistic DLD array (Inglis et al. 2006: G ~ lambda/2, epsilon = 0.1):
// R = 10 um, lambda = 40 um (G = 20 um), 10 columns, in a 600 x 200 um channel.
PillarLattice example_lattice() {
  PillarLattice p;
  p.radius = 10 * um;
  p.x_first = 100 * um;
  p.x_last = 460 * um;
  p.spacing_x = 40 * um;
  p.spacing_y = 40 * um;
  p.row_shift = 0.1;
  return p;
}
constexpr double kLength = 600 * um, kWidth = 200 * um;

std::string message_of(const PillarLattice& p, double width = kWidth) {
  try {
    pillar_array(p, kLength, width);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(PillarArray, ColumnsAreSpacedAndShiftedByEpsilonPerColumn) {
  const PillarLattice p = example_lattice();
  const auto pillars = pillar_array(p, kLength, kWidth);
  std::map<int, int> per_column;
  for (const ZCylinder& c : pillars) {
    const double column = (c.center_x - p.x_first) / p.spacing_x;
    const int i = static_cast<int>(std::lround(column));
    EXPECT_NEAR(column, i, 1e-9);
    ++per_column[i];
    // (y - W/2) / lambda_y - i epsilon is a whole number: the shift per column.
    const double rows = (c.center_y - 0.5 * kWidth) / p.spacing_y - i * p.row_shift;
    EXPECT_NEAR(rows, std::round(rows), 1e-9) << "pillar at (" << c.center_x << ", " << c.center_y << ")";
    EXPECT_DOUBLE_EQ(c.radius, p.radius);
  }
  // x_last = x_first + 9 lambda_x: columns 0..9.
  ASSERT_EQ(per_column.size(), 10u);
  EXPECT_EQ(per_column.begin()->first, 0);
  EXPECT_EQ(per_column.rbegin()->first, 9);
  // Column 0: pillars at W/2 + j lambda, |j lambda| <= W/2 - R - G/2 = 80 um: j = -2..2.
  EXPECT_EQ(per_column[0], 5);
}

TEST(PillarArray, EveryPairAndWallGapMeasured) {
  for (double shift : {0.0, 0.1, 0.25, 0.5, 0.9}) {
    PillarLattice p = example_lattice();
    p.row_shift = shift;
    const auto pillars = pillar_array(p, kLength, kWidth);
    double smallest = 1e300;
    for (std::size_t a = 0; a < pillars.size(); ++a)
      for (std::size_t b = a + 1; b < pillars.size(); ++b)
        smallest = std::min(smallest, std::hypot(pillars[a].center_x - pillars[b].center_x,
                                                 pillars[a].center_y - pillars[b].center_y) -
                                          2.0 * p.radius);
    EXPECT_NEAR(smallest, narrowest_pillar_gap(p), 1e-12) << "row_shift " << shift;
    const double gap = pillar_gap(p);
    for (const ZCylinder& c : pillars) {
      const double wall = std::min(c.center_y, kWidth - c.center_y) - p.radius;
      EXPECT_GE(wall, 0.5 * gap - 1e-12);
    }
    // Every pillar that leaves G/2 to the walls is there: each column holds
    // all lattice sites in [R + G/2, W - R - G/2] (a span of 4 lambda here,
    // so 4 or 5 sites).
    std::map<long, int> per_column;
    for (const ZCylinder& c : pillars) ++per_column[std::lround(c.center_x / um)];
    for (const auto& [x, n] : per_column) EXPECT_TRUE(n == 4 || n == 5) << "column x = " << x << " um: " << n;
    // The channel stays open and ChannelGeometry accepts the array.
    const ChannelGeometry channel(kLength, kWidth, 20 * um, 0.0, 0.0, pillars);
    EXPECT_GT(channel.narrowest_opening(), 0.0);
  }
}

TEST(PillarArray, RefusesBadLatticesNamingTheParameter) {
  PillarLattice p = example_lattice();
  p.spacing_y = 20 * um;  // = 2R: touching pillars
  EXPECT_NE(message_of(p).find("spacing_y must be > 2R"), std::string::npos) << message_of(p);
  p = example_lattice();
  p.spacing_x = 15 * um;
  EXPECT_NE(message_of(p).find("spacing_x must be > 2R"), std::string::npos) << message_of(p);
  p = example_lattice();
  p.row_shift = 1.0;
  EXPECT_NE(message_of(p).find("row_shift"), std::string::npos);
  p.row_shift = -0.1;
  EXPECT_NE(message_of(p).find("in [0, 1)"), std::string::npos);
  p = example_lattice();
  p.x_last = 595 * um;  // the last column reaches the outlet
  EXPECT_NE(message_of(p).find("clear of the inlet and outlet"), std::string::npos) << message_of(p);
  p = example_lattice();
  p.x_first = 5 * um;
  EXPECT_NE(message_of(p).find("clear of the inlet and outlet"), std::string::npos);
  p = example_lattice();
  p.radius = 0.0;
  EXPECT_NE(message_of(p).find("radius R must be"), std::string::npos);
  p = example_lattice();
  p.x_last = 50 * um;
  EXPECT_NE(message_of(p).find("x0 <= x1"), std::string::npos);
  // W = 35 um < 2R + G = 40 um: no pillar fits with G/2 to both walls.
  EXPECT_NE(message_of(example_lattice(), 35 * um).find("no pillar fits"), std::string::npos);
}

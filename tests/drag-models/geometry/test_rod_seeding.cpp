// Seeding of many rods (geometry/rod_seeding.h): no two rods overlap and no
// sphere touches a wall or a pore cylinder, measured sphere by sphere
// (independently of the capsule test the seeding uses); the count, the
// seed's reproducibility, the lattice's even spread, and the refusals of a
// packing that cannot be reached and of a region outside the planform.
#include "common/math_constants.h"
#include "geometry/pore_constriction.h"
#include "geometry/rod_seeding.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

using namespace hsrod;

namespace {

constexpr double kD = 3e-6;  // sphere diameter [m], the paper's pore scene

std::vector<Eigen::Vector2d> spheres_of(const SeededRod& rod, const RodSeedingRequest& r) {
  const double s = r.spacing > 0 ? r.spacing : r.sphere_diameter;
  const Eigen::Vector2d t(std::sin(rod.angle), std::cos(rod.angle));
  std::vector<Eigen::Vector2d> out;
  for (int k = 0; k < r.spheres; ++k) out.push_back(rod.centre + (k - 0.5 * (r.spheres - 1)) * s * t);
  return out;
}

// Smallest sphere-sphere surface gap between different rods [m] (all pairs).
double smallest_rod_gap(const std::vector<SeededRod>& rods, const RodSeedingRequest& r) {
  double gap = 1e300;
  for (std::size_t i = 0; i < rods.size(); ++i)
    for (std::size_t j = i + 1; j < rods.size(); ++j)
      for (const auto& p : spheres_of(rods[i], r))
        for (const auto& q : spheres_of(rods[j], r)) gap = std::min(gap, (p - q).norm() - r.sphere_diameter);
  return gap;
}

// Smallest sphere surface distance to a side wall or cylinder [m].
double smallest_wall_gap(const std::vector<SeededRod>& rods, const RodSeedingRequest& r, const ChannelGeometry& g) {
  double gap = 1e300;
  for (const SeededRod& rod : rods)
    for (const auto& p : spheres_of(rod, r)) gap = std::min(gap, g.signed_distance(p.x(), p.y()) - 0.5 * r.sphere_diameter);
  return gap;
}

// The paper's pore scene planform (Table 1): L = 600 um, W = 200 um, pore
// cylinders R = 85 um at mid-length (d_pore = 30 um), H = 20 um.
ChannelGeometry pore_scene() { return make_pore_constriction(600e-6, 200e-6, 20e-6, 85e-6, 300e-6); }

RodSeedingRequest ten_sphere_rods(int rods, SeedingLayout layout) {
  RodSeedingRequest r;
  r.rods = rods;
  r.spheres = 10;
  r.sphere_diameter = kD;
  r.min_gap = 0.1 * kD;
  r.layout = layout;
  return r;
}

}  // namespace

TEST(RodSeeding, RandomRodsInThePoreSceneNeverOverlapNorTouchWallsOrCylinders) {
  const ChannelGeometry g = pore_scene();
  const RodSeedingRequest r = ten_sphere_rods(150, SeedingLayout::random);
  const auto rods = seed_rods(g, r);
  ASSERT_EQ(rods.size(), 150u);
  EXPECT_GE(smallest_rod_gap(rods, r), r.min_gap * (1 - 1e-9));
  EXPECT_GE(smallest_wall_gap(rods, r, g), r.min_gap * (1 - 1e-9));
  for (const SeededRod& rod : rods)
    for (const auto& p : spheres_of(rod, r)) {
      EXPECT_GE(p.x(), g.x_lo());
      EXPECT_LE(p.x(), g.x_hi());
    }
}

TEST(RodSeeding, SameSeedSameRodsAnotherSeedOthers) {
  const ChannelGeometry g = pore_scene();
  RodSeedingRequest r = ten_sphere_rods(40, SeedingLayout::random);
  const auto a = seed_rods(g, r), b = seed_rods(g, r);
  r.seed = 2;
  const auto c = seed_rods(g, r);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].centre, b[i].centre);
    EXPECT_EQ(a[i].angle, b[i].angle);
  }
  EXPECT_NE(a[0].centre, c[0].centre);
}

TEST(RodSeeding, RandomAnglesAreUniformAndAFixedAngleIsKept) {
  const ChannelGeometry g(2e-3, 2e-3, 20e-6);
  RodSeedingRequest r = ten_sphere_rods(2000, SeedingLayout::random);
  const auto rods = seed_rods(g, r);
  // Dilute (area fraction ~3 %): the accepted angles stay uniform on [0, pi),
  // mean pi/2 with standard error pi / sqrt(12 n) = 0.020 rad; 4 sigma.
  double mean = 0;
  for (const auto& rod : rods) mean += rod.angle / rods.size();
  EXPECT_NEAR(mean, 0.5 * M_PI, 4 * M_PI / std::sqrt(12.0 * rods.size()));
  r.rods = 50;
  r.angle = 0.3;
  for (const auto& rod : seed_rods(g, r)) EXPECT_EQ(rod.angle, 0.3);
}

TEST(RodSeeding, LatticeSpreadsRodsEvenlyAndSkipsTheCylinders) {
  const ChannelGeometry g = pore_scene();
  RodSeedingRequest r = ten_sphere_rods(24, SeedingLayout::lattice);
  r.angle = 0.5 * M_PI;  // along the flow
  const auto rods = seed_rods(g, r);
  ASSERT_EQ(rods.size(), 24u);
  EXPECT_GE(smallest_rod_gap(rods, r), r.min_gap * (1 - 1e-9));
  EXPECT_GE(smallest_wall_gap(rods, r, g), r.min_gap * (1 - 1e-9));
  // Spread over the channel, not packed at its inlet: rods in both halves.
  int upstream = 0;
  for (const auto& rod : rods) upstream += rod.centre.x() < 0.5 * (g.x_lo() + g.x_hi());
  EXPECT_GT(upstream, 4);
  EXPECT_LT(upstream, 20);
}

// A jittered lattice: every rod within the jitter of its lattice site and
// angle, none overlapping or touching a wall, and each seed another set.
TEST(RodSeeding, JitteredLatticeStaysClearAndWithinTheJitter) {
  const ChannelGeometry g = pore_scene();
  RodSeedingRequest r = ten_sphere_rods(24, SeedingLayout::lattice);
  r.angle = 0.0;  // across the flow
  const auto sites = seed_rods(g, r);
  r.jitter_position = 3e-6;
  r.jitter_angle = 10.0 * M_PI / 180.0;
  const auto a = seed_rods(g, r);
  r.seed = 2;
  const auto b = seed_rods(g, r);
  ASSERT_EQ(a.size(), 24u);
  ASSERT_EQ(b.size(), 24u);
  EXPECT_GE(smallest_rod_gap(a, r), r.min_gap * (1 - 1e-9));
  EXPECT_GE(smallest_wall_gap(a, r, g), r.min_gap * (1 - 1e-9));
  double moved = 0.0, turned = 0.0, apart = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    moved = std::max(moved, (a[k].centre - sites[k].centre).lpNorm<Eigen::Infinity>());
    turned = std::max(turned, std::abs(a[k].angle - sites[k].angle));
    apart = std::max(apart, (a[k].centre - b[k].centre).norm());
  }
  EXPECT_LE(moved, r.jitter_position);
  EXPECT_LE(turned, r.jitter_angle);
  EXPECT_GT(moved, 0.5 * r.jitter_position);  // jittered, not the sites themselves
  EXPECT_GT(apart, 0.5 * r.jitter_position);  // another seed, other rods
  r.layout = SeedingLayout::random;           // random rods take no jitter
  EXPECT_THROW(seed_rods(g, r), std::invalid_argument);
}

TEST(RodSeeding, ExistingRodsAreKeptClearOf) {
  const ChannelGeometry g(200e-6, 60e-6, 20e-6);
  RodSeedingRequest r = ten_sphere_rods(30, SeedingLayout::random);
  const RodObstacle wall_of_rod{{100e-6, 5e-6}, {100e-6, 55e-6}, kD};  // a rod across the channel at x = 100 um
  for (const auto& rod : seed_rods(g, r, {wall_of_rod}))
    EXPECT_GE(segment_distance(rod.centre - 13.5e-6 * Eigen::Vector2d(std::sin(rod.angle), std::cos(rod.angle)),
                               rod.centre + 13.5e-6 * Eigen::Vector2d(std::sin(rod.angle), std::cos(rod.angle)),
                               wall_of_rod.end_a, wall_of_rod.end_b),
              kD + r.min_gap - 1e-15);
}

TEST(RodSeeding, SegmentDistanceOfKnownConfigurations) {
  // Crossing segments 0; parallel ones their offset; end point to segment.
  EXPECT_NEAR(segment_distance({0, -1}, {0, 1}, {-1, 0}, {1, 0}), 0.0, 1e-15);
  EXPECT_NEAR(segment_distance({0, 0}, {1, 0}, {0.5, 2}, {3, 2}), 2.0, 1e-15);
  EXPECT_NEAR(segment_distance({0, 0}, {1, 0}, {4, 4}, {4, 9}), 5.0, 1e-15);
  EXPECT_NEAR(segment_distance({0, 0}, {0, 0}, {3, -1}, {3, 1}), 3.0, 1e-15);
}

TEST(RodSeeding, AConcentrationThatCannotBePackedIsRefused) {
  const ChannelGeometry g(200e-6, 60e-6, 20e-6);
  // 400 rods of 10 spheres cover 1.07 of the planform: impossible.
  RodSeedingRequest r = ten_sphere_rods(400, SeedingLayout::random);
  r.max_trials_per_rod = 2000;
  try {
    seed_rods(g, r);
    FAIL() << "an impossible packing was accepted";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("cannot pack 400 rods"), std::string::npos) << m;
    EXPECT_NE(m.find("placed"), std::string::npos) << m;
  }
  r.layout = SeedingLayout::lattice;
  EXPECT_THROW(seed_rods(g, r), std::runtime_error);
}

TEST(RodSeeding, BadInputNamesTheParameter) {
  const ChannelGeometry g(200e-6, 60e-6, 20e-6);
  auto message = [&](RodSeedingRequest r) {
    try {
      seed_rods(g, r);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  RodSeedingRequest r = ten_sphere_rods(5, SeedingLayout::random);
  RodSeedingRequest bad = r;
  bad.rods = 0;
  EXPECT_NE(message(bad).find("rods must be >= 1"), std::string::npos);
  bad = r;
  bad.sphere_diameter = -1;
  EXPECT_NE(message(bad).find("diameter must be"), std::string::npos);
  bad = r;
  bad.spacing = 0.5 * kD;
  EXPECT_NE(message(bad).find("spacing must be >="), std::string::npos);
  bad = r;
  bad.min_gap = -1e-6;
  EXPECT_NE(message(bad).find("min_gap must be"), std::string::npos);
  bad = r;
  bad.x_min = -50e-6;  // outside the planform (x from 0 to 200 um)
  bad.x_max = 50e-6;
  EXPECT_NE(message(bad).find("inside the planform"), std::string::npos) << message(bad);
}

// The fluid area of an inflow band, against geometry: a straight channel
// band is W (x1 - x0) exactly (every sample fluid); across the paper's pore
// it is the band less two half discs, 170 x 200 um^2 - pi R^2, to 0.5 % (the
// 512 x 512 sample's cells cut by the cylinders cover 0.8 % of the band;
// their in/out errors mostly cancel). The rods of a concentration round c A.
TEST(RodSeeding, BandFluidAreaAndConcentrationMatchGeometry) {
  RodSeedingRequest band;
  band.x_min = 0.0;
  band.x_max = 35e-6;
  const ChannelGeometry straight(150e-6, 60e-6, 20e-6);
  EXPECT_NEAR(region_fluid_area(straight, band), 60e-6 * 35e-6, 1e-12 * 60e-6 * 35e-6);
  EXPECT_EQ(rods_at_concentration(straight, band, 1e10), 21);   // 1e10 / m^2 x 2.1e-9 m^2
  EXPECT_EQ(rods_at_concentration(straight, band, 0.0), 0);
  EXPECT_THROW(rods_at_concentration(straight, band, -1.0), std::invalid_argument);
  band.x_min = 215e-6;
  band.x_max = 385e-6;
  const double pore_band = 170e-6 * 200e-6 - kPi * 85e-6 * 85e-6;
  EXPECT_NEAR(region_fluid_area(pore_scene(), band), pore_band, 0.005 * pore_band);
}

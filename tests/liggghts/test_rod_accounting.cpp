// The whole-rod bookkeeping of fix rod/implicit (rod_accounting.h) on
// hand-made rods: counts, box faces, overlaps between rods.
#include "rod_accounting.h"

#include <gtest/gtest.h>

using LAMMPS_NS::GatheredSphere;

namespace {

// n spheres of radius r along x from `start`, spacing 2 r, molecule `id`.
std::vector<GatheredSphere> rod(int id, int n, Eigen::Vector3d start, Eigen::Vector3d step, double r = 1.5e-6) {
  std::vector<GatheredSphere> spheres(n);
  for (int k = 0; k < n; k++) {
    spheres[k].tag = 100 * id + k;
    spheres[k].molecule = id;
    spheres[k].position = start + k * step;
    spheres[k].radius = r;
  }
  return spheres;
}

}  // namespace

TEST(RodAccounting, CensusReportsARodThatLostSpheresOrVanished) {
  LAMMPS_NS::RodCensus census;
  std::map<int, std::vector<GatheredSphere>> rods{{1, rod(1, 10, {0, 0, 0}, {3e-6, 0, 0})},
                                                  {2, rod(2, 10, {0, 50e-6, 0}, {3e-6, 0, 0})}};
  EXPECT_EQ(census.check(rods), "");
  rods[1].resize(7);
  EXPECT_EQ(census.check(rods), "rod 1 has 7 of its 10 spheres");
  rods[1] = rod(1, 10, {0, 0, 0}, {3e-6, 0, 0});
  rods.erase(2);
  EXPECT_EQ(census.check(rods), "rod 2 (10 spheres) is gone");
}

TEST(RodAccounting, LeavingFaceIsTheNonPeriodicFaceACentreCrossed) {
  const double lo[3] = {0, 0, 0}, hi[3] = {600e-6, 200e-6, 20e-6};
  const int walls[3] = {0, 0, 0}, periodic_x[3] = {1, 0, 0};
  std::vector<Eigen::Vector3d> inside{{599e-6, 100e-6, 10e-6}}, out_x{{599e-6, 1e-6, 10e-6}, {600.1e-6, 1e-6, 10e-6}},
      out_z{{10e-6, 100e-6, -1e-9}};
  EXPECT_EQ(LAMMPS_NS::leaving_face(inside, lo, hi, walls), -1);
  EXPECT_EQ(LAMMPS_NS::leaving_face(out_x, lo, hi, walls), 1);  // +x
  EXPECT_STREQ(LAMMPS_NS::face_name(1), "+x");
  EXPECT_EQ(LAMMPS_NS::leaving_face(out_x, lo, hi, periodic_x), -1);
  EXPECT_EQ(LAMMPS_NS::leaving_face(out_z, lo, hi, walls), 4);  // -z
}

TEST(RodAccounting, FractionInsideBoxBringsTheLeadingCentreOntoTheFace) {
  const double lo[3] = {0, 0, 0}, hi[3] = {600e-6, 200e-6, 20e-6};
  const int walls[3] = {0, 0, 0}, periodic_x[3] = {1, 0, 0};
  // Two centres step +6 um in x; the front one starts 2 um before the
  // outlet, so a third of the step reaches it; the other one would not.
  const std::vector<Eigen::Vector3d> before{{595e-6, 100e-6, 10e-6}, {598e-6, 100e-6, 10e-6}},
      after{{601e-6, 100e-6, 10e-6}, {604e-6, 100e-6, 10e-6}};
  EXPECT_NEAR(LAMMPS_NS::fraction_inside_box(before, after, lo, hi, walls), 1.0 / 3.0, 1e-6);  // 2 um less 6e-13 m of 6 um
  EXPECT_LT(LAMMPS_NS::fraction_inside_box(before, after, lo, hi, walls), 1.0 / 3.0);
  EXPECT_EQ(LAMMPS_NS::fraction_inside_box(before, after, lo, hi, periodic_x), 1.0);
  EXPECT_EQ(LAMMPS_NS::fraction_inside_box(before, before, lo, hi, walls), 1.0);
  // Through the -y face: 1 um of a 4 um step.
  const std::vector<Eigen::Vector3d> low{{300e-6, 1e-6, 10e-6}}, below{{300e-6, -3e-6, 10e-6}};
  EXPECT_NEAR(LAMMPS_NS::fraction_inside_box(low, below, lo, hi, walls), 0.25, 1e-6);
}

TEST(RodAccounting, OverlapOfTwoRodsNamesThemAndTheClosestDistance) {
  std::map<int, std::vector<GatheredSphere>> rods{{1, rod(1, 5, {0, 0, 0}, {3e-6, 0, 0})},
                                                  {2, rod(2, 5, {0, 9e-6, 0}, {3e-6, 0, 0})}};
  EXPECT_EQ(LAMMPS_NS::first_rod_overlap(rods).rod_a, -1);  // 3 d apart
  rods[2] = rod(2, 5, {6e-6, -6e-6, 0}, {0, 3e-6, 0});       // crosses rod 1 at its third sphere
  const auto overlap = LAMMPS_NS::first_rod_overlap(rods);
  EXPECT_EQ(overlap.rod_a, 1);
  EXPECT_EQ(overlap.rod_b, 2);
  EXPECT_NEAR(overlap.distance_over_contact, 0.0, 1e-12);
  rods[2] = rod(2, 5, {0, 2.7e-6, 0}, {3e-6, 0, 0});  // side by side, 0.9 of the contact distance
  EXPECT_NEAR(LAMMPS_NS::first_rod_overlap(rods).distance_over_contact, 0.9, 1e-12);
}

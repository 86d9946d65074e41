// Outcome classes (rod/rod_outcome.h) on synthetic trajectories whose
// outcome and decision time follow from the stated criteria by hand.
#include "rod/rod_outcome.h"
#include "rod/rod_outcome_set.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>
#include <stdexcept>

using namespace hsrod;

namespace {

constexpr double U = 0.03;       // [m/s]
constexpr double tau = 1e-3;     // averaging time [s]
constexpr double hold = 5e-3;    // clog time [s]
constexpr double dt = 2e-6;      // sample spacing [s]

RodOutcomeCriteria criteria() {
  RodOutcomeCriteria c;
  c.mean_velocity = U;
  c.channel_centre_y = 100e-6;
  c.pass_x = 385e-6;
  c.averaging_time = tau;
  c.clog_time = hold;
  return c;
}

RodOutcomeSample sample(double t, double x, double vx, bool below, bool above) {
  RodOutcomeSample s;
  s.time = t;
  s.centre = Eigen::Vector2d(x, 100e-6);
  s.velocity_x = vx;
  s.touching_below = below;
  s.touching_above = above;
  s.contact_position = Eigen::Vector2d(x, below ? 85e-6 : 115e-6);
  return s;
}

}  // namespace

TEST(RodOutcome, FreePassageWithoutContactDecidedWhenCentreCrossesPassX) {
  RodOutcomeTracker tracker(criteria());
  double x = 150e-6;
  int k = 0;
  while (!tracker.decided() && k < 100000) {
    x += U * dt;
    tracker.update(sample(++k * dt, x, U, false, false));
  }
  EXPECT_EQ(tracker.outcome(), RodOutcome::passed_without_contact);
  EXPECT_FALSE(tracker.touched());
  EXPECT_LT(tracker.first_contact_time(), 0.0);
  // Crossing after (385 - 150) um / U.
  EXPECT_NEAR(tracker.decision_time(), 235e-6 / U, 2 * dt);
  EXPECT_GT(tracker.decision_centre().x(), 385e-6);
}

TEST(RodOutcome, ContactOnTheWayRecordsFirstContactAndGivesPassedWithContact) {
  RodOutcomeTracker tracker(criteria());
  double x = 150e-6;
  int k = 0;
  while (!tracker.decided() && k < 100000) {
    ++k;
    x += U * dt;
    const bool touching = x > 280e-6 && x < 300e-6;  // brushes the lower cylinder
    tracker.update(sample(k * dt, x, U, touching, false));
  }
  EXPECT_EQ(tracker.outcome(), RodOutcome::passed_with_contact);
  EXPECT_NEAR(tracker.first_contact_time(), 130e-6 / U, 2 * dt);
  EXPECT_NEAR(tracker.first_contact_position().x(), 280e-6, U * dt * 1.01);
  EXPECT_DOUBLE_EQ(tracker.first_contact_position().y(), 85e-6);
}

TEST(RodOutcome, VelocityFlippingSignEveryStepIsClassifiedClogged) {
  // Rattling in place between both cylinders: v_x = +-2U alternately, mean 0.
  RodOutcomeTracker tracker(criteria());
  int k = 0;
  while (!tracker.decided() && k < 100000) {
    ++k;
    tracker.update(sample(k * dt, 250e-6, (k % 2 ? 2.0 : -2.0) * U, true, true));
  }
  ASSERT_EQ(tracker.outcome(), RodOutcome::clogged);
  // The average starts at +2 (the first sample) and decays as 2 exp(-t/tau):
  // below 0.05 after tau ln 40, then the clog time. The alternation adds
  // +-2 dt/tau = +-0.004 to the average; where the average falls at 0.05/tau
  // that moves the crossing by up to 0.004/0.05 tau = 0.08 tau.
  const double expected = tau * std::log(2.0 / 0.05) + hold;
  EXPECT_NEAR(tracker.decision_time(), expected, 0.1 * tau);
}

TEST(RodOutcome, StalledAgainstOneCylinderOnlyIsNotClogged) {
  RodOutcomeTracker both(criteria());
  RodOutcomeCriteria any = criteria();
  any.require_both_sides = false;
  RodOutcomeTracker one_side(any);
  for (int k = 1; k <= 20000; ++k) {  // 40 ms, 8 clog times
    both.update(sample(k * dt, 250e-6, 0.0, true, false));
    one_side.update(sample(k * dt, 250e-6, 0.0, true, false));
  }
  EXPECT_FALSE(both.decided());
  EXPECT_TRUE(both.stalled());
  EXPECT_FALSE(both.pinned());
  EXPECT_EQ(one_side.outcome(), RodOutcome::clogged);
  EXPECT_NEAR(one_side.decision_time(), hold + dt, 2 * dt);
}

TEST(RodOutcome, HysteresisBetweenStallAndReleaseRatios) {
  // A rod creeping at 0.07 U (between 0.05 and 0.1) is not stalled if it
  // never was; one that first stopped stays stalled while creeping so.
  RodOutcomeTracker creeping(criteria());
  RodOutcomeTracker stopped_then_creeping(criteria());
  for (int k = 1; k <= 1000; ++k) stopped_then_creeping.update(sample(k * dt, 250e-6, 0.0, true, true));
  ASSERT_TRUE(stopped_then_creeping.stalled());
  for (int k = 1; k <= 1600; ++k) {
    creeping.update(sample(k * dt, 250e-6, 0.07 * U, true, true));
    stopped_then_creeping.update(sample((1000 + k) * dt, 250e-6, 0.07 * U, true, true));
  }
  EXPECT_FALSE(creeping.stalled());
  EXPECT_FALSE(creeping.decided());
  EXPECT_TRUE(stopped_then_creeping.stalled());
  // Trapped since the first sample: clogged once 5 ms (2500 samples) have passed.
  EXPECT_EQ(stopped_then_creeping.outcome(), RodOutcome::clogged);
}

TEST(RodOutcome, FlickeringContactStaysPinned) {
  // Contacts on the two sides on alternate samples only.
  RodOutcomeTracker tracker(criteria());
  int k = 0;
  while (!tracker.decided() && k < 100000) {
    ++k;
    tracker.update(sample(k * dt, 250e-6, 0.0, k % 2 == 0, k % 2 == 1));
  }
  EXPECT_EQ(tracker.outcome(), RodOutcome::clogged);
  EXPECT_NEAR(tracker.decision_time(), 2 * dt + hold, 2 * dt);
}

TEST(RodOutcome, ShortStopThenEscapeIsPassageWithContact) {
  // Held 3 ms (< clog time 5 ms) between the cylinders, then it slips through.
  RodOutcomeTracker tracker(criteria());
  double x = 250e-6;
  int k = 0;
  while (!tracker.decided() && k < 100000) {
    ++k;
    const double t = k * dt;
    const bool held = t < 3e-3;
    const double v = held ? 0.0 : U;
    x += v * dt;
    tracker.update(sample(t, x, v, held, held));
    if (held) {
      EXPECT_FALSE(tracker.decided());
    }
  }
  EXPECT_EQ(tracker.outcome(), RodOutcome::passed_with_contact);
  EXPECT_NEAR(tracker.first_contact_time(), dt, 1e-12);
}

TEST(RodOutcome, OnceDecidedTheOutcomeStays) {
  RodOutcomeTracker tracker(criteria());
  for (int k = 1; k <= 3000; ++k) tracker.update(sample(k * dt, 250e-6, 0.0, true, true));
  ASSERT_EQ(tracker.outcome(), RodOutcome::clogged);
  tracker.update(sample(1.0, 500e-6, U, false, false));
  EXPECT_EQ(tracker.outcome(), RodOutcome::clogged);
}

TEST(RodOutcome, BadCriteriaNameTheField) {
  RodOutcomeCriteria c = criteria();
  c.mean_velocity = 0.0;
  EXPECT_THROW(RodOutcomeTracker{c}, std::invalid_argument);
  c = criteria();
  c.release_ratio = 0.04;  // below stall_ratio 0.05
  try {
    RodOutcomeTracker t(c);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("release_ratio"), std::string::npos);
  }
  c = criteria();
  c.clog_time = -1.0;
  EXPECT_THROW(RodOutcomeTracker{c}, std::invalid_argument);
}

// Several rods (rod/rod_outcome_set.h): a rod resting against a rod trapped
// at the cylinders, itself touching no wall.
namespace {

std::map<int, RodOutcomeSample> two_rods(double t, bool front_pinned, double behind_vx) {
  return {{1, sample(t, 285e-6, 0.0, front_pinned, front_pinned)}, {2, sample(t, 279e-6, behind_vx, false, false)}};
}

}  // namespace

TEST(RodOutcomeSet, RodRestingOnATrappedRodIsClassifiedCloggedHeldByIt) {
  RodOutcomeSet rods(criteria());
  int k = 0;
  while (!(rods.trackers().count(2) && rods.trackers().at(2).decided()) && k < 100000) {
    ++k;
    rods.update(k * dt, two_rods(k * dt, true, 0.0), {{1, 2}});
  }
  const RodOutcomeTracker& front = rods.trackers().at(1);
  const RodOutcomeTracker& behind = rods.trackers().at(2);
  ASSERT_EQ(front.outcome(), RodOutcome::clogged);
  EXPECT_EQ(front.held_by(), -1);  // the walls
  ASSERT_EQ(behind.outcome(), RodOutcome::clogged);
  EXPECT_EQ(behind.held_by(), 1);
  EXPECT_FALSE(behind.touched());  // never touched a wall
  // Both stalled from the first sample (v = 0), trapped from it: clogged
  // after the clog time, in the same sample.
  EXPECT_NEAR(front.decision_time(), hold + dt, 2 * dt);
  EXPECT_NEAR(behind.decision_time(), front.decision_time(), 1e-12);
}

TEST(RodOutcomeSet, RodAloneBehindTheTrappedOneIsNotHeld) {
  // The same rods without contact between them: the one behind stays en route.
  RodOutcomeSet rods(criteria());
  for (int k = 1; k <= 10000; ++k) rods.update(k * dt, two_rods(k * dt, true, 0.0), {});
  EXPECT_EQ(rods.trackers().at(1).outcome(), RodOutcome::clogged);
  EXPECT_FALSE(rods.trackers().at(2).decided());
  EXPECT_TRUE(rods.trackers().at(2).stalled());
}

TEST(RodOutcomeSet, RodTouchingARodAwayFromTheWallsIsNotHeld) {
  // The front rod is stalled but touches no wall (e.g. two rods stopped
  // together by an external force): neither is an anchor, neither clogs.
  RodOutcomeSet rods(criteria());
  for (int k = 1; k <= 10000; ++k) rods.update(k * dt, two_rods(k * dt, false, 0.0), {{1, 2}});
  EXPECT_FALSE(rods.trackers().at(1).decided());
  EXPECT_FALSE(rods.trackers().at(2).decided());
}

TEST(RodOutcomeSet, ColumnOfThreeRodsClogsThroughTheMiddleOne) {
  // Rod 3 touches only rod 2, which touches only rod 1 at the cylinders;
  // rod 2's contact with rod 1 opens on every other sample (within tau).
  RodOutcomeSet rods(criteria());
  for (int k = 1; k <= 3000; ++k) {
    auto samples = two_rods(k * dt, true, 0.0);
    samples[3] = sample(k * dt, 273e-6, 0.0, false, false);
    std::vector<std::pair<int, int>> contacts = {{3, 2}};
    if (k % 2) contacts.push_back({2, 1});
    rods.update(k * dt, samples, contacts);
  }
  EXPECT_EQ(rods.trackers().at(2).outcome(), RodOutcome::clogged);
  EXPECT_EQ(rods.trackers().at(2).held_by(), 1);
  EXPECT_EQ(rods.trackers().at(3).outcome(), RodOutcome::clogged);
  EXPECT_EQ(rods.trackers().at(3).held_by(), 2);
}

TEST(RodOutcomeSet, HeldRodThatStartsMovingAgainIsReleased) {
  // Rod 2 rests on rod 1 for 3 ms (< clog time), then is carried away at U
  // (it slides off): its average rises above release_ratio, it is no longer
  // held, and its clock restarts; it never clogs.
  RodOutcomeSet rods(criteria());
  double x = 279e-6;
  for (int k = 1; k <= 10000; ++k) {
    const double t = k * dt;
    const bool resting = t < 3e-3;
    auto samples = two_rods(t, true, resting ? 0.0 : U);
    x += (resting ? 0.0 : U) * dt;
    samples[2].centre.x() = std::min(x, 380e-6);
    rods.update(t, samples, resting ? std::vector<std::pair<int, int>>{{1, 2}} : std::vector<std::pair<int, int>>{});
  }
  EXPECT_EQ(rods.trackers().at(1).outcome(), RodOutcome::clogged);
  EXPECT_FALSE(rods.trackers().at(2).decided());
  EXPECT_FALSE(rods.trackers().at(2).stalled());
}

TEST(RodOutcomeSet, TouchingRodPairsAreThoseWithOverlappingSpheres) {
  // Rods 1 and 2 overlap by 0.1 um at one sphere pair; rod 3 is 0.1 um
  // clear of rod 2 (sphere radius 1.5 um).
  const double r = 1.5e-6;
  std::vector<Eigen::Vector3d> x;
  std::vector<int> rod;
  for (int k = 0; k < 3; ++k) {
    x.emplace_back(0.0, 3e-6 * k, 0.0), rod.push_back(1);
    x.emplace_back(2.9e-6, 3e-6 * k + 6e-6, 0.0), rod.push_back(2);
    x.emplace_back(2.9e-6 + 3.1e-6, 3e-6 * k + 6e-6, 0.0), rod.push_back(3);
  }
  const auto pairs = touching_rod_pairs(x, std::vector<double>(x.size(), r), rod);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0], std::make_pair(1, 2));
}

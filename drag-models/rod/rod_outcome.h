// Outcome of a rod's encounter with a pore (Braesel et al., Soft Matter 2024,
// Sec. 3.5): (1) passage without wall contact, (2) passage with wall contact,
// (3) clogging by wall entrapment. The classifier follows one rod sample by
// sample (one sample per time step or per output interval) and decides once.
//
// Criteria (all times in seconds, velocities relative to the mean inflow U):
// - wall contact: a sphere of the rod touches a planform wall (a pore
//   cylinder or a side wall); the first such sample gives the time and the
//   position (the touching sphere's centre) of first contact.
// - passed: the rod's centre of mass is downstream of `pass_x`; the class is
//   (2) if the rod ever touched a planform wall, else (1).
// - clogged: the rod is "stalled" and "pinned" without interruption for
//   `clog_time`.
//     stalled: the time average of v_x / U (exponential moving average with
//       time constant `averaging_time`, exact for uneven sample spacing) fell
//       below `stall_ratio`; it stays stalled until that average exceeds
//       `release_ratio` (> stall_ratio: hysteresis). A velocity that flips
//       sign every step averages out, so a rod rattling in place is stalled.
//     pinned: touching walls on both sides of the channel centre line (both
//       pore cylinders), each within the last `averaging_time` (so a contact
//       that opens for a few steps does not reset the clock); with
//       `require_both_sides = false` any wall contact pins.
// - clogged, held by another rod (several rods, rod/rod_outcome_set.h): the
//   rod is stalled and, instead of pinned, "held": in contact (within the
//   last `averaging_time`) with a rod that is clogged or itself trapped
//   (stalled and pinned, or held), without interruption for `clog_time`.
//   The tracker is then told the holder (settle()); held_by() names it.
// Once decided, the outcome does not change.
#pragma once

#include <Eigen/Core>

namespace hsrod {

enum class RodOutcome { undecided = 0, passed_without_contact = 1, passed_with_contact = 2, clogged = 3 };

// Name for reports: "undecided", "passed without contact", ...
const char* rod_outcome_name(RodOutcome outcome);

struct RodOutcomeCriteria {
  double mean_velocity = 0.0;       // U, mean inflow velocity [m/s], > 0
  double channel_centre_y = 0.0;    // y of the centre line splitting the two sides [m]
  double pass_x = 0.0;              // centre of mass x beyond which the rod has passed [m]
  double averaging_time = 0.0;      // time constant of the v_x / U average [s], > 0
  double clog_time = 0.0;           // stalled and pinned this long -> clogged [s], > 0
  double stall_ratio = 0.05;        // <v_x>/U below this: stalled [-]
  double release_ratio = 0.1;       // <v_x>/U above this: no longer stalled [-], > stall_ratio
  bool require_both_sides = true;   // pinned needs contacts on both sides of the centre line

  // Throws std::invalid_argument naming the field and its accepted range.
  void validate() const;
};

struct RodOutcomeSample {
  double time = 0.0;                                   // [s]
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();    // centre of mass in the plane [m]
  double velocity_x = 0.0;                             // centre-of-mass velocity along the flow [m/s]
  bool touching_below = false;   // a sphere touches a planform wall with y < channel_centre_y
  bool touching_above = false;   // ... with y >= channel_centre_y
  Eigen::Vector2d contact_position = Eigen::Vector2d::Zero();  // a touching sphere's centre [m] (if any)
};

class RodOutcomeTracker {
 public:
  explicit RodOutcomeTracker(const RodOutcomeCriteria& criteria);

  // Adds a sample (times must not decrease). Returns the outcome after it.
  // Same as observe(sample) then settle(sample.time, -1): a rod alone.
  RodOutcome update(const RodOutcomeSample& sample);
  // The two halves of update(), for several rods (rod/rod_outcome_set.h):
  // observe() takes the sample (average, contacts, passage, stalled,
  // pinned); settle() then runs the clog clock with `holder` >= 0 the ID of
  // a trapped or clogged rod this one touches (-1: none).
  void observe(const RodOutcomeSample& sample);
  RodOutcome settle(double time, int holder);

  RodOutcome outcome() const { return outcome_; }
  bool decided() const { return outcome_ != RodOutcome::undecided; }
  double decision_time() const { return decision_time_; }            // [s], -1 if undecided
  Eigen::Vector2d decision_centre() const { return decision_centre_; }  // centre at the decision [m]
  bool touched() const { return first_contact_time_ >= 0.0; }
  double first_contact_time() const { return first_contact_time_; }  // [s], -1 if never
  Eigen::Vector2d first_contact_position() const { return first_contact_position_; }  // [m]
  double averaged_velocity_ratio() const { return averaged_ratio_; }  // <v_x>/U [-]
  bool stalled() const { return stalled_; }
  bool pinned() const { return pinned_; }
  // The rod holding this one when it was decided clogged (-1: the walls).
  int held_by() const { return held_by_; }
  // How long the rod has been stalled and pinned without interruption [s].
  double trapped_duration() const;

 private:
  void decide(RodOutcome outcome, double time);
  RodOutcomeCriteria criteria_;
  RodOutcome outcome_ = RodOutcome::undecided;
  bool started_ = false;
  double last_time_ = 0.0;
  Eigen::Vector2d last_centre_ = Eigen::Vector2d::Zero();  // at the last sample [m]
  double averaged_ratio_ = 0.0;
  bool stalled_ = false, pinned_ = false;
  double last_below_ = -1.0, last_above_ = -1.0;  // last contact times on each side [s]
  double trapped_since_ = -1.0;                   // [s], -1 if not trapped
  int held_by_ = -1;                              // holder when clogged (-1: walls)
  double first_contact_time_ = -1.0;
  Eigen::Vector2d first_contact_position_ = Eigen::Vector2d::Zero();
  double decision_time_ = -1.0;
  Eigen::Vector2d decision_centre_ = Eigen::Vector2d::Zero();
};

}  // namespace hsrod

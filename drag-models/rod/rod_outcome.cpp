#include "rod/rod_outcome.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace hsrod {

const char* rod_outcome_name(RodOutcome outcome) {
  switch (outcome) {
    case RodOutcome::passed_without_contact: return "passed without contact";
    case RodOutcome::passed_with_contact: return "passed with contact";
    case RodOutcome::clogged: return "clogged";
    default: return "undecided";
  }
}

void RodOutcomeCriteria::validate() const {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument(what);
  };
  require(std::isfinite(mean_velocity) && mean_velocity > 0.0, "mean_velocity must be > 0 m/s");
  require(std::isfinite(pass_x), "pass_x must be finite (m)");
  require(std::isfinite(channel_centre_y), "channel_centre_y must be finite (m)");
  require(std::isfinite(averaging_time) && averaging_time > 0.0, "averaging_time must be > 0 s");
  require(std::isfinite(clog_time) && clog_time > 0.0, "clog_time must be > 0 s");
  require(std::isfinite(stall_ratio) && stall_ratio > 0.0 && stall_ratio < 1.0, "stall_ratio must be in (0, 1)");
  require(std::isfinite(release_ratio) && release_ratio > stall_ratio && release_ratio < 1.0,
          "release_ratio must be in (stall_ratio, 1)");
}

RodOutcomeTracker::RodOutcomeTracker(const RodOutcomeCriteria& criteria) : criteria_(criteria) { criteria_.validate(); }

double RodOutcomeTracker::trapped_duration() const {
  return trapped_since_ < 0.0 ? 0.0 : last_time_ - trapped_since_;
}

RodOutcome RodOutcomeTracker::update(const RodOutcomeSample& s) {
  observe(s);
  return settle(s.time, -1);
}

void RodOutcomeTracker::observe(const RodOutcomeSample& s) {
  if (decided()) return;
  if (started_ && s.time < last_time_) throw std::invalid_argument("rod outcome: sample times must not decrease");
  const double ratio = s.velocity_x / criteria_.mean_velocity;
  if (!started_) {
    averaged_ratio_ = ratio;
    started_ = true;
  } else {
    // Exponential moving average over time constant tau, exact for a
    // piecewise-constant ratio between samples of any spacing.
    const double weight = 1.0 - std::exp(-(s.time - last_time_) / criteria_.averaging_time);
    averaged_ratio_ += weight * (ratio - averaged_ratio_);
  }
  last_time_ = s.time;

  if ((s.touching_below || s.touching_above) && first_contact_time_ < 0.0) {
    first_contact_time_ = s.time;
    first_contact_position_ = s.contact_position;
  }
  if (s.touching_below) last_below_ = s.time;
  if (s.touching_above) last_above_ = s.time;
  last_centre_ = s.centre;

  if (s.centre.x() > criteria_.pass_x) {
    decide(touched() ? RodOutcome::passed_with_contact : RodOutcome::passed_without_contact, s.time);
    return;
  }
  // Hysteresis: enter below stall_ratio, leave above release_ratio.
  if (averaged_ratio_ < criteria_.stall_ratio) stalled_ = true;
  else if (averaged_ratio_ > criteria_.release_ratio) stalled_ = false;
  auto recent = [&](double t) { return t >= 0.0 && s.time - t <= criteria_.averaging_time; };
  pinned_ = criteria_.require_both_sides ? recent(last_below_) && recent(last_above_)
                                         : recent(last_below_) || recent(last_above_);
}

RodOutcome RodOutcomeTracker::settle(double time, int holder) {
  if (decided()) return outcome_;
  if (stalled_ && (pinned_ || holder >= 0)) {
    if (trapped_since_ < 0.0) trapped_since_ = time;
    if (time - trapped_since_ >= criteria_.clog_time) {
      held_by_ = pinned_ ? -1 : holder;
      decide(RodOutcome::clogged, time);
    }
  } else {
    trapped_since_ = -1.0;
  }
  return outcome_;
}

void RodOutcomeTracker::decide(RodOutcome outcome, double time) {
  outcome_ = outcome;
  decision_time_ = time;
  decision_centre_ = last_centre_;
}

}  // namespace hsrod

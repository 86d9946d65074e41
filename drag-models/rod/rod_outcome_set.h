// Outcomes of several rods in one scene: each rod has its own
// RodOutcomeTracker (rod/rod_outcome.h); this class adds what one rod
// cannot know alone, that it is held by another rod.
//
// A rod that rests against a rod trapped at the pore cylinders is stopped
// by it, not by the walls: alone it would be "en route" for ever. Criteria
// (times in seconds; the contact rule of the walls, applied to rods):
// - rod contact: a sphere of rod a and a sphere of rod b overlap (centre
//   distance below the sum of the radii); a pair stays "in contact" for
//   `averaging_time` after its last overlap, so a contact that opens for a
//   few steps does not reset the clock (as for walls);
// - anchors: rods already decided clogged, and undecided rods that are
//   stalled and pinned by the walls;
// - held: an undecided, stalled rod in contact with an anchor or with a rod
//   held (transitively: a column of rods behind a trapped one); its holder
//   is the neighbour through which it was reached (breadth first, so the
//   rod nearest the walls in contact steps);
// - a held rod's clog clock runs as a pinned rod's does (stalled and held
//   without interruption for `clog_time`): then clogged, held_by() = holder.
// A rod pinned by the walls itself is classified as before (held_by -1).
#pragma once

#include "rod/rod_outcome.h"

#include <map>
#include <utility>
#include <vector>

namespace hsrod {

// The pairs (a < b) of rod IDs with a sphere of a and a sphere of b
// overlapping: |x_i - x_j| < r_i + r_j (centres [m], radii [m], rod ID per
// sphere). Rods whose bounding boxes are apart are skipped.
std::vector<std::pair<int, int>> touching_rod_pairs(const std::vector<Eigen::Vector3d>& centres,
                                                    const std::vector<double>& radii, const std::vector<int>& rod_ids);

class RodOutcomeSet {
 public:
  explicit RodOutcomeSet(const RodOutcomeCriteria& criteria);

  // One sample of every rod present at `time` (keyed by rod ID; times must
  // not decrease) and the pairs of rod IDs whose spheres overlap now.
  void update(double time, const std::map<int, RodOutcomeSample>& samples,
              const std::vector<std::pair<int, int>>& rod_contacts);

  const std::map<int, RodOutcomeTracker>& trackers() const { return trackers_; }
  // Rods touching rod `id` within the last averaging_time, by ID.
  std::vector<int> recent_partners(int id, double time) const;

 private:
  RodOutcomeCriteria criteria_;
  std::map<int, RodOutcomeTracker> trackers_;
  std::map<std::pair<int, int>, double> last_rod_contact_;  // (lower ID, higher ID) -> time [s]
};

}  // namespace hsrod

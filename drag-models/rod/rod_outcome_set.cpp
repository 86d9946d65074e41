#include "rod/rod_outcome_set.h"

#include <algorithm>
#include <deque>
#include <set>
#include <stdexcept>

namespace hsrod {

std::vector<std::pair<int, int>> touching_rod_pairs(const std::vector<Eigen::Vector3d>& centres,
                                                    const std::vector<double>& radii, const std::vector<int>& rod_ids) {
  if (centres.size() != radii.size() || centres.size() != rod_ids.size())
    throw std::invalid_argument("touching_rod_pairs: centres, radii and rod IDs differ in size");
  // Per rod: its spheres and bounding box grown by its largest radius.
  struct Box {
    std::vector<std::size_t> spheres;
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
  };
  std::map<int, Box> boxes;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    Box& b = boxes[rod_ids[i]];
    b.spheres.push_back(i);
    b.lo = b.lo.cwiseMin(centres[i] - Eigen::Vector3d::Constant(radii[i]));
    b.hi = b.hi.cwiseMax(centres[i] + Eigen::Vector3d::Constant(radii[i]));
  }
  // Sweep and prune along x: boxes sorted by their lower x edge, each
  // compared only with the boxes that start before it ends, so a suspension
  // of many rods costs O(R log R) plus the overlapping pairs, not O(R^2).
  std::vector<const std::pair<const int, Box>*> order;
  order.reserve(boxes.size());
  for (const auto& entry : boxes) order.push_back(&entry);
  std::sort(order.begin(), order.end(), [](auto* a, auto* b) { return a->second.lo.x() < b->second.lo.x(); });
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t ia = 0; ia < order.size(); ++ia) {
    const Box& a = order[ia]->second;
    for (std::size_t ib = ia + 1; ib < order.size() && order[ib]->second.lo.x() <= a.hi.x(); ++ib) {
      const Box& b = order[ib]->second;
      if ((a.hi.array() < b.lo.array()).any() || (b.hi.array() < a.lo.array()).any()) continue;
      bool touching = false;
      for (std::size_t i : a.spheres) {
        for (std::size_t j : b.spheres)
          if ((centres[i] - centres[j]).norm() < radii[i] + radii[j]) {
            touching = true;
            break;
          }
        if (touching) break;
      }
      if (touching) pairs.emplace_back(std::min(order[ia]->first, order[ib]->first),
                                       std::max(order[ia]->first, order[ib]->first));
    }
  }
  // In rod-ID order, as callers and tests read them.
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

RodOutcomeSet::RodOutcomeSet(const RodOutcomeCriteria& criteria) : criteria_(criteria) { criteria_.validate(); }

std::vector<int> RodOutcomeSet::recent_partners(int id, double time) const {
  std::vector<int> partners;
  for (const auto& [pair, last] : last_rod_contact_) {
    if (time - last > criteria_.averaging_time) continue;
    if (pair.first == id) partners.push_back(pair.second);
    else if (pair.second == id) partners.push_back(pair.first);
  }
  return partners;
}

void RodOutcomeSet::update(double time, const std::map<int, RodOutcomeSample>& samples,
                           const std::vector<std::pair<int, int>>& rod_contacts) {
  for (const auto& [id, sample] : samples) {
    if (sample.time != time) throw std::invalid_argument("rod outcome set: a sample's time differs from the update's");
    auto it = trackers_.find(id);
    if (it == trackers_.end()) it = trackers_.emplace(id, RodOutcomeTracker(criteria_)).first;
    it->second.observe(sample);
  }
  for (auto [a, b] : rod_contacts) {
    if (a == b) continue;
    if (a > b) std::swap(a, b);
    last_rod_contact_[{a, b}] = time;
  }
  // Anchors, then the rods they hold, breadth first.
  std::map<int, int> holder;  // held rod -> the rod it rests against
  std::deque<int> queue;
  std::map<int, bool> reached;
  for (const auto& [id, t] : trackers_) {
    const bool anchor = t.outcome() == RodOutcome::clogged || (!t.decided() && samples.count(id) && t.stalled() && t.pinned());
    if (anchor) {
      queue.push_back(id);
      reached[id] = true;
    }
  }
  while (!queue.empty()) {
    const int id = queue.front();
    queue.pop_front();
    for (int partner : recent_partners(id, time)) {
      if (reached.count(partner) || !samples.count(partner)) continue;
      const RodOutcomeTracker& t = trackers_.at(partner);
      if (t.decided() || !t.stalled()) continue;
      reached[partner] = true;
      holder[partner] = id;
      queue.push_back(partner);
    }
  }
  for (const auto& [id, sample] : samples) {
    const auto h = holder.find(id);
    trackers_.at(id).settle(time, h == holder.end() ? -1 : h->second);
  }
}

}  // namespace hsrod

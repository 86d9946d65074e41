/* ----------------------------------------------------------------------
   hsrod - fix rod/implicit (see fix_rod_implicit.h): contact detection
   within the step. Rods are clustered by what they can reach at the step's
   start (fix_rod_implicit_clusters.cpp); a rod that moves further than that
   (a step the accuracy guard cut into substeps, a rod accelerating into a
   pore) can meet a rod it was stepped apart from. Every step is therefore
   taken first, its end positions checked, and groups whose spheres touch
   at the end are merged and stepped again together from the same start
   (the rods' contacts then enter the joint solve and the guard's substeps):
   the trial step's end positions reveal the new contact set, as the
   predictor of an implicit DEM step does. Only then are the steps
   scattered to the atoms. Where no rod meets another, the steps and their
   scatter are those taken without this check, bit for bit.
------------------------------------------------------------------------- */

#include "fix_rod_implicit.h"

#include "rod_gather.h"

#include "dynamics/rod_cluster.h"

#include <algorithm>
#include <numeric>
#include <vector>

using namespace LAMMPS_NS;

void FixRodImplicit::step_group(const RodGather &gather, const std::vector<int> &molecules,
                                const hsrod::WallContactParameters &walls) {
  if (held_rods_.count(molecules.front())) {
    hold_rod(gather.rods.at(molecules.front()));
    return;
  }
  PendingStep step;
  bool taken;
  if (molecules.size() == 1) {
    step.molecules = molecules;
    step.alone = true;
    taken = step_rod_alone(molecules.front(), gather.rods.at(molecules.front()), walls, step.totals);
  } else {
    taken = step_cluster(gather, molecules, walls, step);
  }
  if (taken) {
    pending_.push_back(std::move(step));
  } else if (!step.alone) {  // held at a box face: its bond state as stepped
    joint_strain_ = std::max(joint_strain_, step.strain);
    joint_energy_ += step.energy;
  }
}

// One round: the groups that touch at their steps' end, joined
// transitively, stepped again as one cluster each. False: none touched.
bool FixRodImplicit::merge_rods_meeting_in_step(const RodGather &gather, const hsrod::WallContactParameters &walls) {
  std::vector<const std::vector<Eigen::Vector3d> *> ends;
  std::vector<const std::vector<double> *> radii;
  for (const PendingStep &p : pending_) {
    const hsrod::OverdampedRod &rod = p.alone ? scratch_by_rod_[p.molecules.front()].rod : p.rod;
    ends.push_back(&rod.positions);
    radii.push_back(&rod.radii);
  }
  const auto touching = hsrod::touching_groups(ends, radii);
  if (touching.empty()) return false;
  std::vector<int> root(pending_.size());
  std::iota(root.begin(), root.end(), 0);
  const auto find = [&root](int a) {
    while (root[a] != a) a = root[a] = root[root[a]];
    return a;
  };
  for (const auto &[a, b] : touching) {
    const int ra = find(a), rb = find(b);
    if (ra != rb) root[std::max(ra, rb)] = std::min(ra, rb);
  }
  std::vector<std::vector<int>> merged(pending_.size());
  std::vector<PendingStep> kept;
  for (std::size_t k = 0; k < pending_.size(); ++k) {
    const int r = find(static_cast<int>(k));
    bool alone_group = true;
    for (std::size_t m = 0; m < pending_.size() && alone_group; ++m)
      if (m != k && find(static_cast<int>(m)) == r) alone_group = false;
    if (alone_group) {
      kept.push_back(std::move(pending_[k]));
      continue;
    }
    merged[r].insert(merged[r].end(), pending_[k].molecules.begin(), pending_[k].molecules.end());
    // A rod's own step is discarded: its bond state is the cluster's now.
    if (pending_[k].alone)
      stepped_rods_.erase(std::remove(stepped_rods_.begin(), stepped_rods_.end(), pending_[k].molecules.front()),
                          stepped_rods_.end());
  }
  pending_ = std::move(kept);
  for (std::vector<int> &molecules : merged) {
    if (molecules.empty()) continue;
    std::sort(molecules.begin(), molecules.end());
    ++rods_met_in_step_;
    step_group(gather, molecules, walls);
  }
  return true;
}

std::vector<std::vector<int>> FixRodImplicit::step_all(const RodGather &gather,
                                                       const hsrod::WallContactParameters &walls, StepTotals &totals) {
  const std::vector<std::vector<int>> clusters = step_clusters(gather);
  pending_.clear();
  joint_strain_ = joint_energy_ = 0.0;
  // Rods alone first, then clusters: the order the steps were always taken in.
  for (const std::vector<int> &cluster : clusters)
    if (cluster.size() == 1) step_group(gather, cluster, walls);
  for (const std::vector<int> &cluster : clusters)
    if (cluster.size() > 1) step_group(gather, cluster, walls);
  if (rod_contact_)
    for (int round = 0; round < kContactRounds && merge_rods_meeting_in_step(gather, walls); ++round) {
    }
  // Totals summed in the same order (rods alone, then clusters).
  std::vector<std::vector<int>> stepped;
  for (int joint = 0; joint < 2; ++joint)
    for (const PendingStep &p : pending_) {
      if (p.alone == (joint == 1)) continue;
      const StepTotals &t = p.totals;
      totals.largest = std::max(totals.largest, t.largest);
      totals.wall_force += t.wall_force;
      totals.rod_contact_force += t.rod_contact_force;
      totals.contacts += t.contacts;
      totals.rod_contacts += t.rod_contacts;
      totals.substeps = std::max(totals.substeps, t.substeps);
      if (p.alone) {
        RodScratch &scratch = scratch_by_rod_[p.molecules.front()];
        const hsrod::OverdampedStepResult &result = guard_ ? scratch.report.result : scratch.result;
        scatter_rod(gather.rods.at(p.molecules.front()), scratch.rod, scratch.before, result, scratch.drag);
      } else {
        joint_strain_ = std::max(joint_strain_, p.strain);
        joint_energy_ += p.energy;
        scatter_rod(p.spheres, p.rod, p.before, p.result, p.drag);
      }
      stepped.push_back(p.molecules);
    }
  return stepped;
}

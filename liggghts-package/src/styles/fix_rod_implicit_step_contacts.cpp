/* ----------------------------------------------------------------------
   hsrod - fix rod/implicit (see fix_rod_implicit.h): contact detection
   within the step. Rods are clustered by what they can reach at the step's
   start (fix_rod_implicit_clusters.cpp); a rod that moves further than that
   (a step the accuracy guard cut into substeps, a rod accelerating into a
   pore) can meet a rod it was stepped apart from. Every step is therefore
   taken first, the spheres' paths from start to end checked, and groups
   whose spheres come within contact along them are merged and stepped again together from the same start
   (the rods' contacts then enter the joint solve and the guard's substeps):
   the trial step's displacements reveal the new contact set, as the
   predictor of an implicit DEM step does. Only then are the steps
   scattered to the atoms. Where no rod meets another, the steps and their
   scatter are those taken without this check, bit for bit.
------------------------------------------------------------------------- */

#include "fix_rod_implicit.h"

#include "comm.h"
#include "lmptype.h"
#include "rod_gather.h"
#include "update.h"

#include "dynamics/rod_cluster.h"

#include <algorithm>
#include <cstdio>
#include <string>
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
    step.scratch = &work_by_rod_[molecules.front()].scratch;
    taken = step_rod_alone(molecules.front(), gather.rods.at(molecules.front()), walls, step.totals);
  } else {
    taken = step_cluster(gather, molecules, walls, step);
  }
  if (taken) {
    if (apart()) {  // its obstruction forces at the step's velocities, for the groups stepped after it
      const hsrod::OverdampedStepResult &result =
          step.alone ? (guard_ ? step.scratch->report.result : step.scratch->result) : step.result;
      update_obstruction(molecules, result.velocities);
    }
    pending_.push_back(std::move(step));
  } else if (!step.alone) {  // held at a box face: its bond state as stepped
    joint_strain_ = std::max(joint_strain_, step.strain);
    joint_energy_ += step.energy;
  }
}

// One round: the groups whose spheres' paths in their steps meet, joined
// transitively, stepped again as one cluster each. False: none touched.
bool FixRodImplicit::merge_rods_meeting_in_step(const RodGather &gather, const hsrod::WallContactParameters &walls) {
  std::vector<const std::vector<Eigen::Vector3d> *> starts, ends;
  std::vector<const std::vector<double> *> radii;
  for (const PendingStep &p : pending_) {
    const RodScratch *scratch = p.alone ? p.scratch : nullptr;
    const hsrod::OverdampedRod &rod = scratch ? scratch->rod : p.rod;
    starts.push_back(scratch ? &scratch->before : &p.before);
    ends.push_back(&rod.positions);
    radii.push_back(&rod.radii);
  }
  // Rods held at a box face are obstacles at rest (start = end).
  std::vector<int> held(held_rods_.begin(), held_rods_.end());
  std::vector<std::vector<Eigen::Vector3d>> held_positions;
  std::vector<std::vector<double>> held_radii;
  held_positions.reserve(held.size());
  held_radii.reserve(held.size());
  for (int molecule : held) {
    held_positions.emplace_back();
    held_radii.emplace_back();
    for (const GatheredSphere &sphere : gather.rods.at(molecule)) {
      held_positions.back().push_back(sphere.position);
      held_radii.back().push_back(sphere.radius);
    }
    starts.push_back(&held_positions.back());
    ends.push_back(&held_positions.back());
    radii.push_back(&held_radii.back());
  }
  const auto touching = hsrod::groups_meeting_in_step(starts, ends, radii, meeting_search_);
  const int stepped = static_cast<int>(pending_.size());
  // Held rods touching each other (the pile) are no business of the step.
  if (std::none_of(touching.begin(), touching.end(), [stepped](const auto &t) { return t.first < stepped; }))
    return false;
  // A group that meets a held rod has reached the pile at the box face: it
  // is held too, where its step started (its outcome was decided upstream).
  std::vector<char> stopped(pending_.size(), 0);
  bool any_stopped = false;
  for (const auto &[a, b] : touching)
    if (a < stepped && b >= stepped && !stopped[a]) {
      stopped[a] = 1;
      any_stopped = true;
      hold_at_held_rod(gather, pending_[a], held[b - stepped]);
    }
  if (any_stopped) {
    std::vector<PendingStep> moving;
    for (int k = 0; k < stepped; ++k)
      if (!stopped[k]) moving.push_back(std::move(pending_[k]));
    pending_ = std::move(moving);
    return true;  // the next round checks the others against the new pile
  }
  std::vector<int> root(pending_.size());
  std::iota(root.begin(), root.end(), 0);
  const auto find = [&root](int a) {
    while (root[a] != a) a = root[a] = root[root[a]];
    return a;
  };
  for (const auto &[a, b] : touching) {
    if (b >= stepped) continue;
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

void FixRodImplicit::hold_at_held_rod(const RodGather &gather, const PendingStep &step, int held_rod) {
  if (step.alone)
    stepped_rods_.erase(std::remove(stepped_rods_.begin(), stepped_rods_.end(), step.molecules.front()),
                        stepped_rods_.end());
  std::string name = step.molecules.size() > 1 ? "rods" : "rod";
  for (int molecule : step.molecules) {
    hold_rod(gather.rods.at(molecule));
    held_rods_.insert(molecule);
    name += " " + std::to_string(molecule);
  }
  ++rods_met_in_step_;
  if (comm->me != 0) return;
  char msg[400];
  std::snprintf(msg, sizeof(msg),
                "fix rod/implicit: %s met rod %d, held at the box face, within step " BIGINT_FORMAT
                ": held where the step started, from then on (measures stay there)\n",
                name.c_str(), held_rod, update->ntimestep);
  if (screen) fputs(msg, screen);
  if (logfile) fputs(msg, logfile);
}

std::vector<std::vector<int>> FixRodImplicit::step_all(const RodGather &gather,
                                                       const hsrod::WallContactParameters &walls, StepTotals &totals) {
  const std::vector<std::vector<int>> clusters = step_clusters(gather);
  if (apart()) prepare_rods_apart(gather);
  // Rods apart, iterated: sweeps of every group's step from the same start
  // until the obstruction forces settle (fix_rod_implicit_apart.cpp).
  for (int sweep = 0; sweep < apart_sweeps_; ++sweep) {
    const std::map<int, hsrod::RodObstructionForces> before =
        rods_apart_ == RodsApart::iterated ? obstruction_by_rod_ : std::map<int, hsrod::RodObstructionForces>();
    if (apart() && far_field_) build_far_field();
    pending_.clear();
    stepped_rods_.clear();
    joint_strain_ = joint_energy_ = 0.0;
    // Rods alone first, then clusters: the order the steps were always taken in.
    for (const std::vector<int> &cluster : clusters)
      if (cluster.size() == 1) step_group(gather, cluster, walls);
    for (const std::vector<int> &cluster : clusters)
      if (cluster.size() > 1) step_group(gather, cluster, walls);
    if (rod_contact_)
      for (int round = 0; round < kContactRounds && merge_rods_meeting_in_step(gather, walls); ++round) {
      }
    if (rods_apart_ != RodsApart::iterated) break;
    ++apart_sweeps_taken_;
    const double change = obstruction_change_since(before);
    if (sweep > 0 && change <= apart_tolerance_) break;
    if (sweep + 1 == apart_sweeps_) report_unconverged_sweeps(change);
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
        const RodScratch &scratch = *p.scratch;
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

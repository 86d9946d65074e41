/* ----------------------------------------------------------------------
   hsrod - fix rod/implicit (see fix_rod_implicit.h): the step of each rod,
   or of rods stepped together. Rods whose spheres come within contact
   reach (rod_contact hertz) or within the drag model's interaction reach
   (rod_interaction yes, level 3) form a cluster (dynamics/rod_cluster.h:
   why one joint solve and not rod by rod); a cluster's rods are merged
   into one OverdampedRod (spheres rod after rod, bonds by tag) and take one
   guarded implicit step with their joint drag. A rod with no partner takes
   exactly the step it took before rods could interact.
------------------------------------------------------------------------- */

#include "fix_rod_implicit.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_hele_shaw_drag.h"
#include "fix_rod_bonds.h"
#include "lmptype.h"
#include "rod_accounting.h"
#include "rod_assembly.h"
#include "rod_gather.h"
#include "update.h"

#include "dynamics/rod_cluster.h"
#include "hydro/rod_hydrodynamics.h"
#include "rod/rod_bond_set.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

std::vector<std::vector<int>> FixRodImplicit::step_clusters(const RodGather &gather) const {
  std::vector<int> molecules;  // rods that move (held rods stay put, alone)
  for (const auto &entry : gather.rods)
    if (!held_rods_.count(entry.first)) molecules.push_back(entry.first);
  // One moving rod is a cluster of its own: no pass over its spheres (a
  // whole-array copy per step of a long rod otherwise).
  if (molecules.size() <= 1) {
    std::vector<std::vector<int>> clusters;
    if (!molecules.empty()) clusters.push_back({molecules.front()});
    for (int held : held_rods_)
      if (gather.rods.count(held)) clusters.push_back({held});
    return clusters;
  }
  // The moving rods' positions, in the order of `molecules` (the gather's),
  // into buffers kept between steps.
  std::vector<std::vector<Eigen::Vector3d>> &positions = cluster_positions_;
  positions.resize(molecules.size());
  double largest_radius = 0.0, fastest = 0.0;
  std::size_t r = 0;
  for (const auto &entry : gather.rods) {
    if (r == molecules.size() || entry.first != molecules[r]) continue;  // held
    std::vector<Eigen::Vector3d> &rod = positions[r++];
    rod.clear();
    for (const GatheredSphere &s : entry.second) {
      rod.push_back(s.position);
      largest_radius = std::max(largest_radius, s.radius);
      fastest = std::max(fastest, s.velocity.norm());
    }
  }
  // Contact reach: touching now, or able to touch within the step (each rod
  // moving max_displacement diameters or twice its last step's travel).
  double reach = 0.0;
  if (rod_contact_)
    reach = 2.0 * largest_radius + 2.0 * std::max(2.0 * max_displacement_ * largest_radius, 2.0 * fastest * update->dt);
  if (rod_interaction_) reach = std::max(reach, drag_->hydrodynamics().interaction_reach());
  std::vector<std::vector<int>> clusters;
  for (const std::vector<int> &members : hsrod::rod_clusters(positions, reach, cluster_search_)) {
    clusters.emplace_back();
    for (int k : members) clusters.back().push_back(molecules[k]);
  }
  for (int held : held_rods_)
    if (gather.rods.count(held)) clusters.push_back({held});
  return clusters;
}

bool FixRodImplicit::step_cluster(const RodGather &gather, const std::vector<int> &molecules,
                                  const hsrod::WallContactParameters &walls, PendingStep &step) {
  hsrod::RodHydrodynamics &hydro = drag_->hydrodynamics();
  const int first = molecules.front();
  const bool joint = molecules.size() > 1;
  StepTotals &totals = step.totals;
  step.molecules = molecules;
  step.alone = false;
  // The cluster's spheres rod after rod, and which rod each belongs to.
  std::vector<GatheredSphere> &spheres = step.spheres;
  spheres.clear();
  std::vector<int> rod_of_sphere;
  for (std::size_t r = 0; r < molecules.size(); ++r) {
    const std::vector<GatheredSphere> &rod_spheres = gather.rods.at(molecules[r]);
    spheres.insert(spheres.end(), rod_spheres.begin(), rod_spheres.end());
    rod_of_sphere.insert(rod_of_sphere.end(), rod_spheres.size(), static_cast<int>(r));
  }
  const int n = static_cast<int>(spheres.size());
  const double dt = update->dt;
  step.rod = overdamped_rod(spheres, bonds_->bond_set());
  hsrod::OverdampedRod &rod = step.rod;
  if (joint) rod.rod_of_sphere = rod_of_sphere;
  // Wall friction is linearised about the velocities of the last step
  // (this fix set them: v = dx/dt).
  for (const auto &sphere : spheres) {
    rod.velocities.push_back(sphere.velocity);
    rod.angular_velocities.push_back(sphere.angular_velocity);
  }
  std::vector<hsrod::RodGeometry> geometries;
  for (int molecule : molecules) geometries.push_back(rod_geometry(hydro, molecule, gather.rods.at(molecule)));
  bool step_start = true;  // the first evaluation: the disturbance of rods apart found there
  const auto evaluate = [&](const std::vector<Eigen::Vector3d> &at, hsrod::RodDrag &out) {
    const Clock::time_point drag_start = Clock::now();
    std::size_t offset = 0;
    for (hsrod::RodGeometry &g : geometries) {
      std::copy(at.begin() + offset, at.begin() + offset + g.positions.size(), g.positions.begin());
      offset += g.positions.size();
    }
    if (apart()) apart_loads(molecules, geometries, out, step_start);
    else if (joint) hydro.loads(geometries, out);
    else hydro.loads(geometries.front(), out);
    cost_.drag_seconds += seconds_since(drag_start);
  };
  hsrod::RodDrag &drag = step.drag;
  evaluate(rod.positions, drag);
  step_start = false;
  cost_.sphere_steps += n;

  std::string name = "rod " + std::to_string(first);
  for (std::size_t r = 1; r < molecules.size(); ++r) name += (r == 1 ? " (with rods " : ", ") + std::to_string(molecules[r]);
  if (joint) name += ", stepped together)";
  step.before = rod.positions;
  const std::vector<Eigen::Vector3d> &before = step.before;
  // Self-contact (a folding rod) is always on; scene walls with `walls yes`.
  const hsrod::ChannelGeometry *scene_walls = walls_ ? &hydro.geometry() : nullptr;
  hsrod::OverdampedRodSolver &solver = joint ? solvers_by_cluster_[molecules] : work_by_rod_[first].solver;
  solver.set_chain_contact_capacitance(contact_capacitance_);
  hsrod::OverdampedStepResult &result = step.result;
  if (guard_) {
    // Accuracy guard: substeps (drag re-evaluated at each) or a refusal.
    auto drag_at = [&](const hsrod::OverdampedRod &moved, hsrod::RodDrag &out) { evaluate(moved.positions, out); };
    try {
      hsrod::GuardedStepReport report =
          hsrod::guarded_rod_step(solver, rod, drag, drag_at, dt, scene_walls, &walls, limits_,
                                  joint ? guards_by_cluster_[molecules] : work_by_rod_[first].guard);
      result = std::move(report.result);
      account_guard_report(name, report, step.totals.substeps);
    } catch (const std::exception &e) {
      char msg[896];
      std::snprintf(msg, sizeof(msg), "fix rod/implicit: %s at step " BIGINT_FORMAT ": %s", name.c_str(),
                    update->ntimestep, e.what());
      error->all(FLERR, msg);
    }
  } else {
    result = solver.step(rod, drag, dt, scene_walls, &walls);
  }
  // The cluster's bond state now (the merged rod is not kept for later).
  const auto strain_energy = hsrod::bond_strain_and_energy(rod);
  step.strain = strain_energy.first;
  step.energy = strain_energy.second;
  // A step that would carry a sphere centre out of the box (the outlet,
  // or any non-periodic face) is taken only up to the face: the rod (with
  // the rods stepped with it) is held there, whole, instead of LIGGGHTS
  // dropping its spheres one by one.
  const int face = leaving_face(rod.positions, domain->boxlo, domain->boxhi, domain->periodicity);
  if (face >= 0) {
    held_rods_.insert(molecules.begin(), molecules.end());
    report_held_at_face(name, face);
    hold_rod_at_face(spheres, before, rod.positions);
    return false;
  }
  totals.largest = std::max(totals.largest, result.largest_displacement / geometries.front().sphere_diameter);
  totals.wall_force += result.wall_force;
  totals.rod_contact_force += result.rod_contact_force;
  // Contact records per rod (a cluster's result is over all its spheres).
  std::size_t offset = 0;
  for (std::size_t r = 0; r < molecules.size(); ++r) {
    const std::size_t size = gather.rods.at(molecules[r]).size();
    double rod_wall_force = result.wall_force;
    bool touching = result.wall_contact;
    if (joint) {
      rod_wall_force = 0.0;
      for (std::size_t k = offset; k < offset + size; ++k) rod_wall_force += result.sphere_wall_force[k];
      touching = rod_wall_force > 0.0;
    }
    if (touching) totals.contacts++;
    RodContactRecord &record = contacts_by_rod_[molecules[r]];
    record.touching = touching;
    record.ever_touched = record.ever_touched || touching;
    record.wall_force = rod_wall_force;
    record.largest_wall_force = std::max(record.largest_wall_force, rod_wall_force);
    offset += size;
  }
  if (result.rod_contact) totals.rod_contacts += static_cast<int>(molecules.size());
  return true;  // scattered by step_all once no other rod met it within the step
}

void FixRodImplicit::scatter_rod(const std::vector<GatheredSphere> &spheres, const hsrod::OverdampedRod &rod,
                                 const std::vector<Eigen::Vector3d> &before, const hsrod::OverdampedStepResult &result,
                                 const hsrod::RodDrag &drag) {
  for (std::size_t k = 0; k < spheres.size(); k++) {
    const int i = atom->map(spheres[k].tag);
    if (i < 0 || i >= atom->nlocal) continue;
    const Eigen::Vector3d dx = rod.positions[k] - before[k];
    for (int a = 0; a < 3; a++) {
      atom->x[i][a] += dx[a];
      atom->v[i][a] = result.velocities[k][a];
      atom->omega[i][a] = result.angular_velocities[k][a];
    }
    bonds_->set_orientation(i, rod.orientations[k]);
    // The load at the step's new velocities (the step gave F already).
    const Eigen::Vector3d torque = drag.torque(k, result.angular_velocities[k]);
    drag_->store_loads(i, drag.driving_force[k], result.hydrodynamic_forces[k], torque);
  }
}

// A guarded step's report into the run's totals; one warning per run when
// substeps were accepted unresolved.
void FixRodImplicit::account_guard_report(const std::string &who, const hsrod::GuardedStepReport &report,
                                          int &substeps) {
  if (report.unresolved_substeps > 0 && !unresolved_warned_ && comm->me == 0) {
    char msg[640];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/implicit: %s at step " BIGINT_FORMAT ": %d substep(s) of dt/%d still differ from "
                  "two half steps by %.3g of their displacement (step_error %.3g): accepted as the half steps; "
                  "the motion is not resolved here (contact or buckling); reduce the timestep to check",
                  who.c_str(), update->ntimestep, report.unresolved_substeps, limits_.max_substeps,
                  report.unresolved_error, limits_.max_step_error);
    error->warning(FLERR, msg);
    unresolved_warned_ = true;
  }
  if (!limits_.adaptive && report.substeps >= kManySubsteps && !substeps_warned_ && comm->me == 0) {
    // Each substep met the guard's limits, but the run carries the
    // first-order error of whatever the guard does not measure (in the stress
    // matrix a rod released from a pinned state at 250x the default step
    // ends with the dt/10 run, 8 deg from the converged one).
    char msg[640];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/implicit: %s at step " BIGINT_FORMAT ": the accuracy guard cut the step of dt = %g s "
                  "into %d substeps: the timestep is far above what the motion allows here, and the run carries "
                  "the step's first-order error where the guard does not measure it (e.g. a rod released from a "
                  "pinned state); check against a smaller timestep, or use adaptive yes tolerance 1e-3 (said once)",
                  who.c_str(), update->ntimestep, update->dt, report.substeps);
    error->warning(FLERR, msg);
    substeps_warned_ = true;
  }
  unresolved_ += report.unresolved_substeps;
  substeps_taken_ += report.substeps;
  trials_rejected_ += report.rejected_trials;
  substeps = std::max(substeps, report.substeps);
}

// Said once when a rod (or a cluster of rods) is held at a box face.
void FixRodImplicit::report_held_at_face(const std::string &who, int face) {
  if (comm->me != 0) return;
  char msg[480];
  std::snprintf(msg, sizeof(msg),
                "fix rod/implicit: %s reached the box's %s face at step " BIGINT_FORMAT
                " (t = %g s): its step would carry a sphere out of the box; it is taken up to the face and the "
                "rod held there, whole, from then on (measures stay at its exit)\n", who.c_str(), face_name(face),
                update->ntimestep, update->get_cur_time());
  if (screen) fputs(msg, screen);
  if (logfile) fputs(msg, logfile);
}

// Joint workspaces of clusters that no longer exist are dropped (a cache:
// a fresh one gives the same step), their statistics kept for the report.
void FixRodImplicit::retire_stale_clusters(const std::vector<std::vector<int>> &clusters) {
  // Only groups of several rods have a joint workspace: those, sorted, are
  // searched (not every rod's group for every workspace).
  std::vector<const std::vector<int> *> joint;
  for (const std::vector<int> &cluster : clusters)
    if (cluster.size() > 1) joint.push_back(&cluster);
  const auto by_molecules = [](const std::vector<int> *a, const std::vector<int> *b) { return *a < *b; };
  std::sort(joint.begin(), joint.end(), by_molecules);
  for (auto it = solvers_by_cluster_.begin(); it != solvers_by_cluster_.end();) {
    if (std::binary_search(joint.begin(), joint.end(), &it->first, by_molecules)) {
      ++it;
      continue;
    }
    hsrod::accumulate(retired_statistics_, it->second.statistics());
    guards_by_cluster_.erase(it->first);
    it = solvers_by_cluster_.erase(it);
  }
}

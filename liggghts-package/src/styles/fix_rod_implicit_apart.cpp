/* ----------------------------------------------------------------------
   hsrod - fix rod/implicit (see fix_rod_implicit.h): rods coupled by level 3
   without one joint solve (rod_interaction lagged | iterated N tol). The
   rods are clustered by contact reach only; each group is stepped alone
   with the disturbance of the other rods within the model's interaction
   reach imposed at its spheres (hydro/cross_rod_disturbance.h: why, and
   what it converges to), and with rod_far_field yes that of the rods
   beyond the reach (hydro/cross_rod_far_field.h). This file gathers the rods' centres and
   neighbours (dynamics/rod_cluster.h: rods_within_reach, a cell list),
   hands each group its disturbance and keeps every rod's obstruction
   forces; the physics is in drag-models/hydro.
------------------------------------------------------------------------- */

#include "fix_rod_implicit.h"

#include "error.h"
#include "fix_hele_shaw_drag.h"
#include "keyword_parsing.h"
#include "lmptype.h"
#include "rod_gather.h"
#include "update.h"

#include "hydro/nonlocal_model.h"
#include "hydro/rod_hydrodynamics.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

// rod_interaction yes | joint | no | lagged | iterated N tol
void FixRodImplicit::parse_rod_interaction(int narg, char **arg, int &iarg) {
  const char *val = arg[iarg + 1];
  rods_apart_ = RodsApart::off;
  rod_interaction_ = false;
  if (strcmp(val, "yes") == 0 || strcmp(val, "joint") == 0) {
    rod_interaction_ = true;
  } else if (strcmp(val, "lagged") == 0) {
    rods_apart_ = RodsApart::lagged;
    apart_sweeps_ = 1;
  } else if (strcmp(val, "iterated") == 0) {
    if (iarg + 3 >= narg)
      error->all(FLERR, "fix rod/implicit: rod_interaction iterated needs N tol (most sweeps per step, in [1, 1000], "
                        "and the accepted change of the obstruction forces, in (0, 1))");
    rods_apart_ = RodsApart::iterated;
    apart_sweeps_ = parse_integer(error, "fix rod/implicit", "rod_interaction iterated", arg[iarg + 2]);
    apart_tolerance_ = parse_number(error, "fix rod/implicit", "rod_interaction iterated", arg[iarg + 3]);
    if (!(apart_sweeps_ >= 1 && apart_sweeps_ <= 1000))
      error->all(FLERR, "fix rod/implicit: rod_interaction iterated N must be in [1, 1000] (sweeps per step)");
    if (!(apart_tolerance_ > 0.0 && apart_tolerance_ < 1.0))
      error->all(FLERR, "fix rod/implicit: rod_interaction iterated tol must be in (0, 1) (change of the obstruction "
                        "forces between sweeps over the largest)");
    iarg += 2;
  } else if (strcmp(val, "no") != 0) {
    error->all(FLERR, "fix rod/implicit: rod_interaction expects yes (= joint), joint, no, lagged or iterated N tol");
  }
}

void FixRodImplicit::prepare_rods_apart(const RodGather &gather) {
  hsrod::RodHydrodynamics &hydro = drag_->hydrodynamics();
  if (!hydro.nonlocal_model() || hydro.nonlocal_model()->wall_reflection() != hsrod::WallReflection::none) {
    char msg[512];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/implicit: rod_interaction %s needs fix %s with model nonlocal (level 3) and "
                  "wall_reflection none (model here: %s); use rod_interaction yes (joint) or no",
                  rods_apart_ == RodsApart::lagged ? "lagged" : "iterated", drag_id_.c_str(),
                  hydro.has_model() ? hydro.model().name().c_str() : "none");
    error->all(FLERR, msg);
  }
  std::vector<int> molecules;
  std::vector<std::vector<Eigen::Vector3d>> &positions = cluster_positions_;
  positions.resize(gather.rods.size());
  std::size_t r = 0;
  for (const auto &entry : gather.rods) {
    molecules.push_back(entry.first);
    std::vector<Eigen::Vector3d> &rod = positions[r++];
    rod.clear();
    for (const GatheredSphere &s : entry.second) rod.push_back(s.position);
    hsrod::RodGeometry &geometry = apart_geometry_[entry.first];
    geometry.positions = rod;
    obstruction_by_rod_[entry.first].start(static_cast<int>(rod.size()));
  }
  // Rods gone (outflow) are dropped from the kept forces.
  for (auto it = obstruction_by_rod_.begin(); it != obstruction_by_rod_.end();)
    it = gather.rods.count(it->first) ? std::next(it) : obstruction_by_rod_.erase(it);
  apart_neighbours_.clear();
  for (const auto &[a, b] : hsrod::rods_within_reach(positions, hydro.interaction_reach(), cluster_search_)) {
    apart_neighbours_[molecules[a]].push_back(molecules[b]);
    apart_neighbours_[molecules[b]].push_back(molecules[a]);
  }
}

// The far field's tree over every rod at the step's start, with the
// obstruction forces of the last sweep or step (the same on every rank: the
// rods are gathered on all, by molecule ID).
void FixRodImplicit::build_far_field() {
  drag_->hydrodynamics().nonlocal_model()->set_far_field_scene(far_field_sum_);
  std::vector<int> ids;
  std::vector<const hsrod::RodGeometry *> rods;
  std::vector<const hsrod::RodObstructionForces *> forces;
  for (const auto &entry : obstruction_by_rod_) {
    ids.push_back(entry.first);
    rods.push_back(&apart_geometry_.at(entry.first));
    forces.push_back(&entry.second);
  }
  far_field_sum_.build(ids, rods, forces);
}

void FixRodImplicit::apart_loads(const std::vector<int> &molecules, const std::vector<hsrod::RodGeometry> &geometries,
                                 hsrod::RodDrag &out, bool step_start) {
  hsrod::RodHydrodynamics &hydro = drag_->hydrodynamics();
  hsrod::UnitObstruction &kept = unit_by_first_[molecules.front()];
  if (step_start) {
    // q of each member from the latest obstruction forces of the rods of
    // other groups within reach (Gauss-Seidel: those stepped before it in
    // this sweep, the others from the last sweep or step).
    const hsrod::NonlocalRodModel &model = *hydro.nonlocal_model();
    std::vector<Eigen::VectorXd> driving, velocity;
    Eigen::Index size = 0;
    for (int molecule : molecules) {
      hsrod::RodObstructionForces &forces = obstruction_by_rod_[molecule];
      forces.clear_disturbance();
      const auto near = apart_neighbours_.find(molecule);
      if (near != apart_neighbours_.end())
        for (int other : near->second)
          if (std::find(molecules.begin(), molecules.end(), other) == molecules.end())
            model.add_disturbance(apart_geometry_.at(molecule), forces, apart_geometry_.at(other),
                                  obstruction_by_rod_.at(other));
      if (far_field_) {  // the rods beyond the reach: all but those just coupled exactly and the unit's own
        std::vector<int> excluded = molecules;
        if (near != apart_neighbours_.end()) excluded.insert(excluded.end(), near->second.begin(), near->second.end());
        std::sort(excluded.begin(), excluded.end());
        far_field_sum_.add_disturbance(apart_geometry_.at(molecule), excluded, forces);
      }
      size += forces.driving.size();
    }
    kept.driving_disturbance.resize(size);
    kept.velocity_disturbance.resize(size);
    Eigen::Index at = 0;
    for (int molecule : molecules) {
      const hsrod::RodObstructionForces &forces = obstruction_by_rod_[molecule];
      kept.driving_disturbance.segment(at, forces.driving.size()) = forces.driving_disturbance;
      kept.velocity_disturbance.segment(at, forces.driving.size()) = forces.velocity_disturbance;
      at += forces.driving.size();
    }
  }
  try {
    if (step_start) {
      hydro.loads_apart(geometries, out, kept);
    } else {  // a substep: the disturbance held over the step, the rod's own coupling where it is now
      hsrod::UnitObstruction substep = kept;
      hydro.loads_apart(geometries, out, substep);
    }
  } catch (const std::exception &e) {
    char msg[768];
    std::snprintf(msg, sizeof(msg), "fix rod/implicit: rod %d at step " BIGINT_FORMAT ": drag model: %s",
                  molecules.front(), update->ntimestep, e.what());
    error->all(FLERR, msg);
  }
}

void FixRodImplicit::update_obstruction(const std::vector<int> &molecules,
                                        const std::vector<Eigen::Vector3d> &velocities) {
  const hsrod::UnitObstruction &unit = unit_by_first_.at(molecules.front());
  Eigen::VectorXd driving, velocity;
  hsrod::unit_obstruction_forces(unit, velocities, driving, velocity);
  Eigen::Index at = 0;
  for (int molecule : molecules) {
    hsrod::RodObstructionForces &forces = obstruction_by_rod_[molecule];
    const Eigen::Index size = forces.driving.size();
    forces.driving = driving.segment(at, size);
    forces.velocity = velocity.segment(at, size);
    at += size;
  }
}

double FixRodImplicit::obstruction_change_since(const std::map<int, hsrod::RodObstructionForces> &before) const {
  std::vector<hsrod::RodObstructionForces> a, b;
  for (const auto &entry : obstruction_by_rod_) {
    const auto old = before.find(entry.first);
    if (old == before.end()) return 1.0;
    a.push_back(old->second);
    b.push_back(entry.second);
  }
  return hsrod::obstruction_change(a, b);
}

// The sweeps of rod_interaction iterated ended above their tolerance: the
// step is not the coupled one asked for (rods too close for the rod-by-rod
// iteration to settle within N sweeps).
void FixRodImplicit::report_unconverged_sweeps(double change) {
  char msg[640];
  std::snprintf(msg, sizeof(msg),
                "fix rod/implicit: rod_interaction iterated %d %g: after %d sweeps at step " BIGINT_FORMAT
                " the rods' obstruction forces still change by %.3g of the largest (> tol %g): rods side by side "
                "within a few diameters converge slowly; raise N, or use rod_interaction yes (one joint solve)",
                apart_sweeps_, apart_tolerance_, apart_sweeps_, update->ntimestep, change, apart_tolerance_);
  error->all(FLERR, msg);
}

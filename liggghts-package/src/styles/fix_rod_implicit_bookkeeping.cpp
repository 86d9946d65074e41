/* ----------------------------------------------------------------------
   hsrod - fix rod/implicit (see fix_rod_implicit.h): its bookkeeping.
   The partner fixes by ID (implicit_partners.h), whole-rod accounting
   (rod_accounting.h: lost spheres and rod-rod overlap refused, rods held at
   the box boundary) and the global restart data (wall-contact records).
------------------------------------------------------------------------- */

#include "fix_rod_implicit.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_hele_shaw_drag.h"
#include "fix_rod_bonds.h"
#include "force.h"
#include "lmptype.h"
#include "modify.h"
#include "rod_accounting.h"
#include "rod_gather.h"
#include "update.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

bool FixRodImplicit::names_partner(const char *fix_id) const { return bonds_id_ == fix_id || drag_id_ == fix_id; }

// The partner fixes by ID: an error if one was removed (unfix) or replaced
// by a fix of another style since this fix was defined.
void FixRodImplicit::resolve_partners() {
  const std::string *ids[2] = {&bonds_id_, &drag_id_};
  const char *keys[2] = {"bonds", "drag"}, *styles[2] = {"rod/bonds", "hele_shaw/drag"};
  for (int k = 0; k < 2; k++) {
    const int f = modify->find_fix(ids[k]->c_str());
    Fix *partner = f < 0 ? nullptr : modify->fix[f];
    if (!partner) {
      char msg[256];
      std::snprintf(msg, sizeof(msg), "fix rod/implicit: %s fix '%s' not found (define it before this fix; "
                    "unfix this fix before its %s fix)", keys[k], ids[k]->c_str(), keys[k]);
      error->all(FLERR, msg);
    }
    if (k == 0) bonds_ = dynamic_cast<FixRodBonds *>(partner);
    else drag_ = dynamic_cast<FixHeleShawDrag *>(partner);
    if (k == 0 ? !bonds_ : !drag_) {
      char msg[256];
      std::snprintf(msg, sizeof(msg), "fix rod/implicit: fix '%s' is not a %s fix", ids[k]->c_str(), styles[k]);
      error->all(FLERR, msg);
    }
  }
}

// Every rod whole (RodCensus) and, without a pair style, no two rods
// overlapping (rod-rod contact would go unresolved: they pass through each
// other). Errors name the rod and the figures.
void FixRodImplicit::check_whole_rods(const RodGather &gather) {
  const std::string missing = census_.check(gather.rods);
  if (!missing.empty()) {
    char msg[512];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/implicit: %s at step " BIGINT_FORMAT ": atoms of a rod were lost (outside the box, "
                  "delete_atoms, or a rod ejected by an explicit contact force); rods are moved and measured "
                  "whole only", missing.c_str(), update->ntimestep);
    error->all(FLERR, msg);
  }
  if (force->pair || gather.rods.size() < 2) return;
  const RodOverlap overlap = first_rod_overlap(gather.rods);
  // With rod_contact, touching rods are the contact's business; rods placed
  // into each other (centres closer than 0.8 of the contact distance: an
  // overlap beyond 0.4 radii, 4x the guard's bound on a step's new overlap)
  // are beyond what the Hertz law describes.
  constexpr double deepest_contact = 0.8;  // [-]
  if (rod_contact_ && overlap.rod_a >= 0 && overlap.distance_over_contact < deepest_contact) {
    char msg[512];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/implicit: rods %d and %d interpenetrate at step " BIGINT_FORMAT
                  " (sphere centres %.3g of the contact distance apart, rod_contact accepts >= %.2g): place the "
                  "rods apart; Hertz contact resolves touching rods, not rods inside each other",
                  overlap.rod_a, overlap.rod_b, update->ntimestep, overlap.distance_over_contact, deepest_contact);
    error->all(FLERR, msg);
  }
  if (rod_contact_) return;
  if (overlap.rod_a >= 0) {
    char msg[512];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/implicit: rods %d and %d overlap at step " BIGINT_FORMAT
                  " (sphere centres %.3g of the contact distance apart) and no pair style handles rod-rod "
                  "contact: they would pass through each other; use fix rod/implicit's rod_contact hertz, or keep "
                  "the rods apart", overlap.rod_a, overlap.rod_b, update->ntimestep, overlap.distance_over_contact);
    error->all(FLERR, msg);
  }
}

void FixRodImplicit::forget_rods(const std::vector<int> &molecules) {
  for (int mol : molecules) {
    census_.forget(mol);
    held_rods_.erase(mol);
    contacts_by_rod_.erase(mol);
    const auto work = work_by_rod_.find(mol);
    if (work != work_by_rod_.end()) {
      hsrod::accumulate(retired_statistics_, work->second.solver.statistics());  // the run's cost report keeps them
      work_by_rod_.erase(work);
    }
    stepped_rods_.erase(std::remove(stepped_rods_.begin(), stepped_rods_.end(), mol), stepped_rods_.end());
  }
  // Joint solvers of clusters with a removed rod: retired as the next step
  // would retire them (the cluster is not stepped again).
  for (auto it = solvers_by_cluster_.begin(); it != solvers_by_cluster_.end();) {
    const bool stale = std::any_of(it->first.begin(), it->first.end(), [&](int mol) {
      return std::binary_search(molecules.begin(), molecules.end(), mol);
    });
    if (!stale) {
      ++it;
      continue;
    }
    hsrod::accumulate(retired_statistics_, it->second.statistics());
    guards_by_cluster_.erase(it->first);
    it = solvers_by_cluster_.erase(it);
  }
}

// Largest |axial strain| and elastic energy of the rods' bonds after the
// last step, evaluated when asked for (output steps), not every step.
void FixRodImplicit::refresh_bond_state() {
  if (bond_state_fresh_) return;
  double strain = joint_strain_, energy = joint_energy_;  // clusters: evaluated at their step
  for (int rod_id : stepped_rods_) {
    const auto strain_energy = hsrod::bond_strain_and_energy(work_by_rod_[rod_id].scratch.rod);
    strain = std::max(strain, strain_energy.first);
    energy += strain_energy.second;
  }
  bond_strain_ = strain;
  bond_energy_ = energy;
  bond_state_fresh_ = true;
}

// A rod whose step (before -> after, sphere by sphere as `spheres`) would
// carry a centre out of the box takes the part of it that brings the
// leading centre to the face, and is held there: its exit does not depend
// on the step size (a step of 5 d used to hold it up to 5 d short).
void FixRodImplicit::hold_rod_at_face(const std::vector<GatheredSphere> &spheres,
                                      const std::vector<Eigen::Vector3d> &before,
                                      const std::vector<Eigen::Vector3d> &after) {
  const double part = fraction_inside_box(before, after, domain->boxlo, domain->boxhi, domain->periodicity);
  for (std::size_t k = 0; k < spheres.size() && k < before.size() && k < after.size(); k++) {
    const int i = atom->map(spheres[k].tag);
    if (i < 0 || i >= atom->nlocal) continue;
    for (int a = 0; a < 3; a++) atom->x[i][a] = before[k][a] + part * (after[k][a] - before[k][a]);
  }
  hold_rod(spheres);
}

// A held rod stays where it is, at rest.
void FixRodImplicit::hold_rod(const std::vector<GatheredSphere> &spheres) {
  for (const auto &sphere : spheres) {
    const int i = atom->map(sphere.tag);
    if (i < 0 || i >= atom->nlocal) continue;
    for (int a = 0; a < 3; a++) atom->v[i][a] = atom->omega[i][a] = 0.0;
  }
}

// Global restart data: [count, then per rod: molecule, touching, ever touched, wall force, largest wall force].
void FixRodImplicit::write_restart(FILE *fp) {
  if (comm->me != 0) return;
  std::vector<double> data{static_cast<double>(contacts_by_rod_.size())};
  for (const auto &entry : contacts_by_rod_) {
    const RodContactRecord &r = entry.second;
    data.insert(data.end(), {static_cast<double>(entry.first), r.touching ? 1.0 : 0.0, r.ever_touched ? 1.0 : 0.0,
                             r.wall_force, r.largest_wall_force});
  }
  const int size = static_cast<int>(data.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(data.data(), sizeof(double), data.size(), fp);
}

void FixRodImplicit::restart(char *buf) {
  const double *list = reinterpret_cast<const double *>(buf);
  const int rods = static_cast<int>(list[0]);
  contacts_by_rod_.clear();
  for (int k = 0; k < rods; k++) {
    const double *r = list + 1 + 5 * k;
    RodContactRecord &record = contacts_by_rod_[static_cast<int>(r[0])];
    record.touching = r[1] != 0.0;
    record.ever_touched = r[2] != 0.0;
    record.wall_force = r[3];
    record.largest_wall_force = r[4];
  }
}

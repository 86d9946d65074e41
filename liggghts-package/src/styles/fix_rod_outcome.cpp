/* ----------------------------------------------------------------------
   hsrod - fix rod/outcome (see fix_rod_outcome.h)

   fix ID group rod/outcome drag DRAG-ID mean_velocity U [pass_x X]
       [averaging_time T] [clog_time T] [stall_ratio F] [release_ratio F]
       [sides both|any]
------------------------------------------------------------------------- */

#include "fix_rod_outcome.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_hele_shaw_drag.h"
#include "keyword_parsing.h"
#include "modify.h"
#include "update.h"

#include "geometry/channel_geometry.h"
#include "hydro/rod_hydrodynamics.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
const char *kStyle = "fix rod/outcome";
}

FixRodOutcome::FixRodOutcome(LAMMPS *instance, int narg, char **arg)
    : Fix(instance, narg, arg),
      drag_(nullptr),
      pass_x_given_(false),
      averaging_given_(false),
      clog_given_(false),
      all_decided_(false) {
  bool velocity_given = false;
  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg) {
      char msg[128];
      std::snprintf(msg, sizeof(msg), "Illegal fix rod/outcome command: keyword %s needs a value", arg[iarg]);
      error->all(FLERR, msg);
    }
    const char *key = arg[iarg], *val = arg[iarg + 1];
    if (strcmp(key, "drag") == 0) {
      const int f = modify->find_fix(val);
      if (f < 0) {
        char msg[256];
        std::snprintf(msg, sizeof(msg), "fix rod/outcome: drag fix '%s' not found (define it before this fix)", val);
        error->all(FLERR, msg);
      }
      drag_ = dynamic_cast<FixHeleShawDrag *>(modify->fix[f]);
      if (!drag_) {
        char msg[256];
        std::snprintf(msg, sizeof(msg), "fix rod/outcome: fix '%s' is not a hele_shaw/drag fix", val);
        error->all(FLERR, msg);
      }
    } else if (strcmp(key, "mean_velocity") == 0) {
      criteria_.mean_velocity = parse_number(error, kStyle, key, val);
      if (!(criteria_.mean_velocity > 0.0)) error->all(FLERR, "fix rod/outcome: mean_velocity must be > 0 m/s");
      velocity_given = true;
    } else if (strcmp(key, "pass_x") == 0) {
      criteria_.pass_x = parse_number(error, kStyle, key, val);
      pass_x_given_ = true;
    } else if (strcmp(key, "averaging_time") == 0) {
      criteria_.averaging_time = parse_number(error, kStyle, key, val);
      if (!(criteria_.averaging_time > 0.0)) error->all(FLERR, "fix rod/outcome: averaging_time must be > 0 s");
      averaging_given_ = true;
    } else if (strcmp(key, "clog_time") == 0) {
      criteria_.clog_time = parse_number(error, kStyle, key, val);
      if (!(criteria_.clog_time > 0.0)) error->all(FLERR, "fix rod/outcome: clog_time must be > 0 s");
      clog_given_ = true;
    } else if (strcmp(key, "stall_ratio") == 0) {
      criteria_.stall_ratio = parse_number(error, kStyle, key, val);
      if (!(criteria_.stall_ratio > 0.0 && criteria_.stall_ratio < 1.0))
        error->all(FLERR, "fix rod/outcome: stall_ratio must be in (0, 1)");
    } else if (strcmp(key, "release_ratio") == 0) {
      criteria_.release_ratio = parse_number(error, kStyle, key, val);
      if (!(criteria_.release_ratio > 0.0 && criteria_.release_ratio < 1.0))
        error->all(FLERR, "fix rod/outcome: release_ratio must be in (0, 1)");
    } else if (strcmp(key, "sides") == 0) {
      if (strcmp(val, "both") != 0 && strcmp(val, "any") != 0)
        error->all(FLERR, "fix rod/outcome: sides expects both or any");
      criteria_.require_both_sides = strcmp(val, "both") == 0;
    } else {
      char msg[256];
      std::snprintf(msg, sizeof(msg),
                    "Illegal fix rod/outcome command: unknown keyword '%s' (expected drag, mean_velocity, pass_x, "
                    "averaging_time, clog_time, stall_ratio, release_ratio, sides)", key);
      error->all(FLERR, msg);
    }
  }
  if (!drag_) error->all(FLERR, "Illegal fix rod/outcome command: missing required keyword drag");
  if (!velocity_given) error->all(FLERR, "Illegal fix rod/outcome command: missing required keyword mean_velocity");
  if (!(criteria_.release_ratio > criteria_.stall_ratio))
    error->all(FLERR, "fix rod/outcome: release_ratio must be larger than stall_ratio (hysteresis)");

  // Defaults from the scene: the rod has passed once its centre is past the
  // downstream edge of every obstacle; time scale = pore width / U.
  const hsrod::ChannelGeometry &g = drag_->hydrodynamics().geometry();
  criteria_.channel_centre_y = g.y_lo() + 0.5 * g.width();
  if (!pass_x_given_) {
    bool any = false;
    double edge = g.x_lo();
    for (const auto &c : g.cylinders())
      if (c.radius > 0.0) {
        edge = std::max(edge, c.center_x + c.radius);
        any = true;
      }
    if (!any) error->all(FLERR, "fix rod/outcome: the channel has no pore cylinders; give pass_x (m)");
    criteria_.pass_x = edge;
  }
  const double time_scale = g.narrowest_opening() / criteria_.mean_velocity;
  if (!averaging_given_) criteria_.averaging_time = time_scale;
  if (!clog_given_) criteria_.clog_time = 5.0 * time_scale;
  try {
    criteria_.validate();
  } catch (const std::invalid_argument &e) {
    char msg[256];
    std::snprintf(msg, sizeof(msg), "fix rod/outcome: %s", e.what());
    error->all(FLERR, msg);
  }
  if (!atom->molecule_flag) error->all(FLERR, "fix rod/outcome: needs molecule IDs (atom_style ... molecular)");
  rods_ = std::make_unique<hsrod::RodOutcomeSet>(criteria_);

  nevery = 1;
  vector_flag = 1;
  size_vector = 11;
  extvector = 0;
  global_freq = 1;
}

int FixRodOutcome::setmask() { return END_OF_STEP; }

void FixRodOutcome::init() {}

void FixRodOutcome::setup(int) {
  if (comm->me == 0 && !criteria_reported_) {  // once, not at every run of a chunked loop
    char msg[512];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/outcome: passed when the centre is past x = %g m; clogged when <v_x>/U (averaged over "
                  "%g s) < %g (released above %g) while touching %s, or resting against a trapped rod, for %g s\n",
                  criteria_.pass_x, criteria_.averaging_time, criteria_.stall_ratio, criteria_.release_ratio,
                  criteria_.require_both_sides ? "walls on both sides" : "a wall", criteria_.clog_time);
    if (screen) fputs(msg, screen);
    if (logfile) fputs(msg, logfile);
  }
  criteria_reported_ = true;
  sample();
}

void FixRodOutcome::end_of_step() { sample(); }

// Per rod: sums of x, y, v_x and counts, contacts below/above the centre
// line and the sum of the touching spheres' centres; reduced over procs.
void FixRodOutcome::sample() {
  int local_max = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) local_max = std::max(local_max, atom->molecule[i]);
  int max_mol = 0;
  MPI_Allreduce(&local_max, &max_mol, 1, MPI_INT, MPI_MAX, world);
  // sum x, sum y, sum vx, count, touching below, above, sums of the touching
  // spheres' x, y below, then above the centre line
  constexpr int kFields = 10;
  std::vector<double> local(kFields * (max_mol + 1), 0.0), total(local.size(), 0.0);
  const hsrod::ChannelGeometry &g = drag_->hydrodynamics().geometry();
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    double *d = &local[kFields * atom->molecule[i]];
    const double *x = atom->x[i];
    d[0] += x[0];
    d[1] += x[1];
    d[2] += atom->v[i][0];
    d[3] += 1.0;
    // A sphere touches a planform wall (pore cylinder or side wall) when its
    // centre is closer to it than its radius (the Hertz overlap is > 0).
    if (g.signed_distance(x[0], x[1]) < atom->radius[i]) {
      const bool below = x[1] < criteria_.channel_centre_y;
      d[below ? 4 : 5] += 1.0;
      d[below ? 6 : 8] += x[0];
      d[below ? 7 : 9] += x[1];
    }
  }
  MPI_Allreduce(local.data(), total.data(), static_cast<int>(local.size()), MPI_DOUBLE, MPI_SUM, world);

  const double time = update->atime + (update->ntimestep - update->atimestep) * update->dt;
  std::map<int, hsrod::RodOutcomeSample> samples;
  for (int mol = 0; mol <= max_mol; mol++) {
    const double *d = &total[kFields * mol];
    if (d[3] <= 0.0) continue;
    hsrod::RodOutcomeSample s;
    s.time = time;
    s.centre = Eigen::Vector2d(d[0] / d[3], d[1] / d[3]);
    s.velocity_x = d[2] / d[3];
    s.touching_below = d[4] > 0.0;
    s.touching_above = d[5] > 0.0;
    // Contact position: mean centre of the touching spheres on the lower
    // side, else on the upper side.
    if (d[4] > 0.0) s.contact_position = Eigen::Vector2d(d[6] / d[4], d[7] / d[4]);
    else if (d[5] > 0.0) s.contact_position = Eigen::Vector2d(d[8] / d[5], d[9] / d[5]);
    samples.emplace(mol, s);
  }
  // Rod-rod contacts only matter with several rods.
  rods_->update(time, samples, samples.size() > 1 ? touching_rods() : std::vector<std::pair<int, int>>{});
  bool all = true;
  for (const auto &entry : samples) {
    const hsrod::RodOutcomeTracker &tracker = rods_->trackers().at(entry.first);
    if (tracker.decided() && !reported_.count(entry.first)) report_decision(entry.first, tracker);
    all = all && tracker.decided();
  }
  const int rods = static_cast<int>(samples.size());
  all_decided_ = rods > 0 && all;
}

// Every group sphere's molecule, centre and radius from all procs; the
// overlapping pairs of rods (drag-models/rod/rod_outcome_set.h).
std::vector<std::pair<int, int>> FixRodOutcome::touching_rods() {
  constexpr int kPerSphere = 5;  // molecule, x, y, z, radius
  std::vector<double> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    mine.insert(mine.end(), {static_cast<double>(atom->molecule[i]), atom->x[i][0], atom->x[i][1], atom->x[i][2],
                             atom->radius[i]});
  }
  int count = static_cast<int>(mine.size());
  std::vector<int> counts(comm->nprocs), offsets(comm->nprocs, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  for (int p = 1; p < comm->nprocs; p++) offsets[p] = offsets[p - 1] + counts[p - 1];
  std::vector<double> all(offsets.back() + counts.back());
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, world);
  const std::size_t n = all.size() / kPerSphere;
  std::vector<Eigen::Vector3d> centres(n);
  std::vector<double> radii(n);
  std::vector<int> rod_ids(n);
  for (std::size_t k = 0; k < n; k++) {
    const double *d = &all[kPerSphere * k];
    rod_ids[k] = static_cast<int>(d[0]);
    centres[k] = Eigen::Vector3d(d[1], d[2], d[3]);
    radii[k] = d[4];
  }
  return hsrod::touching_rod_pairs(centres, radii, rod_ids);
}

void FixRodOutcome::report_decision(int mol, const hsrod::RodOutcomeTracker &tracker) {
  reported_.insert(mol);
  if (comm->me != 0) return;
  char msg[512];
  int n = std::snprintf(msg, sizeof(msg), "fix rod/outcome: rod %d %s", mol, hsrod::rod_outcome_name(tracker.outcome()));
  if (tracker.held_by() >= 0) n += std::snprintf(msg + n, sizeof(msg) - n, " (held by rod %d)", tracker.held_by());
  n += std::snprintf(msg + n, sizeof(msg) - n, " at t = %g s, centre (%g, %g) m", tracker.decision_time(),
                     tracker.decision_centre().x(), tracker.decision_centre().y());
  if (tracker.touched())
    std::snprintf(msg + n, sizeof(msg) - n, "; first wall contact at t = %g s, sphere centre (%g, %g) m\n",
                  tracker.first_contact_time(), tracker.first_contact_position().x(),
                  tracker.first_contact_position().y());
  else
    std::snprintf(msg + n, sizeof(msg) - n, "; no wall contact\n");
  if (screen) fputs(msg, screen);
  if (logfile) fputs(msg, logfile);
}

double FixRodOutcome::compute_vector(int n) {
  // [1] all rods decided (1/0), [2] outcome code (0 undecided, 1 passed
  // without contact, 2 passed with contact, 3 clogged; with several rods the
  // largest, once all are decided), [3] first wall contact time [s] (-1:
  // none), [4-5] its position [m], [6] <v_x>/U of the first rod, [7-9] rods
  // clogged / passed with contact / passed without, [10] how long the first
  // rod has been trapped (stalled and pinned or held) [s], [11] rods clogged
  // held by another rod (of [7]).
  const auto &trackers = rods_->trackers();
  const hsrod::RodOutcomeTracker *first = trackers.empty() ? nullptr : &trackers.begin()->second;
  const hsrod::RodOutcomeTracker *earliest = nullptr;
  int worst = 0, counts[4] = {0, 0, 0, 0}, held = 0;
  for (const auto &entry : trackers) {
    const hsrod::RodOutcomeTracker &t = entry.second;
    worst = std::max(worst, static_cast<int>(t.outcome()));
    counts[static_cast<int>(t.outcome())]++;
    if (t.outcome() == hsrod::RodOutcome::clogged && t.held_by() >= 0) held++;
    if (t.touched() && (!earliest || t.first_contact_time() < earliest->first_contact_time())) earliest = &t;
  }
  switch (n) {
    case 0: return all_decided_ ? 1.0 : 0.0;
    case 1: return all_decided_ ? worst : 0.0;
    case 2: return earliest ? earliest->first_contact_time() : -1.0;
    case 3: return earliest ? earliest->first_contact_position().x() : 0.0;
    case 4: return earliest ? earliest->first_contact_position().y() : 0.0;
    case 5: return first ? first->averaged_velocity_ratio() : 0.0;
    case 6: return counts[3];
    case 7: return counts[2];
    case 8: return counts[1];
    case 9: return first ? first->trapped_duration() : 0.0;
    default: return held;
  }
}

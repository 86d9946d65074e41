/* ----------------------------------------------------------------------
   hsrod - fix rod/inflow (see fix_rod_inflow.h)

   fix ID group rod/inflow drag ID spheres n diameter d type T density rho
       region x0 x1 every N [count K | concentration c] [seed S] [angle alpha|random]
       [min_gap g] [spacing s] [bond_type B]
------------------------------------------------------------------------- */

#include "fix_rod_inflow.h"

#include "create_rod.h"
#include "fix_hele_shaw_drag.h"
#include "fix_rod_bonds.h"
#include "keyword_parsing.h"
#include "rod_gather.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "modify.h"
#include "update.h"

#include "geometry/rod_seeding.h"
#include "hydro/rod_hydrodynamics.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
constexpr const char *kStyle = "fix rod/inflow";
// Attempt k of seed S draws from the sequence S * kSeedStride + k: the same
// on every rank, distinct for 1e6 attempts per seed.
constexpr std::uint64_t kSeedStride = 1000003;
}  // namespace

FixRodInflow::FixRodInflow(LAMMPS *instance, int narg, char **arg)
    : Fix(instance, narg, arg), rods_per_insertion_(1), concentration_(-1.0), band_target_(0), rods_in_band_(0),
      drag_(nullptr), rods_inserted_(0), rods_refused_(0),
      attempts_(0), next_tag_(1), next_mol_(1), rest_states_pending_(false) {
  nevery = 0;
  bool have_region = false, have_count = false, have_concentration = false;
  for (int iarg = 3; iarg < narg;) {
    const char *key = arg[iarg];
    if (std::strcmp(key, "every") == 0 || std::strcmp(key, "count") == 0) {
      if (iarg + 1 >= narg) {
        char msg[160];
        std::snprintf(msg, sizeof(msg), "Illegal fix rod/inflow command: %s expects 1 value(s)", key);
        error->all(FLERR, msg);
      }
      const int value = parse_integer(error, kStyle, key, arg[iarg + 1]);
      if (value < 1) {
        char msg[160];
        std::snprintf(msg, sizeof(msg), "fix rod/inflow: %s must be an integer >= 1 (got %d)", key, value);
        error->all(FLERR, msg);
      }
      (key[0] == 'e' ? nevery : rods_per_insertion_) = value;
      if (key[0] == 'c') have_count = true;
      iarg += 2;
      continue;
    }
    if (std::strcmp(key, "concentration") == 0) {
      if (iarg + 1 >= narg) error->all(FLERR, "Illegal fix rod/inflow command: concentration expects 1 value(s)");
      concentration_ = parse_number(error, kStyle, key, arg[iarg + 1]);
      if (!(concentration_ > 0.0)) {
        char msg[200];
        std::snprintf(msg, sizeof(msg), "fix rod/inflow: concentration must be > 0 rods/m^2 (got %g)", concentration_);
        error->all(FLERR, msg);
      }
      have_concentration = true;
      iarg += 2;
      continue;
    }
    if (std::strcmp(key, "layout") == 0 || std::strcmp(key, "jitter") == 0)
      error->all(FLERR, "fix rod/inflow: layout and jitter are not keywords here (rods are placed at random in the band)");
    if (std::strcmp(key, "region") == 0) have_region = true;
    const int used = parse_seeded_rods_keyword(error, kStyle, narg, arg, iarg, spec_);
    if (used == 0) {
      char msg[256];
      std::snprintf(msg, sizeof(msg),
                    "Illegal fix rod/inflow command: unknown keyword '%s' (expected drag, spheres, diameter, type, "
                    "density, region, every, count, seed, angle, min_gap, spacing, bond_type)", key);
      error->all(FLERR, msg);
    }
    iarg += used;
  }
  check_seeded_rods_required(error, kStyle, spec_);
  if (!have_region) error->all(FLERR, "Illegal fix rod/inflow command: missing required keyword region (x0 x1, m)");
  if (nevery < 1) error->all(FLERR, "Illegal fix rod/inflow command: missing required keyword every (steps, >= 1)");
  if (!(spec_.seeding.x_max > spec_.seeding.x_min)) {
    char msg[200];
    std::snprintf(msg, sizeof(msg), "fix rod/inflow: region x0 x1 must have x1 > x0 (got %g %g m)",
                  spec_.seeding.x_min, spec_.seeding.x_max);
    error->all(FLERR, msg);
  }
  if (have_count && have_concentration)
    error->all(FLERR, "fix rod/inflow: count (rods per insertion) and concentration (rods per m^2 kept in the band) "
                      "exclude each other");
  drag_ = seeding_drag_fix(lmp, kStyle, spec_);
  spec_.seeding.layout = hsrod::SeedingLayout::random;
  spec_.seeding.rods = 1;
  // The keywords' ranges and the band inside the planform, now: a trial
  // placement in the empty planform throws invalid_argument for bad input.
  try {
    hsrod::seed_rods(drag_->hydrodynamics().geometry(), spec_.seeding);
  } catch (const std::invalid_argument &e) {
    error->all(FLERR, (std::string("fix rod/inflow: ") + e.what()).c_str());
  } catch (const std::runtime_error &e) {
    error->all(FLERR, (std::string("fix rod/inflow: no rod fits the empty band: ") + e.what()).c_str());
  }
  if (have_concentration) {
    band_target_ = hsrod::rods_at_concentration(drag_->hydrodynamics().geometry(), spec_.seeding, concentration_);
    if (band_target_ < 1) {
      char msg[256];
      std::snprintf(msg, sizeof(msg), "fix rod/inflow: concentration %g rods/m^2 gives no rod in the band's fluid "
                    "area %g m^2 (needs >= %g rods/m^2)", concentration_,
                    hsrod::region_fluid_area(drag_->hydrodynamics().geometry(), spec_.seeding),
                    0.5 / hsrod::region_fluid_area(drag_->hydrodynamics().geometry(), spec_.seeding));
      error->all(FLERR, msg);
    }
  }
  force_reneighbor = 1;  // rods are made in pre_exchange of a step that rebuilds the neighbour lists
  next_reneighbor = -1;
  vector_flag = 1;
  // [1] rods inserted, [2] attempts refused (no free place), since the fix was defined;
  // [3] rods in the band after the last insertion, [4] the concentration's target
  size_vector = 4;
  extvector = 0;
  global_freq = 1;
  restart_global = 1;  // the counts, the attempts (the seeding sequence) and the next IDs
}

int FixRodInflow::setmask() { return PRE_EXCHANGE | PRE_NEIGHBOR; }

void FixRodInflow::init() { drag_ = seeding_drag_fix(lmp, kStyle, spec_); }

// The next insertion at the next multiple of `every`.
void FixRodInflow::setup(int) { next_reneighbor = (update->ntimestep / nevery + 1) * nevery; }

void FixRodInflow::pre_exchange() {
  if (next_reneighbor != update->ntimestep) return;
  next_reneighbor += nevery;
  insert();
}

void FixRodInflow::insert() {
  const hsrod::RodHydrodynamics &scene = drag_->hydrodynamics();
  std::vector<hsrod::RodObstacle> obstacles = atoms_as_obstacles(lmp);
  std::vector<hsrod::SeededRod> placed;
  const int present = rods_in_band();
  const int wanted = concentration_ > 0.0 ? std::max(0, band_target_ - present) : rods_per_insertion_;
  rods_in_band_ = present;
  const double d = spec_.seeding.sphere_diameter;
  const double half_length = 0.5 * (spec_.seeding.spheres - 1) * std::max(spec_.seeding.spacing, d);
  for (int k = 0; k < wanted; k++) {
    hsrod::RodSeedingRequest request = spec_.seeding;
    request.seed = spec_.seeding.seed * kSeedStride + static_cast<std::uint64_t>(attempts_++);
    try {
      const hsrod::SeededRod rod = hsrod::seed_rods(scene.geometry(), request, obstacles).front();
      const Eigen::Vector2d axis(std::sin(rod.angle), std::cos(rod.angle));
      obstacles.push_back({rod.centre - half_length * axis, rod.centre + half_length * axis, d});
      placed.push_back(rod);
    } catch (const std::runtime_error &) {
      rods_refused_++;  // no free place in the band now (the same on every rank)
    }
  }
  rods_in_band_ += static_cast<int>(placed.size());
  if (placed.empty()) return;
  CreateRod creator(lmp);
  CreateRod::NextRodIds next = creator.next_ids();
  next.tag = std::max(next.tag, next_tag_);
  next.mol = std::max(next.mol, next_mol_);
  const int first_tag = next.tag;
  make_seeded_rods(creator, next, spec_, placed, scene.gap_bottom() + 0.5 * scene.geometry().gap_height());
  // The special-list rebuild reports its neighbour counts at every call:
  // once per insertion would fill the log, so it runs without screen and log.
  FILE *const screen_kept = screen, *const logfile_kept = logfile;
  screen = logfile = nullptr;
  creator.finish();
  screen = screen_kept;
  logfile = logfile_kept;
  next_tag_ = next.tag;
  next_mol_ = next.mol;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->tag[i] >= first_tag) atom->mask[i] |= groupbit;
  rods_inserted_ += static_cast<long>(placed.size());
  rest_states_pending_ = true;
}

// The new rods' bonds take their current (straight) geometry as rest state,
// as at a run's start: fix rod/bonds' set-up, once the new spheres are
// ghosts where their partners need them (after the borders of this step).
// Its forces are cleared before this step's forces are computed.
void FixRodInflow::pre_neighbor() {
  if (!rest_states_pending_) return;
  rest_states_pending_ = false;
  for (int f = 0; f < modify->nfix; f++)
    if (auto *bonds = dynamic_cast<FixRodBonds *>(modify->fix[f])) bonds->setup(0);
}

// A rod is in the band when the mean of its sphere centres is (the rods
// of the group, all ranks: sums of x and counts per molecule).
int FixRodInflow::rods_in_band() {
  std::vector<double> mine;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) mine.insert(mine.end(), {static_cast<double>(atom->molecule[i]), atom->x[i][0]});
  const std::vector<double> all = allgather_all(world, comm->nprocs, mine);
  std::map<int, std::pair<double, int>> sums;  // molecule -> (sum of x [m], spheres)
  for (std::size_t k = 0; k + 1 < all.size(); k += 2) {
    auto &sum = sums[static_cast<int>(all[k])];
    sum.first += all[k + 1];
    sum.second++;
  }
  int inside = 0;
  for (const auto &entry : sums) {
    const double centre = entry.second.first / entry.second.second;
    if (centre >= spec_.seeding.x_min && centre <= spec_.seeding.x_max) inside++;
  }
  return inside;
}

double FixRodInflow::compute_vector(int n) {
  if (n == 0) return static_cast<double>(rods_inserted_);
  if (n == 1) return static_cast<double>(rods_refused_);
  return n == 2 ? rods_in_band_ : band_target_;
}

// Global restart data: [rods inserted, refused, attempts, next atom ID, next molecule ID].
void FixRodInflow::write_restart(FILE *fp) {
  if (comm->me != 0) return;
  const double data[5] = {static_cast<double>(rods_inserted_), static_cast<double>(rods_refused_),
                          static_cast<double>(attempts_), static_cast<double>(next_tag_),
                          static_cast<double>(next_mol_)};
  const int size = static_cast<int>(sizeof(data));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(data, sizeof(double), 5, fp);
}

void FixRodInflow::restart(char *buf) {
  const double *data = reinterpret_cast<const double *>(buf);
  rods_inserted_ = static_cast<long>(data[0]);
  rods_refused_ = static_cast<long>(data[1]);
  attempts_ = static_cast<long>(data[2]);
  next_tag_ = static_cast<int>(data[3]);
  next_mol_ = static_cast<int>(data[4]);
}

/* ----------------------------------------------------------------------
   hsrod - fix rod/outflow (see fix_rod_outflow.h)

   fix ID group rod/outflow x_out X [every N]
     x_out: the removal plane [m], inside the box in x
     every: steps between the checks (>= 1, default 1)
------------------------------------------------------------------------- */

#include "fix_rod_outflow.h"

#include "fix_rod_outcome.h"
#include "keyword_parsing.h"
#include "rod_gather.h"
#include "rod_removal.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "lmptype.h"
#include "modify.h"
#include "update.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
constexpr const char *kStyle = "fix rod/outflow";
}

FixRodOutflow::FixRodOutflow(LAMMPS *instance, int narg, char **arg)
    : Fix(instance, narg, arg), outlet_x_(0.0), rods_removed_(0), spheres_removed_(0), rods_removed_at_setup_(0) {
  if (!domain->box_exist) error->all(FLERR, "fix rod/outflow: define the simulation box first");
  if (!atom->molecule_flag) error->all(FLERR, "fix rod/outflow: needs molecule IDs (atom_style ... molecular)");
  bool have_outlet = false;
  nevery = 1;
  for (int iarg = 3; iarg < narg; iarg += 2) {
    const char *key = arg[iarg];
    if (iarg + 1 >= narg) {
      char msg[160];
      std::snprintf(msg, sizeof(msg), "Illegal fix rod/outflow command: keyword %s needs a value", key);
      error->all(FLERR, msg);
    }
    if (std::strcmp(key, "x_out") == 0) {
      outlet_x_ = parse_number(error, kStyle, key, arg[iarg + 1]);
      have_outlet = true;
    } else if (std::strcmp(key, "every") == 0) {
      nevery = parse_integer(error, kStyle, key, arg[iarg + 1]);
      if (nevery < 1) {
        char msg[160];
        std::snprintf(msg, sizeof(msg), "fix rod/outflow: every must be an integer >= 1 (got %d)", nevery);
        error->all(FLERR, msg);
      }
    } else {
      char msg[200];
      std::snprintf(msg, sizeof(msg), "Illegal fix rod/outflow command: unknown keyword '%s' (expected x_out, every)",
                    key);
      error->all(FLERR, msg);
    }
  }
  if (!have_outlet) error->all(FLERR, "Illegal fix rod/outflow command: missing required keyword x_out");
  // A plane at or beyond a face removes nothing: a rod is held whole at the
  // face by fix rod/implicit, its last spheres short of the plane.
  if (!(outlet_x_ > domain->boxlo[0] && outlet_x_ < domain->boxhi[0])) {
    char msg[256];
    std::snprintf(msg, sizeof(msg), "fix rod/outflow: x_out %g m must lie inside the box in x, in (%g, %g) m",
                  outlet_x_, domain->boxlo[0], domain->boxhi[0]);
    error->all(FLERR, msg);
  }
  force_reneighbor = 1;  // atoms are deleted in pre_exchange of a step that rebuilds the neighbour lists
  next_reneighbor = -1;
  vector_flag = 1;
  size_vector = 2;  // [1] rods removed, [2] spheres removed (since the fix was defined)
  extvector = 0;
  global_freq = 1;
  restart_global = 1;  // the counts
}

int FixRodOutflow::setmask() { return PRE_EXCHANGE | END_OF_STEP; }

// A rod removed before fix rod/outcome saw it pass would stay undecided for
// ever: the outcome's pass plane must come first.
void FixRodOutflow::init() {
  for (int f = 0; f < modify->nfix; f++) {
    const auto *outcome = dynamic_cast<const FixRodOutcome *>(modify->fix[f]);
    if (!outcome || outcome->pass_x() <= outlet_x_) continue;
    char msg[320];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/outflow: x_out %g m is upstream of the pass_x %g m of fix rod/outcome %s: rods would be "
                  "removed before their outcome is decided; use x_out >= %g m", outlet_x_, outcome->pass_x(),
                  modify->fix[f]->id, outcome->pass_x());
    error->all(FLERR, msg);
  }
}

// Rods already past the plane when a run starts go before its first step.
void FixRodOutflow::setup_pre_exchange() {
  rods_removed_at_setup_ = rods_removed_;
  remove_rods(rods_past_outlet());
}

// The check after a step; the deletion at the next step's neighbour-list
// rebuild (forced), where LIGGGHTS exchanges atoms and rebuilds ghosts.
void FixRodOutflow::end_of_step() {
  if (!rods_past_outlet().empty()) next_reneighbor = update->ntimestep + 1;
}

void FixRodOutflow::pre_exchange() {
  if (next_reneighbor != update->ntimestep) return;
  remove_rods(rods_past_outlet());
}

std::vector<int> FixRodOutflow::rods_past_outlet() {
  const int nlocal = atom->nlocal;
  // Rods with some sphere past the plane here, then from every processor.
  std::vector<int> mine;
  for (int i = 0; i < nlocal; i++)
    if ((atom->mask[i] & groupbit) && atom->molecule[i] > 0 && atom->x[i][0] >= outlet_x_)
      mine.push_back(atom->molecule[i]);
  std::sort(mine.begin(), mine.end());
  mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
  std::vector<int> candidates = allgather_all(world, comm->nprocs, mine);
  if (candidates.empty()) return candidates;
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  // A candidate with any sphere short of the plane, on any processor, stays.
  std::vector<int> short_here(candidates.size(), 0), short_anywhere(candidates.size(), 0);
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || atom->x[i][0] >= outlet_x_) continue;
    const auto it = std::lower_bound(candidates.begin(), candidates.end(), atom->molecule[i]);
    if (it != candidates.end() && *it == atom->molecule[i]) short_here[it - candidates.begin()] = 1;
  }
  MPI_Allreduce(short_here.data(), short_anywhere.data(), static_cast<int>(candidates.size()), MPI_INT, MPI_MAX,
                world);
  std::vector<int> past;
  for (std::size_t k = 0; k < candidates.size(); k++)
    if (!short_anywhere[k]) past.push_back(candidates[k]);
  return past;
}

void FixRodOutflow::remove_rods(const std::vector<int> &molecules) {
  if (molecules.empty()) return;
  for (int f = 0; f < modify->nfix; f++)
    if (auto *listener = dynamic_cast<RodRemovalListener *>(modify->fix[f])) listener->forget_rods(molecules);
  // Every atom of the rods (the whole molecule, also spheres outside the
  // group), the last local atom moved into each freed slot; the fixes'
  // per-atom data moves with it (AtomVec::copy).
  int nlocal = atom->nlocal;
  bigint deleted_here = 0;
  for (int i = 0; i < nlocal;) {
    if (std::binary_search(molecules.begin(), molecules.end(), atom->molecule[i])) {
      atom->avec->copy(nlocal - 1, i, 1);
      nlocal--;
      deleted_here++;
    } else {
      i++;
    }
  }
  atom->nlocal = nlocal;
  // Totals from what is left: atoms, and bonds (stored once with
  // newton_bond, on both spheres otherwise). A rod's bonds join its own
  // spheres only, so no remaining atom's bond or special list names a
  // deleted atom.
  bigint here[3] = {nlocal, 0, deleted_here}, total[3] = {0, 0, 0};
  for (int i = 0; i < nlocal; i++) here[1] += atom->num_bond[i];
  MPI_Allreduce(here, total, 3, MPI_LMP_BIGINT, MPI_SUM, world);
  atom->natoms = total[0];
  atom->nbonds = force->newton_bond ? total[1] : total[1] / 2;
  if (atom->map_style) {
    atom->nghost = 0;
    atom->map_init();
    atom->map_set();
  }
  rods_removed_ += static_cast<long>(molecules.size());
  spheres_removed_ += static_cast<long>(total[2]);
}

void FixRodOutflow::post_run() {
  if (comm->me != 0) return;
  char msg[256];
  std::snprintf(msg, sizeof(msg), "fix rod/outflow: %ld rod(s) removed past x = %g m in this run (%ld in all)\n",
                rods_removed_ - rods_removed_at_setup_, outlet_x_, rods_removed_);
  if (screen) std::fputs(msg, screen);
  if (logfile) std::fputs(msg, logfile);
}

double FixRodOutflow::compute_vector(int n) {
  return n == 0 ? static_cast<double>(rods_removed_) : static_cast<double>(spheres_removed_);
}

// Global restart data: [rods removed, spheres removed].
void FixRodOutflow::write_restart(FILE *fp) {
  if (comm->me != 0) return;
  const double data[2] = {static_cast<double>(rods_removed_), static_cast<double>(spheres_removed_)};
  const int size = static_cast<int>(sizeof(data));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(data, sizeof(double), 2, fp);
}

void FixRodOutflow::restart(char *buf) {
  const double *data = reinterpret_cast<const double *>(buf);
  rods_removed_ = static_cast<long>(data[0]);
  spheres_removed_ = static_cast<long>(data[1]);
}

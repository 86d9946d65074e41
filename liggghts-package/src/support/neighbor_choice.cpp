#include "neighbor_choice.h"

#include "comm.h"
#include "domain.h"
#include "force.h"
#include "lammps.h"
#include "neighbor.h"
#include "pair.h"
#include "atom.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hsrod {
namespace {

constexpr int kNeighborBin = 1;              // Neighbor::style: 0 nsq, 1 bin, 2 multi
constexpr double kLiggghtsCutToBinRatio = 100.0;  // CUT2BIN_RATIO of neighbor.cpp

// Largest neighbor cutoff [m] as Neighbor::init computes it.
double largest_neighbor_cutoff(LAMMPS_NS::LAMMPS *lmp) {
  LAMMPS_NS::Pair *pair = lmp->force->pair;
  if (!pair || !pair->cutsq) return 0.0;
  double largest = 0.0;
  const int types = lmp->atom->ntypes;
  for (int i = 1; i <= types; i++)
    for (int j = 1; j <= types; j++) {
      const double cut = std::sqrt(pair->cutsq[i][j]);
      if (cut > 0.0) largest = std::max(largest, cut + lmp->neighbor->skin);
    }
  return largest;
}

}  // namespace

void choose_neighbor_style(LAMMPS_NS::LAMMPS *lmp, const char *who) {
  LAMMPS_NS::Neighbor *neighbor = lmp->neighbor;
  LAMMPS_NS::Domain *domain = lmp->domain;
  if (neighbor->style != kNeighborBin || domain->triclinic) return;
  const double box[3] = {domain->boxhi[0] - domain->boxlo[0], domain->boxhi[1] - domain->boxlo[1],
                         domain->boxhi[2] - domain->boxlo[2]};  // [m]
  double bin = 0.5 * largest_neighbor_cutoff(lmp);              // [m]
  if (bin == 0.0) bin = box[0];
  double worst = 0.0;  // largest bin / (box side split into whole bins) [-]
  int side = 0;
  for (int a = 0; a < 3; a++) {
    const int bins = std::max(1, static_cast<int>(box[a] / bin));
    const double ratio = bin / (box[a] / bins);
    if (ratio > worst) {
      worst = ratio;
      side = a;
    }
  }
  if (worst <= kLiggghtsCutToBinRatio) return;
  neighbor->style = 0;  // nsq
  if (lmp->comm->me != 0) return;
  char msg[512];
  std::snprintf(msg, sizeof(msg),
                "%s: the box (%g x %g x %g m) is too thin for LIGGGHTS' neighbor bins (bin %g m, %.3g times its %c "
                "side: 'Cannot use neighbor bins - box size << cutoff'): using 'neighbor %g nsq' (set it in the "
                "script to choose yourself)\n",
                who, box[0], box[1], box[2], bin, worst, "xyz"[side], neighbor->skin);
  if (lmp->screen) std::fputs(msg, lmp->screen);
  if (lmp->logfile) std::fputs(msg, lmp->logfile);
}

}  // namespace hsrod

/* ----------------------------------------------------------------------
   hsrod - fix hele_shaw/drag: checks of the scene against the spheres
   before any work: confinement beta against the coefficient table before
   the background flow is solved, and at each run's start the spheres'
   placement in the fluid, between the gap walls and in the gap's
   mid-plane. (The model's own resources are checked by the facade,
   RodHydrodynamics::choose_model.)
   See fix_hele_shaw_drag.h.
------------------------------------------------------------------------- */

#include "fix_hele_shaw_drag.h"

#include "atom.h"
#include "comm.h"
#include "error.h"

#include "rod_gather.h"

#include "flow/grid_brinkman_flow.h"
#include "hydro/rod_hydrodynamics.h"
#include "rod_assembly.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

using namespace LAMMPS_NS;

namespace {
// Cells the grid should put across the narrowest pillar gap: half the
// solver's 16 across the narrowest opening, which a single centred
// cylinder's two gaps share.
constexpr double kCellsAcrossPillarGap = 8.0;
constexpr double kWallOverlapAllowed = 0.1;  // gap-wall overlap accepted at init [sphere radii]
// Sphere centres farther than this from the gap's mid-plane are warned
// about: the model holds for rods in the mid-plane [fraction of H].
constexpr double kMidPlaneTolerance = 0.05;
}  // namespace

// beta = d / H against the coefficient table before the background flow is
// solved, so that a beta outside the table is refused before a long grid solve.
// Spheres created later are checked in init() by the facade.
void FixHeleShawDrag::check_confinement_before_solve(const hsrod::SceneSpec &scene, const hsrod::ModelSpec &model) {
  double dmin = 1e300;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) dmin = std::min(dmin, 2.0 * atom->radius[i]);
  double d = 1e300;
  MPI_Allreduce(&dmin, &d, 1, MPI_DOUBLE, MPI_MIN, world);
  if (d > 1e299) return;  // no spheres yet
  const double beta = d / scene.gap_height;
  char msg[512];
  if (!(beta < 1.0)) {
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: sphere diameter %g m >= gap height %g m (beta = d/H must be < 1)",
                  d, scene.gap_height);
    error->all(FLERR, msg);
  }
  // The pore's opening W - 2R against the spheres (a pore closed
  // to 0.2 um was refused later for the size of the flow grid it needs).
  if (scene.pore_radius > 0.0 && scene.width - 2.0 * scene.pore_radius < d) {
    std::snprintf(msg, sizeof(msg),
                  "fix hele_shaw/drag: pore opening W - 2R = %g m (pore radius %g m, channel width %g m) is narrower "
                  "than the rod's spheres (d = %g m): the rod cannot enter the pore; pore radius must be <= "
                  "(W - d)/2 = %g m", scene.width - 2.0 * scene.pore_radius, scene.pore_radius, scene.width, d,
                  0.5 * (scene.width - d));
    error->all(FLERR, msg);
  }
  // Every gap of a pillar array (between pillars, and the >= G/2 left to
  // the side walls) against the spheres, before the flow solve; overlapping
  // pillars are refused by the lattice itself (pillar_array), with its ranges.
  const double diameter = 2.0 * scene.pillars.radius;
  if (scene.pillars.radius > 0.0 && scene.pillars.spacing_x > diameter && scene.pillars.spacing_y > diameter) {
    const double gap = std::min(hsrod::narrowest_pillar_gap(scene.pillars), 0.5 * hsrod::pillar_gap(scene.pillars));
    if (gap < d) {
      std::snprintf(msg, sizeof(msg),
                    "fix hele_shaw/drag: pillars leave gaps of %g m (between pillars: %g m, to the side walls: >= "
                    "G/2 = %g m) narrower than the rod's spheres (d = %g m): spacing_x and spacing_y must leave "
                    "every gap >= d", gap, hsrod::narrowest_pillar_gap(scene.pillars),
                    0.5 * hsrod::pillar_gap(scene.pillars), d);
      error->all(FLERR, msg);
    }
  }
  try {
    const hsrod::ConfinementTable table = model.coefficients_file.empty()
                                              ? hsrod::ConfinementTable::default_table()
                                              : hsrod::ConfinementTable::read(model.coefficients_file);
    if (!(beta >= table.rows().front().beta && beta <= table.max_beta())) {
      std::snprintf(msg, sizeof(msg),
                    "fix hele_shaw/drag: confinement beta = d/H = %g outside the coefficient table's range [%g, %g] "
                    "(d = %g m, H = %g m); checked before the background flow is solved",
                    beta, table.rows().front().beta, table.max_beta(), d, scene.gap_height);
      error->all(FLERR, msg);
    }
  } catch (const std::exception &e) {
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: %s", e.what());
    error->all(FLERR, msg);
  }
}

// Every sphere in the fluid, between the gap walls, and (warned) in the
// gap's mid-plane, at the start of each run ('placement_check no' skips).
void FixHeleShawDrag::check_placement() {
  // Every sphere must start in the fluid (inside the planform and the gap).
  int outside = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double *x = atom->x[i];
    if (!hydro_->in_fluid(Eigen::Vector3d(x[0], x[1], x[2]))) outside++;
  }
  int total_outside = 0;
  MPI_Allreduce(&outside, &total_outside, 1, MPI_INT, MPI_SUM, world);
  if (total_outside > 0) {
    char msg[256];
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/drag: %d sphere centre(s) outside the channel planform or gap",
                  total_outside);
    error->all(FLERR, msg);
  }
  // Every sphere must fit between the gap walls (a rod centred in the lower
  // wall z = 0 would otherwise be accepted and pushed out). Overlaps up to 0.1 r
  // pass: a rod touching a wall at the end of a run (Hertz overlap, bounded
  // per step by fix rod/implicit's guard at 0.1 r) may be run on.
  const double bottom = hydro_->gap_bottom(), top = bottom + hydro_->geometry().gap_height();
  int overlapping = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double z = atom->x[i][2], r = atom->radius[i];
    if (z - r < bottom - kWallOverlapAllowed * r || z + r > top + kWallOverlapAllowed * r) overlapping++;
  }
  int total_overlapping = 0;
  MPI_Allreduce(&overlapping, &total_overlapping, 1, MPI_INT, MPI_SUM, world);
  if (total_overlapping > 0) {
    char msg[256];
    std::snprintf(msg, sizeof(msg),
                  "fix hele_shaw/drag: %d sphere(s) overlap the gap walls by more than %g r: centres must lie in "
                  "[z_bottom + r, z_top - r] = [%g + r, %g - r] m ('placement_check no' to run anyway)",
                  total_overlapping, kWallOverlapAllowed, bottom, top);
    error->all(FLERR, msg);
  }
  // The model is gap-averaged for rods in the mid-plane (Faxen's mid-plane
  // friction and driving; the 3-D flow u(x,y) 6 (z/H)(1 - z/H)): a rod
  // centred at z = H/4 moves exactly like one in the mid-plane.
  // Off the mid-plane the flow is slower (3/4 of the mid-plane velocity at
  // H/4) and the friction higher; not modelled, so said once.
  if (midplane_warned_) return;
  // Per rod: the mean z of its spheres (a multi-sphere section is centred
  // on the mid-plane, its spheres are not). RodGather holds every rod on
  // every rank.
  const double gap = hydro_->geometry().gap_height(), middle = bottom + 0.5 * gap;
  RodGather gather(lmp);
  gather.gather(groupbit, nullptr);
  double largest_off = 0.0;  // largest |mean z - mid-plane| [m]
  int total_off = 0;         // rods off the mid-plane
  for (const auto &rod : gather.rods) {
    double mean_z = 0.0;
    for (const auto &sphere : rod.second) mean_z += sphere.position[2] / rod.second.size();
    const double distance = std::fabs(mean_z - middle);
    if (distance > kMidPlaneTolerance * gap) total_off++;
    largest_off = std::max(largest_off, distance);
  }
  if (total_off == 0) return;
  midplane_warned_ = true;
  if (comm->me != 0) return;
  char msg[512];
  std::snprintf(msg, sizeof(msg),
                "fix hele_shaw/drag: %d rod(s) centred off the gap mid-plane z = %g m by up to %.3g H: the reduced "
                "model holds for rods in the mid-plane (Faxen's mid-plane friction and driving) and moves them as if "
                "there; the slower flow (at H/4: 3/4 of the mid-plane velocity) and higher friction off it are not "
                "modelled", total_off, middle, largest_off / gap);
  error->warning(FLERR, msg);
}


// The grid's cell size is set by the wall layer and by the narrowest total
// opening of a cross-section (GridBrinkmanOptions), not by the gap between
// two pillars: warn when a pillar gap gets fewer than 8 cells (thin gaps,
// where the exponentially fitted wall layer lets the cells grow).
void FixHeleShawDrag::warn_pillar_resolution(const hsrod::SceneSpec &scene) {
  if (!(scene.pillars.radius > 0.0) || comm->me != 0) return;
  const auto *grid = dynamic_cast<const hsrod::GridBrinkmanFlow *>(&hydro_->flow());
  if (!grid) return;
  const double gap = std::min(hsrod::narrowest_pillar_gap(scene.pillars), 0.5 * hsrod::pillar_gap(scene.pillars));
  const double cell = std::max(grid->cell_size_x(), grid->cell_size_y());
  if (gap / cell >= kCellsAcrossPillarGap) return;
  char msg[512];
  std::snprintf(msg, sizeof(msg),
                "fix hele_shaw/drag: the background-flow grid resolves the narrowest pillar gap (%g m) by %.1f cells "
                "of %g m, fewer than %g: the flow between the pillars is approximate (larger pillar spacings, or a "
                "thicker gap, give more cells)", gap, gap / cell, cell, kCellsAcrossPillarGap);
  error->warning(FLERR, msg);
}

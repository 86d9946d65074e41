/* ----------------------------------------------------------------------
   hsrod - compute hele_shaw/pressure_drop (see compute_hele_shaw_pressure_drop.h)

   compute ID group hele_shaw/pressure_drop DRAG-ID [sections x_up x_down] [pieces n]
   Global scalar: total pressure drop [Pa]. Global vector: 1 total [Pa],
   2 background flow between the sections [Pa], 3 rise from the loads on the
   spheres of the group [Pa], 4 flow rate Q [m^3/s].
------------------------------------------------------------------------- */

#include "compute_hele_shaw_pressure_drop.h"

#include "atom.h"
#include "error.h"
#include "keyword_parsing.h"
#include "modify.h"
#include "update.h"

#include "fix_hele_shaw_drag.h"

#include "flow/flow_probe.h"
#include "flow/particle_pressure_drop.h"
#include "hydro/rod_hydrodynamics.h"

#include <mpi.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

using namespace LAMMPS_NS;

ComputeHeleShawPressureDrop::ComputeHeleShawPressureDrop(LAMMPS *instance, int &iarg, int narg, char **arg)
    : Compute(instance, iarg, narg, arg),
      drag_(nullptr),
      x_up_(0.0),
      x_down_(0.0),
      pieces_(2000),
      background_(0.0),
      background_done_(false) {
  const char *style_name = "compute hele_shaw/pressure_drop";
  if (iarg >= narg)
    error->all(FLERR, "Illegal compute hele_shaw/pressure_drop command: missing the ID of a fix hele_shaw/drag");
  drag_id_ = arg[iarg++];
  find_drag();
  const hsrod::ChannelGeometry &g = drag_->flow().geometry();
  x_up_ = g.x_lo();
  x_down_ = g.x_hi();
  while (iarg < narg) {
    const char *key = arg[iarg];
    if (strcmp(key, "sections") == 0) {
      if (iarg + 2 >= narg) error->all(FLERR, "Illegal compute hele_shaw/pressure_drop command: sections needs x_up x_down");
      x_up_ = parse_number(error, style_name, key, arg[iarg + 1]);
      x_down_ = parse_number(error, style_name, key, arg[iarg + 2]);
      if (!(g.x_lo() <= x_up_ && x_up_ < x_down_ && x_down_ <= g.x_hi()))
        error->all(FLERR, "compute hele_shaw/pressure_drop: sections need x_lo <= x_up < x_down <= x_hi of the channel");
      iarg += 3;
    } else if (strcmp(key, "pieces") == 0) {
      if (iarg + 1 >= narg) error->all(FLERR, "Illegal compute hele_shaw/pressure_drop command: pieces needs a value");
      pieces_ = parse_integer(error, style_name, key, arg[iarg + 1]);
      if (pieces_ < 10 || pieces_ > 1000000) error->all(FLERR, "compute hele_shaw/pressure_drop: pieces must be in [10, 1000000]");
      iarg += 2;
    } else {
      char msg[256];
      std::snprintf(msg, sizeof(msg),
                    "Illegal compute hele_shaw/pressure_drop command: unknown keyword '%s' (expected sections, pieces)", key);
      error->all(FLERR, msg);
    }
  }
  scalar_flag = 1;
  extscalar = 0;
  vector_flag = 1;
  size_vector = N_ENTRIES;
  extvector = 0;
  vector = new double[N_ENTRIES];
}

ComputeHeleShawPressureDrop::~ComputeHeleShawPressureDrop() { delete[] vector; }

void ComputeHeleShawPressureDrop::find_drag() {
  const int f = modify->find_fix(drag_id_.c_str());
  drag_ = f < 0 ? nullptr : dynamic_cast<FixHeleShawDrag *>(modify->fix[f]);
  if (!drag_) {
    char msg[256];
    std::snprintf(msg, sizeof(msg),
                  "compute hele_shaw/pressure_drop: '%s' is not the ID of a fix hele_shaw/drag defined before",
                  drag_id_.c_str());
    error->all(FLERR, msg);
  }
}

void ComputeHeleShawPressureDrop::init() { find_drag(); }

double ComputeHeleShawPressureDrop::compute_scalar() {
  invoked_scalar = update->ntimestep;
  compute_vector();
  scalar = vector[TOTAL];
  return scalar;
}

void ComputeHeleShawPressureDrop::compute_vector() {
  invoked_vector = update->ntimestep;
  const hsrod::BackgroundFlow &flow = drag_->flow();
  const hsrod::ChannelGeometry &g = flow.geometry();
  if (!background_done_) {
    background_ = hsrod::section_pressure_drop(flow, x_up_, x_down_, pieces_);
    background_done_ = true;
  }
  const double q = flow.mean_velocity() * g.width() * g.gap_height();
  // Loads: the drag fix's per-atom hydrodynamic force on the spheres of this
  // compute's group (its last evaluation), local atoms, summed over ranks.
  std::vector<hsrod::ParticleLoad> loads;
  double **sphere_force = drag_->array_atom;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || !(atom->mask[i] & drag_->groupbit)) continue;
    hsrod::ParticleLoad p;
    p.position = Eigen::Vector3d(atom->x[i][0], atom->x[i][1], atom->x[i][2]);
    p.radius = atom->radius[i];
    p.force = Eigen::Vector3d(sphere_force[i][0], sphere_force[i][1], sphere_force[i][2]);
    loads.push_back(p);
  }
  double local = 0.0, rods = 0.0;
  try {
    local = hsrod::particle_pressure_drop(flow, loads, drag_->hydrodynamics().gap_bottom(), q);
  } catch (const std::exception &e) {
    char msg[512];
    std::snprintf(msg, sizeof(msg), "compute hele_shaw/pressure_drop: %s", e.what());
    error->one(FLERR, msg);
  }
  MPI_Allreduce(&local, &rods, 1, MPI_DOUBLE, MPI_SUM, world);
  vector[BACKGROUND] = background_;
  vector[RODS] = rods;
  vector[TOTAL] = background_ + rods;
  vector[FLOW_RATE] = q;
}

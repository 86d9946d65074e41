/* ----------------------------------------------------------------------
   hsrod - fix hele_shaw/field (see fix_hele_shaw_field.h)

   fix ID group hele_shaw/field DRAG-ID N prefix keyword values ...
     spacing h        lattice spacing [m] (default: the flow grid's cell, or
                      min(L, W)/100 for a straight channel)
     gap_layers n     3-D image with n + 1 layers through the gap, parabolic
                      profile (default 0: the gap-averaged field at mid-gap)
     walls yes|no     write <prefix>_walls.vtp once (default yes)
     disturbed yes|no at level 4 (model twoway), add each rod's window
                      disturbance to the background (default yes)
   Writes <prefix>_<step>.vti at the start of the first run and every N
   steps, and <prefix>.pvd.
------------------------------------------------------------------------- */

#include "fix_hele_shaw_field.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "keyword_parsing.h"
#include "modify.h"
#include "update.h"

#include "fix_hele_shaw_drag.h"
#include "rod_gather.h"

#include "flow/flow_field_vtk.h"
#include "flow/grid_brinkman_flow.h"
#include "hydro/rod_hydrodynamics.h"
#include "hydro/twoway_disturbance.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>

using namespace LAMMPS_NS;
using namespace FixConst;

FixHeleShawField::FixHeleShawField(LAMMPS *instance, int narg, char **arg)
    : Fix(instance, narg, arg),
      drag_(nullptr),
      spacing_(0.0),
      gap_layers_(0),
      walls_(true),
      disturbed_(true),
      walls_written_(false),
      last_written_(-1) {
  const char *style_name = "fix hele_shaw/field";
  if (narg < 6)
    error->all(FLERR, "Illegal fix hele_shaw/field command: expected fix ID group hele_shaw/field drag-ID N prefix");
  drag_id_ = arg[3];
  find_drag();
  nevery = parse_integer(error, style_name, "N", arg[4]);
  if (nevery < 1) error->all(FLERR, "fix hele_shaw/field: N (output interval) must be >= 1 step");
  prefix_ = arg[5];
  int iarg = 6;
  while (iarg < narg) {
    const char *key = arg[iarg];
    if (iarg + 1 >= narg) {
      char msg[256];
      std::snprintf(msg, sizeof(msg), "Illegal fix hele_shaw/field command: keyword %s needs a value", key);
      error->all(FLERR, msg);
    }
    if (strcmp(key, "spacing") == 0) {
      spacing_ = parse_number(error, style_name, key, arg[iarg + 1]);
      if (!(spacing_ > 0.0)) error->all(FLERR, "fix hele_shaw/field: spacing must be > 0 m");
    } else if (strcmp(key, "gap_layers") == 0) {
      gap_layers_ = parse_integer(error, style_name, key, arg[iarg + 1]);
      if (gap_layers_ < 0 || gap_layers_ > 1000) error->all(FLERR, "fix hele_shaw/field: gap_layers must be in [0, 1000]");
    } else if (strcmp(key, "walls") == 0) {
      walls_ = parse_yes_no(error, style_name, key, arg[iarg + 1]);
    } else if (strcmp(key, "disturbed") == 0) {
      disturbed_ = parse_yes_no(error, style_name, key, arg[iarg + 1]);
    } else {
      char msg[256];
      std::snprintf(msg, sizeof(msg),
                    "Illegal fix hele_shaw/field command: unknown keyword '%s' (expected spacing, gap_layers, walls, disturbed)", key);
      error->all(FLERR, msg);
    }
    iarg += 2;
  }
  if (spacing_ == 0.0) {
    const hsrod::BackgroundFlow &flow = drag_->flow();
    const auto *grid = dynamic_cast<const hsrod::GridBrinkmanFlow *>(&flow);
    spacing_ = grid ? std::min(grid->cell_size_x(), grid->cell_size_y())
                    : std::min(flow.geometry().length(), flow.geometry().width()) / 100.0;
  }
  // Refuse a lattice that is too large now, not at the first output.
  try {
    hsrod::planform_lattice(drag_->flow().geometry(), spacing_, drag_->hydrodynamics().gap_bottom(), gap_layers_);
  } catch (const std::exception &e) {
    char msg[512];
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/field: %s", e.what());
    error->all(FLERR, msg);
  }
}

int FixHeleShawField::setmask() { return END_OF_STEP; }

void FixHeleShawField::find_drag() {
  const int f = modify->find_fix(drag_id_.c_str());
  drag_ = f < 0 ? nullptr : dynamic_cast<FixHeleShawDrag *>(modify->fix[f]);
  if (!drag_) {
    char msg[256];
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/field: '%s' is not the ID of a fix hele_shaw/drag defined before",
                  drag_id_.c_str());
    error->all(FLERR, msg);
  }
}

void FixHeleShawField::init() { find_drag(); }

// The first run writes its initial frame; later runs (a script running in
// chunks) continue the series every N steps without a frame per chunk.
void FixHeleShawField::setup(int) {
  if (frames_.empty() && last_written_ < 0) write_frame();
}

void FixHeleShawField::end_of_step() { write_frame(); }

// Level 4: the rods' last loads (the drag fix's per-atom columns), gathered
// on every processor by molecule, spheres in tag order as the drag fix hands
// them to the model (rod_assembly.h). Collective.
std::vector<hsrod::RodLoadSample> FixHeleShawField::gather_rod_loads() {
  std::vector<hsrod::RodLoadSample> rods;
  RodGather gather(lmp);
  gather.gather(drag_->groupbit, nullptr);
  std::vector<double> mine;  // tag, total xyz, friction xyz per local sphere
  double **load = drag_->array_atom;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & drag_->groupbit)) continue;
    mine.push_back(static_cast<double>(atom->tag[i]));
    for (int a = 0; a < 3; a++) mine.push_back(load[i][FixHeleShawDrag::TOTAL_X + a]);
    for (int a = 0; a < 3; a++) mine.push_back(load[i][FixHeleShawDrag::FRICTION_X + a]);
  }
  const std::vector<double> all = allgather_all(world, comm->nprocs, mine);
  std::map<int, std::pair<Eigen::Vector3d, Eigen::Vector3d>> by_tag;
  for (std::size_t k = 0; k + 6 < all.size(); k += 7)
    by_tag[static_cast<int>(all[k])] = {Eigen::Vector3d(all[k + 1], all[k + 2], all[k + 3]),
                                        Eigen::Vector3d(all[k + 4], all[k + 5], all[k + 6])};
  for (const auto &entry : gather.rods) {
    if (entry.first <= 0) continue;
    hsrod::RodLoadSample rod;
    rod.id = entry.first;
    for (const GatheredSphere &s : entry.second) {
      rod.positions.push_back(s.position);
      rod.total_force.push_back(by_tag[s.tag].first);
      rod.friction_force.push_back(by_tag[s.tag].second);
    }
    rods.push_back(std::move(rod));
  }
  return rods;
}

// The background field is the same on every processor: processor 0 samples
// and writes it (with the rods' disturbances at level 4, gathered first on all).
void FixHeleShawField::write_frame() {
  if (last_written_ == update->ntimestep) return;
  last_written_ = update->ntimestep;
  const hsrod::RodHydrodynamics &hydro = drag_->hydrodynamics();
  const auto *twoway = hydro.has_model() ? dynamic_cast<const hsrod::TwoWayWindowModel *>(&hydro.model()) : nullptr;
  const auto *state = dynamic_cast<const hsrod::TwoWayWindowState *>(hydro.model_state());
  std::vector<hsrod::RodLoadSample> rods;
  if (disturbed_ && twoway && state) rods = gather_rod_loads();
  if (comm->me != 0) return;
  const hsrod::BackgroundFlow &flow = drag_->flow();
  const double time = update->atime + (update->ntimestep - update->atimestep) * update->dt;
  char name[512];
  std::snprintf(name, sizeof(name), "%s_" BIGINT_FORMAT ".vti", prefix_.c_str(), update->ntimestep);
  try {
    if (walls_ && !walls_written_) {
      hsrod::write_walls_vtp(prefix_ + "_walls.vtp", flow.geometry(), drag_->hydrodynamics().gap_bottom());
      walls_written_ = true;
    }
    const hsrod::FieldLattice lattice =
        hsrod::planform_lattice(flow.geometry(), spacing_, drag_->hydrodynamics().gap_bottom(), gap_layers_);
    std::vector<hsrod::WindowFlowField> windows;
    if (!rods.empty()) windows = hsrod::twoway_disturbances(*twoway, *state, rods, flow.geometry());
    hsrod::write_field_vti(name, lattice, hsrod::sample_field(flow, lattice, hydro.gap_bottom(), windows), time,
                           static_cast<long>(update->ntimestep));
    // The collection refers to the frames by name relative to its own directory.
    std::string file = name;
    const size_t slash = file.find_last_of('/');
    if (slash != std::string::npos) file = file.substr(slash + 1);
    frames_.emplace_back(time, file);
    hsrod::write_collection_pvd(prefix_ + ".pvd", frames_);
  } catch (const std::exception &e) {
    char msg[512];
    std::snprintf(msg, sizeof(msg), "fix hele_shaw/field: %s", e.what());
    error->one(FLERR, msg);
  }
}

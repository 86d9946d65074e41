/* ----------------------------------------------------------------------
   hsrod - compute rod/shape (see compute_rod_shape.h)

   compute ID group rod/shape [channel_width W] [channel_centre yc]
                              [mean_velocity U] [section S] [contacts FIX-ID]
                              [pass_x X] [clog_velocity f]
   Global array: one row per rod, columns (1-based, as thermo sees them):
     1 rod (molecule) ID, 2-4 centre of mass [m], 5-6 velocity x y [m/s],
     7 angle, eq. (1) [deg], 8 relative deflection, eq. (2) [-],
     9 lateral displacement (y_com - yc)/W [-], 10 v_x / U [-],
     11 number of spheres, 12 wall contact now (0/1), 13 wall contact
     force [N], 14 outcome: 0 en route, 1 passed without contact, 2 passed
     with contact, 3 clogged (columns 12-14 need `contacts FIX-ID`).
   Global vector: the row of the first rod.
------------------------------------------------------------------------- */

#include "compute_rod_shape.h"
#include "common/math_constants.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "keyword_parsing.h"
#include "memory.h"
#include "update.h"

#include "fix_rod_implicit.h"
#include "modify.h"
#include "rod_gather.h"

#include "rod/rod_measures.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>

using namespace LAMMPS_NS;


ComputeRodShape::ComputeRodShape(LAMMPS *instance, int &iarg, int narg, char **arg)
    : Compute(instance, iarg, narg, arg),
      mean_velocity_(0.0),
      section_size_(1),
      contacts_(nullptr),
      pass_x_(0.0),
      clog_velocity_(0.01),
      last_step_(-1) {
  pass_x_ = domain->boxhi[0];
  if (!atom->molecule_flag) error->all(FLERR, "compute rod/shape requires molecule IDs (atom_style ... molecular)");
  channel_width_ = domain->boxhi[1] - domain->boxlo[1];
  channel_centre_ = 0.5 * (domain->boxhi[1] + domain->boxlo[1]);
  for (; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg) {
      char msg[128];
      std::snprintf(msg, sizeof(msg), "Illegal compute rod/shape command: keyword %s needs a value", arg[iarg]);
      error->all(FLERR, msg);
    }
    if (strcmp(arg[iarg], "channel_width") == 0) {
      channel_width_ = parse_number(error, "compute rod/shape", arg[iarg], arg[iarg + 1]);
      if (!(channel_width_ > 0.0)) error->all(FLERR, "compute rod/shape: channel_width must be > 0 m");
    } else if (strcmp(arg[iarg], "channel_centre") == 0 || strcmp(arg[iarg], "channel_center") == 0) {
      channel_centre_ = parse_number(error, "compute rod/shape", arg[iarg], arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "mean_velocity") == 0) {
      mean_velocity_ = parse_number(error, "compute rod/shape", arg[iarg], arg[iarg + 1]);
      if (!(mean_velocity_ > 0.0)) error->all(FLERR, "compute rod/shape: mean_velocity must be > 0 m/s");
    } else if (strcmp(arg[iarg], "contacts") == 0) {
      const int f = modify->find_fix(arg[iarg + 1]);
      contacts_ = f < 0 ? nullptr : dynamic_cast<FixRodImplicit *>(modify->fix[f]);
      if (!contacts_) error->all(FLERR, "compute rod/shape: contacts needs the ID of a fix rod/implicit defined before");
    } else if (strcmp(arg[iarg], "pass_x") == 0) {
      pass_x_ = parse_number(error, "compute rod/shape", arg[iarg], arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "clog_velocity") == 0) {
      clog_velocity_ = parse_number(error, "compute rod/shape", arg[iarg], arg[iarg + 1]);
      if (!(clog_velocity_ > 0.0 && clog_velocity_ < 1.0))
        error->all(FLERR, "compute rod/shape: clog_velocity (fraction of mean_velocity) must be in (0, 1)");
    } else if (strcmp(arg[iarg], "section") == 0) {
      section_size_ = parse_integer(error, "compute rod/shape", arg[iarg], arg[iarg + 1]);
      if (section_size_ < 1) error->all(FLERR, "compute rod/shape: section (spheres per cross-section) must be >= 1");
    } else {
      char msg[256];
      std::snprintf(msg, sizeof(msg),
                    "Illegal compute rod/shape command: unknown keyword '%s' (expected channel_width, "
                    "channel_centre, mean_velocity, section, contacts, pass_x, clog_velocity)", arg[iarg]);
      error->all(FLERR, msg);
    }
  }
  find_rods();
  if (rod_ids_.empty()) error->all(FLERR, "compute rod/shape: no rods (bonded molecules) in the group");

  array_flag = 1;
  size_array_rows = static_cast<int>(rod_ids_.size());
  size_array_cols = N_COLUMNS;
  extarray = 0;
  vector_flag = 1;
  size_vector = N_COLUMNS;
  extvector = 0;
  memory->create(array, size_array_rows, size_array_cols, "rod/shape:array");
  vector = new double[N_COLUMNS];
}

ComputeRodShape::~ComputeRodShape() {
  memory->destroy(array);
  delete[] vector;
}

void ComputeRodShape::init() {
  const size_t before = rod_ids_.size();
  find_rods();
  if (rod_ids_.size() != before)
    error->all(FLERR, "compute rod/shape: the number of rods changed since the compute was defined");
}

void ComputeRodShape::find_rods() { rod_ids_ = RodGather(lmp).rod_ids(groupbit); }

void ComputeRodShape::measure() {
  if (last_step_ == update->ntimestep) return;
  last_step_ = update->ntimestep;

  // Whole rods (unwrapped positions) on every proc: rods are small and the
  // compute runs only at output steps.
  RodGather gather(lmp);
  gather.gather(groupbit, nullptr);
  auto &rods = gather.rods;

  for (size_t row = 0; row < rod_ids_.size(); row++) {
    double *out = array[row];
    std::fill(out, out + N_COLUMNS, 0.0);
    out[ROD_ID] = rod_ids_[row];
    auto it = rods.find(rod_ids_[row]);
    if (it == rods.end()) continue;
    const auto &spheres = it->second;  // sorted by ID
    double mass = 0.0, com[3] = {0, 0, 0}, vel[2] = {0, 0};
    for (const auto &s : spheres) {
      mass += s.mass;
      for (int a = 0; a < 3; a++) com[a] += s.mass * s.position[a];
      vel[0] += s.mass * s.velocity.x();
      vel[1] += s.mass * s.velocity.y();
    }
    // Section centres (spheres ordered section by section, as create_rod makes them).
    std::vector<Eigen::Vector2d> centres;
    const int nsec = static_cast<int>(spheres.size()) / section_size_;
    for (int s = 0; s < nsec; s++) {
      Eigen::Vector2d c(0, 0);
      for (int k = 0; k < section_size_; k++) c += spheres[s * section_size_ + k].position.head<2>();
      centres.push_back(c / section_size_);
    }
    out[COM_X] = com[0] / mass;
    out[COM_Y] = com[1] / mass;
    out[COM_Z] = com[2] / mass;
    out[VEL_X] = vel[0] / mass;
    out[VEL_Y] = vel[1] / mass;
    out[N_SPHERES] = static_cast<double>(spheres.size());
    if (nsec >= 2) {
      // L_Rod = N d (paper): N times the mean centre distance along the
      // rod, which the nearly inextensible bonds keep at d.
      double path = 0.0;
      for (int s = 1; s < nsec; s++) path += (centres[s] - centres[s - 1]).norm();
      const double length = path * nsec / (nsec - 1);
      out[ANGLE_DEG] = hsrod::rod_angle_eq1(centres.front(), centres.back()) * 180.0 / hsrod::kPi;
      out[DEFLECTION] = hsrod::relative_deflection_eq2(centres.front(), centres.back(), centres, length);
    }
    out[LATERAL] = (out[COM_Y] - channel_centre_) / channel_width_;
    if (mean_velocity_ > 0.0) out[VEL_RATIO] = out[VEL_X] / mean_velocity_;
    // Outcome (paper Sec. 3.5): passed (with or without wall contact on the
    // way), clogged (touching a wall and stalled before pass_x), en route.
    const RodContactRecord *record = contacts_ ? contacts_->contact_record(rod_ids_[row]) : nullptr;
    if (record) {
      out[WALL_CONTACT] = record->touching ? 1.0 : 0.0;
      out[WALL_FORCE] = record->wall_force;
    }
    const bool ever_touched = record && record->ever_touched;
    const bool stalled = mean_velocity_ > 0.0 && std::hypot(out[VEL_X], out[VEL_Y]) < clog_velocity_ * mean_velocity_;
    if (out[COM_X] > pass_x_) out[OUTCOME] = ever_touched ? PASSED_WITH_CONTACT : PASSED_WITHOUT_CONTACT;
    else if (record && record->touching && stalled) out[OUTCOME] = CLOGGED;
    else out[OUTCOME] = EN_ROUTE;
  }
}

void ComputeRodShape::compute_array() {
  invoked_array = update->ntimestep;
  measure();
}

void ComputeRodShape::compute_vector() {
  invoked_vector = update->ntimestep;
  measure();
  for (int c = 0; c < N_COLUMNS; c++) vector[c] = array[0][c];
}

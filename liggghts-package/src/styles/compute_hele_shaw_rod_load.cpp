/* ----------------------------------------------------------------------
   hsrod - compute hele_shaw/rod_load (see compute_hele_shaw_rod_load.h)

   compute ID group hele_shaw/rod_load DRAG-ID
   Global array, one row per rod of the group (by molecule ID), columns
   (1-based): 1 rod ID, 2-3 centre (centroid of the sphere centres) [m],
   4-5 hydrodynamic force F_x F_y on the rod at its current velocities [N],
   6 torque T_z about the centre [N m], 7-12 in-plane rigid resistance
   R_xx R_xy R_xw R_yy R_yw R_ww (w = rotation about z) [N s/m, N s, N m s],
   13-15 load of the rod held at rest F_x F_y T_z [N, N, N m], 16-18 free
   rigid velocity V_x V_y [m/s] Omega_z [1/s], 19 drift angle of the free
   translation against the background flow at the centre [deg], 20 free
   speed / background speed at the centre [-]. Global vector: the first rod's row.
------------------------------------------------------------------------- */

#include "compute_hele_shaw_rod_load.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include "fix_hele_shaw_drag.h"
#include "rod_assembly.h"
#include "rod_gather.h"

#include "hydro/rigid_rod_load.h"
#include "hydro/rod_hydrodynamics.h"

#include <cmath>
#include <cstdio>

using namespace LAMMPS_NS;

ComputeHeleShawRodLoad::ComputeHeleShawRodLoad(LAMMPS *instance, int &iarg, int narg, char **arg)
    : Compute(instance, iarg, narg, arg), drag_(nullptr), last_step_(-1) {
  if (iarg >= narg)
    error->all(FLERR, "Illegal compute hele_shaw/rod_load command: missing the ID of a fix hele_shaw/drag");
  drag_id_ = arg[iarg++];
  if (iarg < narg) {
    char msg[256];
    std::snprintf(msg, sizeof(msg), "Illegal compute hele_shaw/rod_load command: unexpected argument '%s'", arg[iarg]);
    error->all(FLERR, msg);
  }
  if (!atom->molecule_flag) error->all(FLERR, "compute hele_shaw/rod_load requires molecule IDs (atom_style ... molecular)");
  find_drag();
  find_rods();
  if (rod_ids_.empty()) error->all(FLERR, "compute hele_shaw/rod_load: no rods (molecules) in the group");
  array_flag = 1;
  size_array_rows = static_cast<int>(rod_ids_.size());
  size_array_cols = N_COLUMNS;
  extarray = 0;
  vector_flag = 1;
  size_vector = N_COLUMNS;
  extvector = 0;
  memory->create(array, size_array_rows, size_array_cols, "hele_shaw/rod_load:array");
  vector = new double[N_COLUMNS];
}

ComputeHeleShawRodLoad::~ComputeHeleShawRodLoad() {
  memory->destroy(array);
  delete[] vector;
}

void ComputeHeleShawRodLoad::find_drag() {
  const int f = modify->find_fix(drag_id_.c_str());
  drag_ = f < 0 ? nullptr : dynamic_cast<FixHeleShawDrag *>(modify->fix[f]);
  if (!drag_) {
    char msg[256];
    std::snprintf(msg, sizeof(msg),
                  "compute hele_shaw/rod_load: '%s' is not the ID of a fix hele_shaw/drag defined before",
                  drag_id_.c_str());
    error->all(FLERR, msg);
  }
}

void ComputeHeleShawRodLoad::find_rods() { rod_ids_ = RodGather(lmp).rod_ids(groupbit); }

void ComputeHeleShawRodLoad::init() {
  find_drag();
  last_step_ = -1;  // velocities may have been set between runs
  const size_t before = rod_ids_.size();
  find_rods();
  if (rod_ids_.size() != before)
    error->all(FLERR, "compute hele_shaw/rod_load: the number of rods changed since the compute was defined");
}

// Every processor gathers the rods and asks the drag fix's hydrodynamics for
// their loads (as the drag fix does), so all hold the same numbers; level 4
// may re-solve its window here if the rod moved since its last update.
void ComputeHeleShawRodLoad::measure() {
  if (last_step_ == update->ntimestep) return;
  last_step_ = update->ntimestep;
  RodGather gather(lmp);
  gather.gather(groupbit, nullptr);
  const hsrod::BackgroundFlow &flow = drag_->flow();
  for (size_t row = 0; row < rod_ids_.size(); row++) {
    double *out = array[row];
    std::fill(out, out + N_COLUMNS, 0.0);
    out[ROD_ID] = rod_ids_[row];
    auto it = gather.rods.find(rod_ids_[row]);
    if (it == gather.rods.end()) continue;
    const auto &spheres = it->second;
    const hsrod::RodGeometry rod = rod_geometry(drag_->hydrodynamics(), rod_ids_[row], spheres);
    const int n = rod.size();
    Eigen::VectorXd v(3 * n);
    for (int k = 0; k < n; k++) v.segment<3>(3 * k) = spheres[k].velocity;
    hsrod::RodDrag drag;
    drag_->hydrodynamics().loads(rod, drag);
    const hsrod::RigidRodLoad rigid = hsrod::rigid_rod_load(rod, drag);
    std::vector<Eigen::Vector3d> torques(n);
    for (int k = 0; k < n; k++)
      torques[k] = drag.torque(k, spheres[k].angular_velocity);
    const Eigen::Vector3d now = hsrod::rod_in_plane_load(rod, rigid.centre, drag.forces(v), torques);
    out[CENTRE_X] = rigid.centre.x();
    out[CENTRE_Y] = rigid.centre.y();
    out[FORCE_X] = now.x();
    out[FORCE_Y] = now.y();
    out[TORQUE_Z] = now.z();
    const Eigen::Matrix3d &r = rigid.resistance;
    out[R_XX] = r(0, 0);
    out[R_XY] = r(0, 1);
    out[R_XW] = r(0, 2);
    out[R_YY] = r(1, 1);
    out[R_YW] = r(1, 2);
    out[R_WW] = r(2, 2);
    out[HELD_X] = rigid.driving.x();
    out[HELD_Y] = rigid.driving.y();
    out[HELD_TORQUE] = rigid.driving.z();
    out[FREE_VX] = rigid.free_velocity.x();
    out[FREE_VY] = rigid.free_velocity.y();
    out[FREE_OMEGA] = rigid.free_velocity.z();
    out[DRIFT_DEG] = hsrod::drift_angle(rigid, flow) * 180.0 / 3.14159265358979323846;
    const double u = flow.velocity(rigid.centre.x(), rigid.centre.y()).norm();
    out[FREE_SPEED_RATIO] = u > 0.0 ? rigid.free_velocity.head<2>().norm() / u : 0.0;
  }
}

void ComputeHeleShawRodLoad::compute_array() {
  invoked_array = update->ntimestep;
  measure();
}

void ComputeHeleShawRodLoad::compute_vector() {
  invoked_vector = update->ntimestep;
  measure();
  for (int c = 0; c < N_COLUMNS; c++) vector[c] = array[0][c];
}

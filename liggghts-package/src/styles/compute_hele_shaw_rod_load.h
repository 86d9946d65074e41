/* ----------------------------------------------------------------------
   hsrod - compute hele_shaw/rod_load: per rod, the hydrodynamic force and
   torque of a fix hele_shaw/drag's model, the 3x3 in-plane resistance of
   the rod moving rigidly, its load when held, its free rigid velocity and
   drift angle in the local flow. Physics in drag-models/hydro/rigid_rod_load.h.
   Doc: doc/compute_hele_shaw_rod_load.txt
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS

ComputeStyle(hele_shaw/rod_load,ComputeHeleShawRodLoad)

#else

#ifndef LMP_COMPUTE_HELE_SHAW_ROD_LOAD_H
#define LMP_COMPUTE_HELE_SHAW_ROD_LOAD_H

#include "compute.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class ComputeHeleShawRodLoad : public Compute {
 public:
  ComputeHeleShawRodLoad(class LAMMPS *, int &, int, char **);
  ~ComputeHeleShawRodLoad();
  void init();
  void compute_array();
  void compute_vector();

  // Columns of the global array, one row per rod ordered by molecule ID
  // (0-based here, 1-based in scripts).
  enum Column {
    ROD_ID, CENTRE_X, CENTRE_Y, FORCE_X, FORCE_Y, TORQUE_Z,
    R_XX, R_XY, R_XW, R_YY, R_YW, R_WW,
    HELD_X, HELD_Y, HELD_TORQUE, FREE_VX, FREE_VY, FREE_OMEGA, DRIFT_DEG, FREE_SPEED_RATIO, N_COLUMNS
  };

 private:
  std::string drag_id_;
  class FixHeleShawDrag *drag_;
  std::vector<int> rod_ids_;
  bigint last_step_;

  void find_drag();
  void find_rods();
  void measure();
};

}  // namespace LAMMPS_NS

#endif
#endif

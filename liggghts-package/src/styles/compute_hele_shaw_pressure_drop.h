/* ----------------------------------------------------------------------
   hsrod - compute hele_shaw/pressure_drop: the pressure drop of the channel
   of a fix hele_shaw/drag between two cross-sections: the background flow's
   and the rise the hydrodynamic loads on the rods cause (reciprocal
   theorem). Physics in drag-models/flow/flow_probe.h and
   particle_pressure_drop.h. Doc: doc/compute_hele_shaw_pressure_drop.txt
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS

ComputeStyle(hele_shaw/pressure_drop,ComputeHeleShawPressureDrop)

#else

#ifndef LMP_COMPUTE_HELE_SHAW_PRESSURE_DROP_H
#define LMP_COMPUTE_HELE_SHAW_PRESSURE_DROP_H

#include "compute.h"

#include <string>

namespace LAMMPS_NS {

class ComputeHeleShawPressureDrop : public Compute {
 public:
  ComputeHeleShawPressureDrop(class LAMMPS *, int &, int, char **);
  ~ComputeHeleShawPressureDrop();
  void init();
  double compute_scalar();
  void compute_vector();

  // Entries of the global vector (0-based here, 1-based in scripts).
  enum Entry { TOTAL, BACKGROUND, RODS, FLOW_RATE, N_ENTRIES };

 private:
  std::string drag_id_;
  class FixHeleShawDrag *drag_;
  double x_up_, x_down_;  // cross-sections [m] (default: inlet and outlet planes)
  int pieces_;            // midpoint-rule pieces across the width
  double background_;     // background drop between the sections [Pa] (steady: computed once)
  bool background_done_;

  void find_drag();
};

}  // namespace LAMMPS_NS

#endif
#endif

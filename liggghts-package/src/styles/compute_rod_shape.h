/* ----------------------------------------------------------------------
   hsrod - compute rod/shape: the paper's rod measures per rod.
   Measures from drag-models/rod/rod_measures.h. Doc: doc/compute_rod_shape.txt
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS

ComputeStyle(rod/shape,ComputeRodShape)

#else

#ifndef LMP_COMPUTE_ROD_SHAPE_H
#define LMP_COMPUTE_ROD_SHAPE_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeRodShape : public Compute {
 public:
  ComputeRodShape(class LAMMPS *, int &, int, char **);
  ~ComputeRodShape();
  void init();
  void compute_vector();
  void compute_array();

  // Outcome classes of column OUTCOME (the paper's classes).
  enum Outcome { EN_ROUTE = 0, PASSED_WITHOUT_CONTACT = 1, PASSED_WITH_CONTACT = 2, CLOGGED = 3 };

  // Columns of the global array, one row per rod (ordered by molecule ID).
  enum Column {
    ROD_ID, COM_X, COM_Y, COM_Z, VEL_X, VEL_Y, ANGLE_DEG, DEFLECTION, LATERAL, VEL_RATIO, N_SPHERES,
    WALL_CONTACT, WALL_FORCE, OUTCOME, N_COLUMNS
  };

 private:
  double channel_width_;     // W [m] (default: box extent in y)
  double channel_centre_;    // y of the channel centre line [m] (default: box centre)
  double mean_velocity_;     // mean inflow velocity [m/s] (0: not given)
  int section_size_;         // spheres per cross-section
  class FixRodImplicit *contacts_;  // wall-contact history (optional)
  double pass_x_;            // a rod whose centre passed this x has passed [m]
  double clog_velocity_;     // below this fraction of U a touching rod is clogged [-]
  std::vector<int> rod_ids_; // molecule IDs of the rods in the group
  bigint last_step_;

  void find_rods();
  void measure();
};

}  // namespace LAMMPS_NS

#endif
#endif

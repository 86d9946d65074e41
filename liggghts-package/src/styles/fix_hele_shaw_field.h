/* ----------------------------------------------------------------------
   hsrod - fix hele_shaw/field: writes the background flow of a fix
   hele_shaw/drag (gap-averaged or 3-D velocity, pressure) as VTK image data
   every N steps, the planform walls as VTK polydata and a ParaView
   collection file; at level 4 with the flow disturbed by each rod in its
   window (drag-models/hydro/twoway_disturbance.h). Physics and file formats in
   drag-models/flow/flow_field_vtk.h. Doc: doc/fix_hele_shaw_field.txt
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

FixStyle(hele_shaw/field,FixHeleShawField)

#else

#ifndef LMP_FIX_HELE_SHAW_FIELD_H
#define LMP_FIX_HELE_SHAW_FIELD_H

#include "fix.h"

#include <string>
#include <utility>
#include <vector>

namespace hsrod {
struct RodLoadSample;
}

namespace LAMMPS_NS {

class FixHeleShawField : public Fix {
 public:
  FixHeleShawField(class LAMMPS *, int, char **);
  int setmask();
  void init();
  void setup(int);
  void end_of_step();

 private:
  std::string drag_id_;
  class FixHeleShawDrag *drag_;
  std::string prefix_;     // files: <prefix>_<step>.vti, <prefix>.pvd, <prefix>_walls.vtp
  double spacing_;         // lattice spacing [m] (0: automatic)
  int gap_layers_;         // 0: mid-plane 2-D image; > 0: 3-D image with gap_layers + 1 layers
  bool walls_;             // write the walls file
  bool disturbed_;         // level 4: add the rods' window disturbances
  bool walls_written_;
  bigint last_written_;
  std::vector<std::pair<double, std::string>> frames_;  // (time [s], file) for the .pvd

  void find_drag();
  void write_frame();
  std::vector<hsrod::RodLoadSample> gather_rod_loads();
};

}  // namespace LAMMPS_NS

#endif
#endif

/* ----------------------------------------------------------------------
   hsrod - create_rod command: a straight rod of bonded spheres.
   Geometry from drag-models/rod/rod_layout.h. Doc: doc/create_rod.txt
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS

CommandStyle(create_rod,CreateRod)

#else

#ifndef LMP_CREATE_ROD_H
#define LMP_CREATE_ROD_H

#include "pointers.h"

namespace LAMMPS_NS {

class CreateRod : protected Pointers {
 public:
  CreateRod(class LAMMPS *);
  void command(int, char **);
};

}  // namespace LAMMPS_NS

#endif
#endif

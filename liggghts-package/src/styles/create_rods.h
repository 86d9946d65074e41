/* ----------------------------------------------------------------------
   hsrod - create_rods command: a suspension of straight rods seeded in the
   planform of a fix hele_shaw/drag without overlaps (random or lattice),
   each made as create_rod makes one. Seeding: drag-models/geometry/
   rod_seeding.h. Doc: doc/create_rods.txt
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS

CommandStyle(create_rods,CreateRods)

#else

#ifndef LMP_CREATE_RODS_H
#define LMP_CREATE_RODS_H

#include "pointers.h"

namespace LAMMPS_NS {

class CreateRods : protected Pointers {
 public:
  CreateRods(class LAMMPS *);
  void command(int, char **);
};

}  // namespace LAMMPS_NS

#endif
#endif

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

  // Several rods in one command (create_rods): add() each rod's spheres and
  // bonds with the IDs in `next` (advanced past them; report: the rod's
  // line on screen), then finish() once (atom map, special lists).
  struct NextRodIds {
    int tag = 1, mol = 1;  // the next atom ID and the next free molecule ID
  };
  NextRodIds next_ids();  // after the largest existing ones
  void add(int narg, char **arg, NextRodIds &next, bool report);
  void finish();
};

}  // namespace LAMMPS_NS

#endif
#endif

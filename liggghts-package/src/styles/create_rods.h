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

#include "create_rod.h"

#include "geometry/rod_seeding.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixHeleShawDrag;

class CreateRods : protected Pointers {
 public:
  CreateRods(class LAMMPS *);
  void command(int, char **);
};

// The rods' keywords, shared by create_rods and fix rod/inflow (the same
// rods, seeded once or during the run).
struct SeededRodsSpec {
  hsrod::RodSeedingRequest seeding;
  std::string drag_id;
  int type = 0;          // atom type
  double density = 0.0;  // [kg/m^3]
  int bond_type = 1;
  bool have_spheres = false, have_diameter = false, have_type = false, have_density = false;
};
// Reads the rod keyword arg[iarg] and its values into `spec` (`style` names
// the command in errors); returns the words read, 0 if arg[iarg] is not one.
int parse_seeded_rods_keyword(Error *error, const char *style, int narg, char **arg, int iarg, SeededRodsSpec &spec);
void check_seeded_rods_required(Error *error, const char *style, const SeededRodsSpec &spec);
// The fix hele_shaw/drag named by spec.drag_id (error->all if it is none).
FixHeleShawDrag *seeding_drag_fix(LAMMPS *lmp, const char *style, const SeededRodsSpec &spec);
// Every atom in the box as a point obstacle of its diameter, from all ranks.
std::vector<hsrod::RodObstacle> atoms_as_obstacles(LAMMPS *lmp);
// The rods made as create_rod makes them, IDs from `next` on, at height z
// [m]; the caller calls creator.finish() after the last.
void make_seeded_rods(CreateRod &creator, CreateRod::NextRodIds &next, const SeededRodsSpec &spec,
                      const std::vector<hsrod::SeededRod> &rods, double z);

}  // namespace LAMMPS_NS

#endif
#endif

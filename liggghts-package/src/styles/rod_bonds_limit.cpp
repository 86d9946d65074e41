/* ----------------------------------------------------------------------
   hsrod - the explicit stability limit of a script's rod bonds (see
   support/rod_bonds_limit.h), read from its fix rod/bonds.
------------------------------------------------------------------------- */

#include "rod_bonds_limit.h"

#include "fix_rod_bonds.h"

#include "lammps.h"
#include "modify.h"

#include <cstring>

using namespace LAMMPS_NS;

double hsrod::explicit_bond_limit(LAMMPS *lmp) {
  FixRodBonds *bonds = nullptr;
  for (int i = 0; i < lmp->modify->nfix; ++i)
    if (std::strcmp(lmp->modify->fix[i]->style, "rod/bonds") == 0) bonds = static_cast<FixRodBonds *>(lmp->modify->fix[i]);
  return bonds ? bonds->explicit_bond_limit() : 0.0;
}

/* ----------------------------------------------------------------------
   hsrod - the explicit stability limit of a script's rod bonds, for code
   that must not include the style's header (the screening report);
   implemented beside fix rod/bonds (styles/rod_bonds_limit.cpp).
------------------------------------------------------------------------- */

#ifndef HSROD_ROD_BONDS_LIMIT_H
#define HSROD_ROD_BONDS_LIMIT_H

namespace LAMMPS_NS {
class LAMMPS;
}

namespace hsrod {

// Explicit stability limit [s] of the bonds of the script's (last) fix
// rod/bonds, bond damping included; 0 without a fix rod/bonds or before
// its limits are known (no run yet).
double explicit_bond_limit(LAMMPS_NS::LAMMPS *lmp);

}  // namespace hsrod

#endif

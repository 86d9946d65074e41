/* ----------------------------------------------------------------------
   hsrod - fix couple/cfd/torque/implicit: the rotational half of LIGGGHTS'
   fix couple/cfd/force/implicit.

   Debian's LIGGGHTS 3.8 fix couple/cfd/force/implicit registers and pulls
   the per-atom vector "KslRotation" from the CFD side but applies only the
   translational Ksl (u_f - v). This fix adds, at every DEM step,
       T_i += - KslRotation_i (componentwise) omega_i              [N m]
   so that a CFD code handing over hdtorque = T^n + Krot omega^n gets the
   spin response T^n - Krot (omega - omega^n) integrated at the DEM step
   (calibration/core/momentum_exchange.h). Requires fix
   couple/cfd/force/implicit (which owns KslRotation). Doc:
   liggghts-package/doc/fix_cfd_torque_implicit.txt
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

FixStyle(couple/cfd/torque/implicit,FixCfdTorqueImplicit)

#else

#ifndef LMP_FIX_CFD_TORQUE_IMPLICIT_H
#define LMP_FIX_CFD_TORQUE_IMPLICIT_H

#include "fix.h"

namespace LAMMPS_NS {

class FixCfdTorqueImplicit : public Fix {
 public:
  FixCfdTorqueImplicit(class LAMMPS *, int, char **);
  int setmask();
  void init();
  void setup(int);
  void post_force(int);

 private:
  class Fix *krot_;  // the property/atom "KslRotation" [kg m^2/s]
};

}  // namespace LAMMPS_NS

#endif
#endif

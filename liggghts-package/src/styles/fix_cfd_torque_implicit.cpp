/* ----------------------------------------------------------------------
   hsrod - fix couple/cfd/torque/implicit (see fix_cfd_torque_implicit.h).
------------------------------------------------------------------------- */

#include "fix_cfd_torque_implicit.h"

#include "atom.h"
#include "error.h"
#include "modify.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

FixCfdTorqueImplicit::FixCfdTorqueImplicit(LAMMPS *instance, int narg, char **arg)
    : Fix(instance, narg, arg), krot_(nullptr) {
  if (narg != 3) error->all(FLERR, "Illegal fix couple/cfd/torque/implicit command: no arguments");
  if (!atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, "fix couple/cfd/torque/implicit needs atoms with omega and torque (atom_style granular)");
}

int FixCfdTorqueImplicit::setmask() { return POST_FORCE; }

void FixCfdTorqueImplicit::init() {
  krot_ = modify->find_fix_property("KslRotation", "property/atom", "vector", 0, 0, style, false);
  if (!krot_)
    error->all(FLERR, "fix couple/cfd/torque/implicit needs fix couple/cfd/force/implicit "
                      "(per-atom KslRotation) defined before it");
}

void FixCfdTorqueImplicit::setup(int vflag) { post_force(vflag); }

void FixCfdTorqueImplicit::post_force(int) {
  double **krot = krot_->array_atom;  // [kg m^2/s] per axis
  double **omega = atom->omega;       // [rad/s]
  double **torque = atom->torque;     // [N m]
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    for (int k = 0; k < 3; ++k) torque[i][k] -= krot[i][k] * omega[i][k];
  }
}

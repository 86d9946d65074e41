/* ----------------------------------------------------------------------
   hsrod - what a style that keeps state per rod (molecule ID) is told when
   whole rods leave the run (fix rod/outflow deletes them at the outlet).

   A style that keeps per-rod records derives from RodRemovalListener; the
   remover finds every such fix in modify->fix and tells it, on every
   processor, the same sorted list of molecule IDs just before their atoms
   are deleted. The listener drops what it keeps for them, so that a rod
   that is gone is not mistaken for a rod that lost atoms, and keeps what is
   a result (an outcome recorded before the removal).
------------------------------------------------------------------------- */

#ifndef LMP_HSROD_ROD_REMOVAL_H
#define LMP_HSROD_ROD_REMOVAL_H

#include <vector>

namespace LAMMPS_NS {

class RodRemovalListener {
 public:
  virtual ~RodRemovalListener() = default;
  // Rods (molecule IDs, sorted, identical on every processor) whose atoms
  // are deleted right after this call.
  virtual void forget_rods(const std::vector<int> &molecules) = 0;
};

}  // namespace LAMMPS_NS

#endif

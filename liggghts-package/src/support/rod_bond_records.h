/* ----------------------------------------------------------------------
   hsrod - what a rod gather needs from the bond fix: per local atom its
   orientation and the rest states of the bonds it stores. fix rod/bonds
   implements it; rod_gather reads it (this header keeps the two from
   including each other).
------------------------------------------------------------------------- */

#ifndef HSROD_ROD_BOND_RECORDS_H
#define HSROD_ROD_BOND_RECORDS_H

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace LAMMPS_NS {

struct GatheredBond {
  int partner_tag;
  Eigen::Vector3d rest_vector;          // in the owner's body frame [m]
  Eigen::Quaterniond rest_rotation;     // q_owner^-1 q_partner at rest
};

class RodBondRecords {
 public:
  virtual ~RodBondRecords() = default;
  // Body -> lab orientation of local atom i.
  virtual Eigen::Quaterniond orientation(int i) const = 0;
  // Rest states of the bonds stored on local atom i (partner tag, rest
  // data), into `out` (cleared first; its memory is reused: a gather runs
  // every step).
  virtual void rest_states(int i, std::vector<GatheredBond> &out) const = 0;
};

}  // namespace LAMMPS_NS

#endif

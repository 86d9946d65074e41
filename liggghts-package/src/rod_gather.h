/* ----------------------------------------------------------------------
   hsrod - gathers whole rods (all spheres of each molecule in a group) on
   every processor, for the styles that need a rod at once (shape measures,
   non-local drag, the implicit rod step). Every proc receives the same data
   in the same order, so work done on it is identical on all procs and a
   run on N ranks matches a serial one.
------------------------------------------------------------------------- */

#ifndef HSROD_ROD_GATHER_H
#define HSROD_ROD_GATHER_H

#include "pointers.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <map>
#include <vector>

namespace LAMMPS_NS {

class FixRodBonds;

struct GatheredBond {
  int partner_tag;
  Eigen::Vector3d rest_vector;          // in the owner's body frame [m]
  Eigen::Quaterniond rest_rotation;     // q_owner^-1 q_partner at rest
};

struct GatheredSphere {
  int tag = 0, molecule = 0;
  Eigen::Vector3d position;             // unwrapped [m]
  Eigen::Vector3d velocity, angular_velocity;  // [m/s], [rad/s]
  Eigen::Vector3d force, torque;        // as currently accumulated in f, torque [N], [N m]
  double radius = 0.0, mass = 0.0;      // [m], [kg]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  std::vector<GatheredBond> bonds;      // bonds stored on this sphere (with `bonds` fix only)
};

class RodGather : protected Pointers {
 public:
  explicit RodGather(class LAMMPS *lmp) : Pointers(lmp) {}
  // Gathers the group's spheres; `bonds` (may be null) adds orientations and
  // bond rest states. Rods are keyed by molecule ID, spheres sorted by tag.
  void gather(int groupbit, FixRodBonds *bonds);
  std::map<int, std::vector<GatheredSphere>> rods;
};

}  // namespace LAMMPS_NS

#endif

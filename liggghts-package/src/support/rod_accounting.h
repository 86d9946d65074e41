/* ----------------------------------------------------------------------
   hsrod - whole-rod accounting for fix rod/implicit:
   rods are moved, measured and lost whole, never in part.
   - RodCensus: the number of spheres of each rod (molecule) as first seen;
     a rod with fewer spheres later (LIGGGHTS dropped atoms outside the box,
     delete_atoms, ...) is reported, so that a partial rod is never moved.
   - leaving_face: the box face a rod's step would carry a sphere centre
     through (non-periodic directions), so that the integrator can hold the
     rod at the boundary instead of letting LIGGGHTS lose its spheres one by
     one as it leaves; fraction_inside_box: how much of such a step keeps
     every centre inside, so the rod is held where its leading sphere
     reaches the face (the exit, independent of the step size).
   - first_rod_overlap: two rods whose spheres overlap, for the refusal of
     rod-rod contact when no pair style handles it.
   No LIGGGHTS state: plain data in, plain data out.
------------------------------------------------------------------------- */

#ifndef HSROD_ROD_ACCOUNTING_H
#define HSROD_ROD_ACCOUNTING_H

#include "rod_gather.h"

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class RodCensus {
 public:
  // Records new rods (and rods that grew); returns "" if every known rod is
  // whole in `rods`, else a description of the first one that is not
  // ("rod 3 has 7 of its 10 spheres" / "rod 3 (10 spheres) is gone").
  std::string check(const std::map<int, std::vector<GatheredSphere>> &rods);
  // A rod removed whole (fix rod/outflow): no longer expected.
  void forget(int molecule) { spheres_by_rod_.erase(molecule); }

 private:
  std::map<int, int> spheres_by_rod_;  // molecule ID -> spheres when first seen (or most since)
};

// Index 0..5 (-x, +x, -y, +y, -z, +z) of the first box face some sphere
// centre in `positions` lies beyond, in a non-periodic direction, or -1.
int leaving_face(const std::vector<Eigen::Vector3d> &positions, const double *boxlo, const double *boxhi,
                 const int *periodic);
const char *face_name(int face);  // "-x", "+x", ...

// The largest s in [0, 1] for which every centre before[k] + s (after[k] -
// before[k]) lies inside the box, at least 1e-9 of its extent from a face,
// in the non-periodic directions (1 if the whole step stays inside;
// `before` must be inside) [-].
double fraction_inside_box(const std::vector<Eigen::Vector3d> &before, const std::vector<Eigen::Vector3d> &after,
                           const double *boxlo, const double *boxhi, const int *periodic);

// The first pair of different rods with overlapping spheres: rod IDs and
// the smallest centre distance over the sum of radii; rods = {-1, -1} if none.
struct RodOverlap {
  int rod_a = -1, rod_b = -1;
  double distance_over_contact = 0.0;  // |x_i - x_j| / (r_i + r_j) [-]
};
RodOverlap first_rod_overlap(const std::map<int, std::vector<GatheredSphere>> &rods);

}  // namespace LAMMPS_NS

#endif

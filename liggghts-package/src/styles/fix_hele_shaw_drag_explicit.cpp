/* ----------------------------------------------------------------------
   hsrod - fix hele_shaw/drag (see fix_hele_shaw_drag.h): the explicit path
   (no fix rod/implicit applies the drag): F = driving - R v and
   T = driving_torque - r omega added to every sphere each step. Rods the
   model couples hydrodynamically (levels 3-4: spheres of different rods
   within its interaction reach, hydro/hydrodynamic_model.h) are evaluated
   together, as fix rod/implicit steps them (dynamics/rod_cluster.h), so
   that one rod's obstruction shields or drives the other; a rod alone, and
   every rod at levels 1-2, is evaluated by itself as before.
------------------------------------------------------------------------- */

#include "fix_hele_shaw_drag.h"

#include "atom.h"
#include "rod_assembly.h"
#include "rod_gather.h"

#include "dynamics/rod_cluster.h"
#include "hydro/rod_hydrodynamics.h"

#include <mpi.h>

#include <vector>

using namespace LAMMPS_NS;

void FixHeleShawDrag::post_force(int) {
  if (applied_by_integrator_) return;
  force_flag_ = 0;
  RodGather gather(lmp);
  gather.gather(groupbit, nullptr);
  std::vector<int> molecules;
  std::vector<std::vector<Eigen::Vector3d>> positions;
  for (const auto &rod : gather.rods) {
    molecules.push_back(rod.first);
    positions.emplace_back();
    for (const GatheredSphere &s : rod.second) positions.back().push_back(s.position);
  }
  const double reach = hydro_->interaction_reach();
  std::vector<std::vector<int>> clusters;
  if (reach > 0.0 && molecules.size() > 1) clusters = hsrod::rod_clusters(positions, reach);
  else
    for (std::size_t k = 0; k < molecules.size(); ++k) clusters.push_back({static_cast<int>(k)});

  double total[3] = {0, 0, 0};
  std::vector<hsrod::RodGeometry> geometries;
  std::vector<const GatheredSphere *> spheres;
  for (const std::vector<int> &cluster : clusters) {
    geometries.clear();
    spheres.clear();
    for (int k : cluster) {
      const std::vector<GatheredSphere> &rod = gather.rods.at(molecules[k]);
      geometries.push_back(rod_geometry(*hydro_, molecules[k], rod));
      for (const GatheredSphere &s : rod) spheres.push_back(&s);
    }
    const int n = static_cast<int>(spheres.size());
    Eigen::VectorXd v(3 * n);
    for (int k = 0; k < n; k++) v.segment<3>(3 * k) = spheres[k]->velocity;
    hsrod::RodDrag drag;
    if (geometries.size() == 1) hydro_->loads(geometries.front(), drag);
    else hydro_->loads(geometries, drag);
    const Eigen::VectorXd forces = drag.forces(v);
    for (int k = 0; k < n; k++) {
      const int i = atom->map(spheres[k]->tag);
      if (i < 0 || i >= atom->nlocal) continue;
      const Eigen::Vector3d torque = drag.torque(k, spheres[k]->angular_velocity);
      const Eigen::Vector3d sphere_force = forces.segment<3>(3 * k);  // [N]
      for (int a = 0; a < 3; a++) {
        atom->f[i][a] += sphere_force[a];
        atom->torque[i][a] += torque[a];
        total[a] += sphere_force[a];
      }
      store_loads(i, drag.driving_force[k], sphere_force, torque);
    }
  }
  MPI_Allreduce(total, total_force_, 3, MPI_DOUBLE, MPI_SUM, world);
}

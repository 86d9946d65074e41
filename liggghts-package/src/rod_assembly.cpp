#include "rod_assembly.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

using namespace LAMMPS_NS;

hsrod::RodGeometry LAMMPS_NS::rod_geometry(const hsrod::RodHydrodynamics &hydro, int molecule,
                                           const std::vector<GatheredSphere> &spheres, double sphere_diameter) {
  std::vector<Eigen::Vector3d> positions;
  positions.reserve(spheres.size());
  for (const auto &s : spheres) positions.push_back(s.position);
  const double d = sphere_diameter > 0.0 ? sphere_diameter : 2.0 * spheres.front().radius;
  return hydro.rod_geometry(molecule, std::move(positions), d);
}

hsrod::OverdampedRod LAMMPS_NS::overdamped_rod(const std::vector<GatheredSphere> &spheres,
                                               const hsrod::RodBondSet &bonds) {
  const int n = static_cast<int>(spheres.size());
  std::map<int, int> index;
  for (int k = 0; k < n; k++) index[spheres[k].tag] = k;

  hsrod::OverdampedRod rod;
  for (const auto &s : spheres) {
    rod.positions.push_back(s.position);
    rod.orientations.push_back(s.orientation);
    rod.radii.push_back(s.radius);
    rod.external_forces.push_back(s.force);
    rod.external_torques.push_back(s.torque);
  }
  std::set<std::pair<int, int>> seen;
  for (int k = 0; k < n; k++) {
    for (const GatheredBond &b : spheres[k].bonds) {
      auto partner = index.find(b.partner_tag);
      if (partner == index.end()) continue;  // bonded to another group: not this rod
      const auto key = std::make_pair(std::min(spheres[k].tag, b.partner_tag), std::max(spheres[k].tag, b.partner_tag));
      if (!seen.insert(key).second) continue;  // newton_bond off stores bonds twice
      hsrod::RodBond bond;
      bond.i = k;
      bond.j = partner->second;
      bond.rest.rest_vector_in_frame_i = b.rest_vector;
      bond.rest.rest_relative_rotation = b.rest_rotation;
      bond.stiffness = bonds.stiffness(spheres[k].radius, spheres[bond.j].radius, bond.rest.rest_length());
      rod.bonds.push_back(bond);
    }
  }
  return rod;
}

#include "rod_assembly.h"

#include <algorithm>
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

void LAMMPS_NS::update_rod_geometry(const hsrod::RodHydrodynamics &hydro, int molecule,
                                    const std::vector<GatheredSphere> &spheres, hsrod::RodGeometry &geometry) {
  std::vector<Eigen::Vector3d> positions = std::move(geometry.positions);
  positions.resize(spheres.size());
  for (std::size_t k = 0; k < spheres.size(); k++) positions[k] = spheres[k].position;
  geometry = hydro.rod_geometry(molecule, std::move(positions), 2.0 * spheres.front().radius);
}

hsrod::OverdampedRod LAMMPS_NS::overdamped_rod(const std::vector<GatheredSphere> &spheres,
                                               const hsrod::RodBondSet &bonds) {
  hsrod::OverdampedRod rod;
  update_overdamped_rod(spheres, bonds, rod);
  return rod;
}

namespace {

bool same_bond_set(const hsrod::RodBondSet &a, const hsrod::RodBondSet &b) {
  return a.youngs_modulus == b.youngs_modulus && a.poisson_ratio == b.poisson_ratio &&
         a.damping_ratio == b.damping_ratio && a.bond_radius_ratio == b.bond_radius_ratio;
}

// Both public forms: `cache` null rebuilds every stiffness.
void assemble_overdamped_rod(const std::vector<GatheredSphere> &spheres, const hsrod::RodBondSet &bonds,
                             hsrod::OverdampedRod &rod, BondStiffnessCache *cache) {
  const int n = static_cast<int>(spheres.size());
  rod.positions.resize(n);
  rod.orientations.resize(n);
  rod.radii.resize(n);
  rod.external_forces.resize(n);
  rod.external_torques.resize(n);
  for (int k = 0; k < n; k++) {
    const GatheredSphere &s = spheres[k];
    rod.positions[k] = s.position;
    rod.orientations[k] = s.orientation;
    rod.radii[k] = s.radius;
    rod.external_forces[k] = s.force;
    rod.external_torques[k] = s.torque;
  }
  // Spheres come sorted by tag (rod_gather.h): a partner's index is the
  // next or previous sphere's in a chain, else found by bisection.
  const auto index_of = [&spheres, n](int tag, int near) {
    if (near + 1 < n && spheres[near + 1].tag == tag) return near + 1;
    if (near > 0 && spheres[near - 1].tag == tag) return near - 1;
    const auto it = std::lower_bound(spheres.begin(), spheres.end(), tag,
                                     [](const GatheredSphere &s, int t) { return s.tag < t; });
    return it != spheres.end() && it->tag == tag ? static_cast<int>(it - spheres.begin()) : -1;
  };
  const auto stores_bond_to = [](const GatheredSphere &s, int tag, std::size_t before) {
    for (std::size_t r = 0; r < before && r < s.bonds.size(); r++)
      if (s.bonds[r].partner_tag == tag) return true;
    return false;
  };
  rod.bonds.clear();
  const bool cache_valid = cache && same_bond_set(cache->bond_set, bonds);
  if (cache && !cache_valid) {
    cache->bond_set = bonds;
    cache->entries.clear();
  }
  for (int k = 0; k < n; k++) {
    const std::vector<GatheredBond> &stored = spheres[k].bonds;
    for (std::size_t r = 0; r < stored.size(); r++) {
      const GatheredBond &b = stored[r];
      const int partner = index_of(b.partner_tag, k);
      if (partner < 0) continue;  // bonded to another group: not this rod
      // A pair counts once (newton_bond off stores a bond on both spheres):
      // where it is first met in sphere order, then record order.
      if (stores_bond_to(spheres[k], b.partner_tag, r)) continue;
      if (partner < k && stores_bond_to(spheres[partner], spheres[k].tag, spheres[partner].bonds.size())) continue;
      hsrod::RodBond bond;
      bond.i = k;
      bond.j = partner;
      bond.rest.rest_vector_in_frame_i = b.rest_vector;
      bond.rest.rest_relative_rotation = b.rest_rotation;
      const double radius_i = spheres[k].radius, radius_j = spheres[bond.j].radius;
      const double rest_length = bond.rest.rest_length();
      const std::size_t m = rod.bonds.size();
      if (cache && m < cache->entries.size() && cache->entries[m].radius_i == radius_i &&
          cache->entries[m].radius_j == radius_j && cache->entries[m].rest_length == rest_length) {
        bond.stiffness = cache->entries[m].stiffness;
      } else {
        bond.stiffness = bonds.stiffness(radius_i, radius_j, rest_length);
        if (cache) {
          if (cache->entries.size() <= m) cache->entries.resize(m + 1);
          cache->entries[m] = {radius_i, radius_j, rest_length, bond.stiffness};
        }
      }
      rod.bonds.push_back(bond);
    }
  }
}

}  // namespace

void LAMMPS_NS::update_overdamped_rod(const std::vector<GatheredSphere> &spheres, const hsrod::RodBondSet &bonds,
                                      hsrod::OverdampedRod &rod) {
  assemble_overdamped_rod(spheres, bonds, rod, nullptr);
}

void LAMMPS_NS::update_overdamped_rod(const std::vector<GatheredSphere> &spheres, const hsrod::RodBondSet &bonds,
                                      hsrod::OverdampedRod &rod, BondStiffnessCache &cache) {
  assemble_overdamped_rod(spheres, bonds, rod, &cache);
}

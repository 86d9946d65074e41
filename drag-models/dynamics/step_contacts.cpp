// The contacts of a step: spheres on the walls and non-bonded spheres
// touching each other, with their Hertz stiffness and friction secants.
#include "dynamics/overdamped_rod_step_internal.h"

#include <algorithm>
#include <tuple>

namespace hsrod {

void OverdampedRodSolver::Workspace::find_contacts(const OverdampedRod& rod, const ChannelGeometry* geometry,
                                                   const WallContactParameters* walls, OverdampedStepResult& result) {
  wall_contacts.clear();
  pair_contacts.clear();
  const int n = rod.size();
  if (geometry && walls) {
    for (int i = 0; i < n; ++i) {
      const WallContact c = wall_contact(*geometry, *walls, rod.positions[i], rod.radii[i]);
      if (!c.touching) continue;
      result.wall_contact = true;
      result.wall_force += c.force.norm();
      if (static_cast<int>(result.sphere_wall_force.size()) == n) result.sphere_wall_force[i] += c.force.norm();
      SphereWallContact contact{i, c.force, c.stiffness, false, Matrix6d::Zero(), Vector6d::Zero(), c.points, c.point,
                                {},  {}};
      // Wall friction: its secant c G^T G (dynamics/wall_contact.h) about
      // the previous velocities (or, when step() repeats the step, about the
      // slip it is given, with the given correction loads), on the sphere's
      // own 6x6 block.
      if (walls->friction_coefficient > 0.0) {
        const Vector6d u0 = previous_velocity(rod, i);
        contact.rubbing = true;
        const std::size_t m = wall_contacts.size();
        for (int k = 0; k < c.points; ++k) {
          const std::size_t slot = 3 * m + k;
          contact.about[k] = slot < given_slip.size() ? given_slip[slot] : wall_slip(c.point[k], rod.radii[i], u0);
          contact.secant[k] =
              walls->friction_coefficient * c.point[k].normal_force / std::max(contact.about[k].norm(), walls->slip_velocity);
          contact.friction += wall_friction_resistance_at_slip(c.point[k], rod.radii[i], walls->friction_coefficient,
                                                               walls->slip_velocity, contact.about[k].norm());
        }
        if (m < given_load.size()) contact.friction_load = given_load[m];
      }
      wall_contacts.push_back(contact);
    }
  }
  // Non-bonded spheres touching each other: a folding rod, or two rods of
  // a cluster stepped together.
  if (walls && sphere_pair_search_on(rod, *walls)) {
    double largest_radius = 0.0;
    for (double r : rod.radii) largest_radius = std::max(largest_radius, r);
    find_nearby_pairs(rod.positions, 2.0 * largest_radius, cells, candidates, false);
    for (const auto& pair : candidates) {
      const int i = pair.first, j = pair.second;
      if (bonded(i, j) || !sphere_pair_contact_on(rod, *walls, i, j)) continue;
      const WallContact c = sphere_contact(*walls, rod.positions[i], rod.radii[i], rod.positions[j], rod.radii[j]);
      if (!c.touching) continue;
      result.self_contact = true;
      if (!rod.same_rod(i, j)) {
        result.rod_contact = true;
        result.rod_contact_force += c.point[0].normal_force;
      }
      SpherePairContact contact{i, j, c.force, c.stiffness, false, Matrix12d::Zero()};
      if (walls->rod_friction_coefficient > 0.0) {
        Vector12d u0;
        u0 << previous_velocity(rod, i), previous_velocity(rod, j);
        contact.rubbing = true;
        contact.friction = sphere_friction_resistance(c.point[0], rod.radii[i], rod.radii[j],
                                                      walls->rod_friction_coefficient, walls->slip_velocity, u0);
      }
      pair_contacts.push_back(contact);
    }
    // Summed in the order of the sphere indices, independent of the cells.
    std::sort(pair_contacts.begin(), pair_contacts.end(),
              [](const SpherePairContact& a, const SpherePairContact& b) {
                return std::tie(a.i, a.j) < std::tie(b.i, b.j);
              });
  }
}

}  // namespace hsrod

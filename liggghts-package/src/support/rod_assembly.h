/* ----------------------------------------------------------------------
   hsrod - gathered rods (rod_gather.h) into the structures of drag-models:
   the one gather-to-geometry function for the hydrodynamics, and the rod
   of the implicit step with its bonds from the bond set.
------------------------------------------------------------------------- */

#ifndef HSROD_ROD_ASSEMBLY_H
#define HSROD_ROD_ASSEMBLY_H

#include "rod_gather.h"

#include "dynamics/overdamped_rod_step.h"
#include "hydro/rod_hydrodynamics.h"
#include "rod/rod_bond_set.h"

#include <vector>

namespace LAMMPS_NS {

// Rod `molecule` as the hydrodynamic models see it: centres in tag order, the
// scene's section size, diameter `sphere_diameter` [m] (<= 0: the first sphere's).
hsrod::RodGeometry rod_geometry(const hsrod::RodHydrodynamics &hydro, int molecule,
                                const std::vector<GatheredSphere> &spheres, double sphere_diameter = 0.0);

// The same into `geometry`, reusing its memory (diameter: the first sphere's).
void update_rod_geometry(const hsrod::RodHydrodynamics &hydro, int molecule,
                         const std::vector<GatheredSphere> &spheres, hsrod::RodGeometry &geometry);

// The rod of the implicit step: positions, orientations, radii, the forces
// and torques accumulated so far, and one bond per bonded pair of the rod
// (a bond to a sphere outside the rod is skipped; a bond stored twice with
// newton_bond off counts once) with its stiffness from `bonds`.
hsrod::OverdampedRod overdamped_rod(const std::vector<GatheredSphere> &spheres, const hsrod::RodBondSet &bonds);
// The same into `rod`, reusing its memory (a rod step rebuilds it every step).
// Velocities are left as they are.
void update_overdamped_rod(const std::vector<GatheredSphere> &spheres, const hsrod::RodBondSet &bonds,
                           hsrod::OverdampedRod &rod);

// The inputs of each bond's stiffness at the last update, in the order of the
// rod's bonds: a bond whose radii [m], rest length [m] and bond set are the
// same as at the same place last time keeps its stiffness (the same numbers:
// the stiffness is a function of these alone) instead of recomputing it.
struct BondStiffnessCache {
  struct Entry {
    double radius_i = 0.0, radius_j = 0.0, rest_length = 0.0;  // [m]
    hsrod::BeamBondStiffness stiffness;
  };
  hsrod::RodBondSet bond_set;
  std::vector<Entry> entries;
};
// update_overdamped_rod with the stiffnesses taken from `cache` where their
// inputs are unchanged (a rod step whose topology and radii stay the same).
void update_overdamped_rod(const std::vector<GatheredSphere> &spheres, const hsrod::RodBondSet &bonds,
                           hsrod::OverdampedRod &rod, BondStiffnessCache &cache);

}  // namespace LAMMPS_NS

#endif

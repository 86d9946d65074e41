// Level 4 with the 3-D near field of nearby spheres (hydro/near_field_coupling.h).
//
// The window (twoway_window_model.h) couples the spheres through the
// depth-averaged Brinkman flow between their footprints, which, like level
// 3's Green's function, misses the 3-D interaction of spheres closer than a
// few gap heights. The correction acts on the window model's load only, so
// the window itself (grid, size, updates) is untouched: the in-plane
// obstruction resistance R_o = R - zeta_f I of the window's load is turned
// into its mobility M = R_o^-1 (diagonal blocks: the sphere's own 1/zeta_o,
// off-diagonal blocks: c times the window's mobility between footprints),
// each pair block within a few H is blended into the 3-D near field, and
//     R_o' = M'^-1,   driving' = R_o^D' M driving
// (the driving is c R_o <u_bg>: the same background flow seen through the
// new coupling; R_o^D' = M^D'^-1 with M^D' blended with the driving's own
// near-field parameters, NearFieldAtBeta). A lone sphere, and pairs beyond a few blend lengths, keep
// the window's load exactly.
//
// Approximation: the window's wall reflections between two spheres within
// the blend region are replaced by the slit's (the blend), those of walls
// farther away stay in the off-diagonal blocks outside it; the stored
// resistance in the level-4 state (used by the disturbed-flow output,
// twoway_disturbance.h) is the window's, without the near field.
#pragma once

#include "hydro/twoway_window_model.h"
#include "hydro/near_field_coupling.h"

namespace hsrod {

// Adds the near field to a load F = d - R v of obstruction form (levels 3-4):
// `film_friction` zeta_f [N s/m] is the part of R's diagonal that is not
// coupled, `obstruction_friction` zeta_o [N s/m] the coupled part of a lone sphere's. The in-plane components of `drag` (coupled) are replaced; z and
// rotation are kept. No-op for a lone sphere or an inactive coupling.
void add_near_field(const RodGeometry& rod, const HydrodynamicParameters& parameters, double film_friction,
                    double obstruction_friction, const NearFieldAtBeta& coupling, RodDrag& drag);

// The registered `twoway` model: the window model plus the near field.
class NearFieldTwoWayModel : public TwoWayWindowModel {
 public:
  NearFieldTwoWayModel(const HydrodynamicParameters& parameters, const ConfinementTable& table,
                       const TwoWayWindowOptions& options, const NearFieldAtBeta& near_field);
  // With the built-in near field at this beta.
  NearFieldTwoWayModel(const HydrodynamicParameters& parameters, const ConfinementTable& table,
                       const TwoWayWindowOptions& options = {});
  using HydrodynamicModel::evaluate;
  void evaluate(const RodGeometry& rod, const BackgroundFlow& flow, RodDrag& out, ModelState* state) const override;

 private:
  NearFieldAtBeta near_field_;
};

}  // namespace hsrod

// How far the linearly implicit overdamped step (overdamped_rod_step.h) can
// be trusted in double precision: the ratio of the stiffest bond force to
// the drag over one step.
//
// The step solves (R + dt K) v = F. K has the rod's rigid-body motions in
// its null space; they are carried by R alone. When dt k / zeta (bond
// stiffness k [N/m], sphere friction zeta [N s/m]) is S, the rigid motions
// are S times smaller than the matrix's largest entries and are resolved
// only to ~S eps (eps = 2.2e-16): at S ~ 1e20 the rod freezes or the solve
// returns inf. Measured on examples/pore-constriction (10 spheres, 100 us
// of passage, E from 1e9 to 1e25 Pa at dt = 2 us; reference E = 1e12 Pa,
// already rigid): lateral displacement off by 6e-5 at S = 2e11, 1e-2 at
// S = 2e14, inf at S = 2e21. A rod is rigid on the step's scale from S ~ 1e4,
// so the limit costs no physics.
#pragma once

namespace hsrod {

// Largest accepted dt k / zeta: round-off error of the motion ~ S eps <= 2e-4.
inline constexpr double kMaxImplicitStiffnessRatio = 1e12;

// dt k / zeta from the two explicit limits a run already knows:
// the undamped bond limit t_b = 2 / omega_max = 2 sqrt(m / k) [s] and the
// drag limit t_d = 2 m / zeta [s], so k / zeta = 2 t_d / t_b^2. Both > 0.
double implicit_stiffness_ratio(double timestep, double drag_limit, double bond_limit);

// The largest Young's modulus [Pa] with ratio <= kMaxImplicitStiffnessRatio
// (k is proportional to E) for a run with modulus E and ratio S.
double largest_well_conditioned_modulus(double youngs_modulus, double stiffness_ratio);

}  // namespace hsrod

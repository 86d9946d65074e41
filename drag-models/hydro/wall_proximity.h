// Near-wall correction of the reduced models: a sphere within a few
// diameters of a side wall or a pore cylinder (a wall spanning the gap).
//
// The reduced levels miss most of what the side wall does to a sphere next
// to it: the lubrication-like rise of the wall-normal friction (the fluid
// squeezed out between sphere and wall) and the smaller rise along the wall.
// Resolved rodIbFoam rows at beta 0.3, gap 0.5 d, pushed towards the wall:
// wall-normal friction 9.48 (3 pi mu d U) against 4.3-6.0 at levels 2-4
// (calibration/validation/crosscheck_walls.md). The correction adds, per
// sphere i with surface gap delta_i to the nearest wall (unit normal n_i into
// the fluid, tangent t_i), in units of 3 pi mu d:
//
//   dR_i = s(delta) [ c_n phi_n(delta) (1 + k_n S_i) n n^T
//                   + c_t phi_t(delta) (1 + k_t S_i) t t^T
//                   + c_q phi_n(delta) E_i (t n^T + n t^T) ]            (friction)
//   dD_i = the same with (b_n, b_t, b_q) in place of (c_n, c_t, c_q), times u(x_i)   (held load)
//
// so F_i gains dD_i - dR_i v_i. The shapes are the single-wall results of
// 3-D Stokes flow, a = d/2, h = a + delta:
//   phi_n = 1 / f_n - 1, f_n = (6 delta^2 + 2 a delta) / (6 delta^2 + 9 a delta + 2 a^2)
//           (Bevan & Prieve, J. Chem. Phys. 113, 1228 (2000): the Pade form of
//           Brenner's exact series, Chem. Eng. Sci. 16, 242 (1961); a / delta
//           lubrication at contact);
//   phi_t = 1 / (1 - 9/16 x + 1/8 x^3 - 45/256 x^4 - 1/16 x^5) - 1, x = a / h
//           (Faxen's series for motion parallel to a wall, as in Goldman, Cox &
//           Brenner, Chem. Eng. Sci. 22, 637 (1967));
// the gap walls of the slit screen the side wall's 3-D disturbance beyond
// ~H (Bhattacharya, Blawzdziewicz & Wajnryb, J. Fluid Mech. 541, 263 (2005):
// the 3-D part of a confined sphere's flow decays exponentially on the scale
// H): s(delta) = exp(-delta / (l H)). A sphere whose chain neighbours
// (i +- 1, centres < 1.5 d apart) lie along the wall cannot let the squeezed
// fluid escape past its sides: S_i = sum over them of |t_i . e_ij| (0 for a
// lone sphere or a row normal to the wall, 2 inside a row along the wall;
// a row squeezes like a cylinder, whose lubrication force grows faster than
// a sphere's, Jeffrey & Onishi, Q. J. Mech. Appl. Math. 34, 129 (1981)); the
// squeezed fluid flowing out past the row's ends pushes them along the wall:
// E_i = sum of t_i . e_ij (+-1 at an end, 0 inside; the symmetric t n + n t
// keeps R symmetric, its size is capped so that dR stays positive
// semi-definite). The free parameters (c_n, c_t, l, k_n, k_t, b_n, b_t, c_q,
// b_q) are fitted per level to the resolved near-wall rows of the geometry
// campaign (calibration/tools/fit_wall_proximity.cpp): each level carries a
// different part of the wall's effect already (level 4's window reflects the
// depth-averaged flow off the walls, levels 1-3 do not).
//
// Applied at level 4 only (wall_proximity_fit.cpp): its fit brings level 4's
// totals within 8 % of every resolved wall and pore row. Levels 1-3 have
// fitted laws (calibration/data/wall_proximity_fit.json) that are not
// applied: they stay 22-23 % off (the channel-wide reflection of the
// depth-averaged flow these levels lack is not a near-wall effect) and, in
// the dynamic pore passages, push the rod the wrong way
// (calibration/validation/pore_passage/README.md).
//
// Neighbour pairs (levels 3-4, whose R is coupled): two chain neighbours i, j
// along the wall that move at different speeds normal to it squeeze fluid
// along the wall from the approaching one to the receding one, which drags
// both with it:
//   F_i,t = F_j,t = k_p s_ij (v_j - v_i).n,   s_ij = t . e_ij,
// with the reciprocal normal forces F_i,n = -F_j,n = -k_p s_ij (v_i + v_j).t
// that keep R symmetric (R_{x Omega} = R_{Omega x}: a pair dragged along the
// wall is turned), k_p in 3 pi mu d times sqrt(s(delta_i) s(delta_j)): the
// displaced volume does not depend on the gap, only how far it stays
// confined between row and wall. A rigid translation gets no force along the
// wall from it and opposite normal forces on the pair (no net force), so the
// totals of translating rows are unchanged.
//
// Gaps below kMinimumGapOverD d are taken at that gap (the fit covers 0.5-3 d;
// contact is the wall-contact model's job, dynamics/wall_contact.h).
#pragma once

#include "flow/background_flow.h"

#include <string>

namespace hsrod {

struct RodGeometry;
struct RodDrag;

struct WallProximityLaw {
  bool active = false;
  double normal = 0.0;          // c_n [-]
  double along = 0.0;           // c_t [-]
  double screening = 1.0;       // l: screening length over the gap height H [-], > 0
  double normal_row_gain = 0.0; // k_n [-]
  double along_row_gain = 0.0;  // k_t [-]
  double normal_held = 0.0;     // b_n [-]
  double along_held = 0.0;      // b_t [-]
  double squeeze = 0.0;         // c_q [-]
  double squeeze_held = 0.0;    // b_q [-]
  double pair_squeeze = 0.0;    // k_p: the neighbour pair's squeeze flow along the wall [-] (below)
  double beta_min = 0.0, beta_max = 1.0;  // confinement range of the resolved cases fitted [-] (information)
  // the nine above pair_squeeze are what hsrod_fit_wall_proximity fits on translating rows;
  // pair_squeeze is fitted on the turning rows (calibration/validation/crosscheck_near_wall.md)
  static constexpr int kParameters = 9;
  static constexpr double kMinimumGapOverD = 0.25;
};

// One law per level family: levels 1-2 (local: no sphere-sphere coupling, no
// walls in the flow they see), level 3, level 4.
struct WallProximityCalibration {
  WallProximityLaw local, nonlocal, twoway;
  std::string source;
  // The shipped fit (hydro/wall_proximity_fit.cpp, written by hsrod_fit_wall_proximity).
  static const WallProximityCalibration& built_in();
  static WallProximityCalibration off();
  // Level 1 or 2: local; 3: nonlocal; 4: twoway.
  const WallProximityLaw& for_level(int level) const;
};

// The level-3 law fitted on top of the walls' images (NonlocalRodModel with
// WallReflection::images; hydro/wall_images.h): hsrod_fit_wall_proximity
// --levels nonlocal+images on the geometry and near-wall campaigns, the 1 d
// rows held out (calibration/data/wall_proximity_fit_images.json, which
// hydro/wall_images_fit.cpp equals: calibration_WallImages.BuiltInLawIsTheFit).
// Held out: within 7.7 % (totals) / 8.6 % (per-sphere RMS) 1 d from a side
// wall, 11.7 % / 11.4 % 1 d from a pore cylinder.
const WallProximityLaw& wall_proximity_with_images();
// The same, friction terms only, fitted on top of the multiple reflections (WallReflection::reflections;
// calibration/data/wall_proximity_fit_reflections.json, level "nonlocal+reflections",
// equal to hydro/wall_reflections_fit.cpp: calibration_WallReflections.BuiltInLawIsTheFit).
const WallProximityLaw& wall_proximity_with_reflections();

// k_p fitted on top of wall_proximity_with_images() / _with_reflections() to
// the along-wall push of the resolved row of 10 turning 0.5 d from a side wall
// (beta 0.3, campaign near-wall-rotation: +2.595 in 3 pi mu d U at Omega d = U),
// one number per level. Not set in the shipped laws: in the dynamic pore
// passage, held out, it turns the rod 0.5 deg less and drifts it 0.0005-0.001 W
// less, away from neither resolved measure's miss, and beside a pore cylinder
// at 0.5 d it triples the row's push (calibration/validation/crosscheck_near_wall.md).
constexpr double kPairSqueezeOnImages = 0.14232264600812172;       // [-]
constexpr double kPairSqueezeOnReflections = 0.13961478819676637;  // [-]

// Shapes of the single-wall rises (3-D Stokes, see above) at surface gap
// delta over the sphere radius a [-].
double wall_normal_rise(double gap_over_radius);
double wall_along_rise(double gap_over_radius);

// Adds the correction to the load `out` of `rod` (out already holds the
// level's load: per-sphere blocks, and the coupled matrix's diagonal blocks
// when coupled). The walls are flow.geometry()'s side walls and cylinders;
// u(x_i) is flow.velocity. viscosity mu [Pa s], gap height H [m].
void add_wall_proximity(const WallProximityLaw& law, const RodGeometry& rod, const BackgroundFlow& flow,
                        double viscosity, double gap_height, RodDrag& out);

}  // namespace hsrod

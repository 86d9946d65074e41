// Near-field sphere-sphere coupling of levels 3 and 4: the interaction of
// spheres closer than a few gap heights H, which the depth-averaged Green's
// function (brinkman_green.h) gets wrong.
//
// Why: the depth-averaged flow treats each sphere as a column blocking the
// whole gap, so two spheres a distance r << H apart interact through the
// screened 2-D Stokeslet (logarithmic in r). In the slit the fluid passes
// above and below them and they interact as in 3-D Stokes flow, ~1/r,
// screened by the walls only beyond ~H (Bhattacharya, Blawzdziewicz &
// Wajnryb, J. Fluid Mech. 541, 263 (2005): friction of sphere pairs and
// chains between two walls, the crossover from quasi-2-D to 3-D behaviour
// with H). A chain of touching spheres at beta = d/H = 0.15 is therefore
// far more shielded than the depth-averaged model says: levels 3-4 were
// 35-60 % too high on the friction and held load of resolved rods
// (calibration/validation/crosscheck.md).
//
// Model (in the spirit of Stokesian dynamics: far field from the
// depth-averaged equations, near field from a 3-D pair mobility): the pair
// mobility of spheres i != k [m/(N s)], the mid-plane velocity of sphere i
// per force exerted on the fluid by sphere k, is blended
//     M_ik = (1 - w) M_ik^level + w (M_RP(r) - m_wall (alpha I + alpha_e (d/r)^3 e e)),
//     w(r) = exp(-r / (kappa H)),
// where M_ik^level is the level's own depth-averaged pair mobility (level 3:
// 3/2 G(r); level 4: its window's mobility between footprints), M_RP the
// Rotne-Prager(-Yamakawa) tensor of two spheres of diameter d in unbounded
// fluid (Rotne & Prager, J. Chem. Phys. 50, 4831 (1969); the overlapping
// form of Yamakawa, J. Chem. Phys. 53, 436 (1970), for r < d) scaled by the
// confined sphere's mobility over the free one (1/zeta_o over 1/(3 pi mu d),
// so that it tends to the level's self mobility as r -> 0), e the unit
// vector between the centres (r taken >= d in (d/r)^3), and
// m_wall = 1.004 / (3 pi mu H) the two walls' reflection at the mid-plane
// (the leading term of Faxen's series, Happel & Brenner 1965, eq. 7-4.28,
// as a mobility). The exponential weight is the decay of the 3-D flow of a
// point force between two walls beyond ~H/pi towards the Hele-Shaw dipole
// (Liron & Mochon, J. Eng. Math. 10, 287 (1976)); alpha is the walls'
// reflection over the blend region, alpha_e a correction along the line of
// centres for close pairs (where Rotne-Prager overestimates the coupling of
// nearly touching spheres along e). kappa, alpha and alpha_e are fitted per
// level to the resolved per-sphere loads of rigid rods
// (calibration/tools/fit_near_field.cpp, Eigen's Levenberg-Marquardt); the
// shipped fit is calibration/data/near_field_coupling.txt, compiled in as the
// default (near_field_coupling_fit.cpp, written by the same tool).
//
// Limits kept by construction: a lone sphere has no pair, so every level's
// lone sphere stays the confined sphere of the table; pairs farther apart
// than a few kappa H get the level's depth-averaged coupling unchanged
// (w < 1e-10 beyond 23 kappa H is dropped); kappa = 0 switches the near
// field off (the depth-averaged levels as before).
#pragma once

#include <Eigen/Core>

#include <string>

namespace hsrod {

struct NearFieldCoupling {
  double blend_length = 0.0;  // kappa: blend length over the gap height H [-] (0: near field off)
  double reflection = 0.0;    // alpha: wall reflection over Faxen's mid-plane value 1.004 / (3 pi mu H) [-]
  double reflection_along = 0.0;  // alpha_e: close-pair correction along the line of centres, same unit [-]
  bool active() const { return blend_length > 0.0; }
};

// The fitted near field of each level, with where it came from.
struct NearFieldCalibration {
  NearFieldCoupling nonlocal;  // level 3
  NearFieldCoupling twoway;    // level 4
  std::string source;          // one line: the fit that produced it

  // The shipped fit (near_field_coupling_fit.cpp = calibration/data/near_field_coupling.txt).
  static NearFieldCalibration built_in();
  // No near field at either level (the depth-averaged couplings alone).
  static NearFieldCalibration off() { return {}; }

  // File format (version 1), '#' starts a comment (the fit tool writes its
  // provenance, residuals and standard errors as comments):
  //   hsrod-near-field-coupling 1
  //   source <free text>
  //   <model> <blend_length> <reflection> <reflection_along>   one line each for nonlocal and twoway
  // Read strictly; throws std::runtime_error naming the file, line and problem.
  static NearFieldCalibration read(const std::string& path);
  // "" if usable, else the problem: blend_length in [0, 10], reflections in [-10, 10], finite.
  static std::string range_problem(const NearFieldCoupling& c);
};

// Rotne-Prager-Yamakawa mobility of two spheres of diameter d [m] at planform
// offset r [m] in unbounded fluid of viscosity mu [Pa s], in-plane block [m/(N s)].
Eigen::Matrix2d rotne_prager_mobility(const Eigen::Vector2d& offset, double viscosity, double diameter);

// Blend weight w(r) of the 3-D near field at centre distance r [m] in a gap H [m] (0 when off).
double near_field_weight(double distance, double gap_height, const NearFieldCoupling& coupling);

// The blended pair mobility M_ik above, from the level's depth-averaged
// pair mobility `depth_averaged` [m/(N s)] of two spheres at `offset` [m];
// `self_mobility` [m/(N s)] is the level's mobility of one sphere (1 /
// zeta_o), to which M_RP is scaled (M_RP -> m_self I as r -> 0: two merging
// spheres couple as one, and the coupling never exceeds the self mobility).
Eigen::Matrix2d near_field_pair_mobility(const Eigen::Matrix2d& depth_averaged, const Eigen::Vector2d& offset,
                                         double viscosity, double gap_height, double diameter, double self_mobility,
                                         const NearFieldCoupling& coupling);

}  // namespace hsrod

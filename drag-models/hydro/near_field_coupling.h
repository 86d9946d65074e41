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
//     M_ik = M_ik^level + (w_t P_t + w_e P_e) [M_RP(r) - m_wall (alpha I + alpha_e (d/r)^3 e e) - M_ik^level],
//     w_t(r) = exp(-r / (kappa H)),  w_e(r) = exp(-r / (kappa_e H)),
// (P_e X = e e X e e and P_t X = (I - e e) X (I - e e): the components along
// the line of centres and across it, each with its own blend length),
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
// nearly touching spheres along e). kappa, kappa_e, alpha and alpha_e are
// fitted per level, separately for the friction and for the held-in-flow
// load (NearFieldAtBeta below), each quadratic in beta (NearFieldLaw), to the
// resolved per-sphere loads, free velocities and r of rigid rods over beta
// 0.1-0.75 (calibration/tools/fit_near_field.cpp, Eigen's
// Levenberg-Marquardt); the shipped fit is
// calibration/data/near_field_coupling.txt, compiled in as the default
// (near_field_coupling_fit.cpp, written by the same tool). Why kappa_e: with
// one blend length for both components, long rods came out 9-16 % too stiff
// along their axis and too free across it at every beta (the far spheres'
// shielding along the chain reaches farther than the transverse coupling's
// crossover); with it the fit's RMS profile error fell from 5.6 % to 2.2 %
// (linear in beta; 2.0 % quadratic).
//
// Limits kept by construction: a lone sphere has no pair, so every level's
// lone sphere stays the confined sphere of the table; pairs farther apart
// than a few kappa H get the level's depth-averaged coupling unchanged
// (w < 1e-10 beyond 23 kappa H is dropped); kappa = 0 switches the near
// field off (the depth-averaged levels as before).
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace hsrod {

struct NearFieldCoupling {
  double blend_length = 0.0;  // kappa: blend length over the gap height H [-] (0: near field off)
  double reflection = 0.0;    // alpha: wall reflection over Faxen's mid-plane value 1.004 / (3 pi mu H) [-]
  double reflection_along = 0.0;  // alpha_e: close-pair correction along the line of centres, same unit [-]
  // kappa_e: blend length of the component along the line of centres over H [-] (0: = blend_length)
  double blend_length_along = 0.0;
  bool active() const { return blend_length > 0.0; }
  double along() const { return blend_length_along > 0.0 ? blend_length_along : blend_length; }
};

// The near field of one level at one beta: the friction (the resistance of
// a row moving through fluid at rest) and the held-in-flow load (the
// driving) each through its own pair mobility.
//
// Why two: with one mobility for both, a row's driving is c R_o u and its
// friction zeta_f + R_o, so its force-free velocity c S / (n zeta_f + S)
// (S = 1^T R_o 1) falls with the shielding S / n: once the friction was
// fitted, the free velocity along a 10-sphere rod came out 3 % (beta 0.3) to
// 14 % (beta 0.75) low. The resolved rods say otherwise: the film part of
// a sphere's friction is shielded in a chain like its obstruction part
// (calibration/campaign: film/zeta_f tracks obstruction/zeta_o sphere by
// sphere), and the held load of a chain in the parabolic gap profile is
// not the resistance times the mid-plane velocity (its Faxen-type
// curvature part couples differently; Bhattacharya, Blawzdziewicz &
// Wajnryb's Poiseuille-flow companion study, arXiv cond-mat/0508309).
// The driving therefore gets its own fitted coupling: the row's held load
// is c R_o^D u with R_o^D = (M^D)^-1, M^D the pair mobility blended with the
// driving's parameters (hydro/nonlocal_model.cpp, hydro/twoway_near_field.cpp).
// A lone sphere has no pair: its friction and driving stay the table's.
struct NearFieldAtBeta {
  NearFieldCoupling friction;  // of the resistance R_o
  NearFieldCoupling driving;   // of the held-in-flow load c R_o^D u
  NearFieldAtBeta() = default;
  NearFieldAtBeta(const NearFieldCoupling& both) : friction(both), driving(both) {}  // NOLINT: one coupling for both
  NearFieldAtBeta(const NearFieldCoupling& f, const NearFieldCoupling& d) : friction(f), driving(d) {}
  bool active() const { return friction.active() || driving.active(); }
};

// The fitted near field of one level as a function of beta = d / H: each of
// the eight parameters (friction and driving x blend length, reflection,
// reflection along, blend length along) is a polynomial in (beta - 0.3); the blend length's
// polynomial is that of ln(kappa) (kappa > 0 at every beta). beta is
// clamped into [beta_min, beta_max], the range of the resolved rows it was
// fitted to: outside it the end values are used (no extrapolation of the
// polynomials), except that below beta_min the held load's parameters tend
// to the friction's as (beta / beta_min)^2 (near_field_coupling.cpp: the
// free velocity of a rod tends to 3/2 as beta -> 0).
struct NearFieldLaw {
  static constexpr double kBetaReference = 0.3;  // [-]
  bool active = false;                           // false: near field off at every beta
  // [friction, driving][ln blend_length, reflection, reflection_along, ln blend_length_along]
  std::vector<double> coefficients[2][4];
  double beta_min = 0.0, beta_max = 1.0;         // [-]
  // The same coupling at every beta, for friction and driving (file version 1).
  static NearFieldLaw constant(const NearFieldCoupling& c);
  NearFieldAtBeta at(double beta) const;
};

// The fitted near field of each level, with where it came from.
struct NearFieldCalibration {
  NearFieldLaw nonlocal;  // level 3
  NearFieldLaw twoway;    // level 4
  std::string source;     // one line: the fit that produced it

  // The shipped fit (near_field_coupling_fit.cpp = calibration/data/near_field_coupling.txt).
  static NearFieldCalibration built_in();
  // No near field at either level (the depth-averaged couplings alone).
  static NearFieldCalibration off() { return {}; }

  // File format, '#' starts a comment (the fit tool writes its provenance,
  // residuals and standard errors as comments):
  //   version 1 (one coupling for friction and driving at every beta):
  //     hsrod-near-field-coupling 1
  //     source <free text>
  //     <model> <blend_length> <reflection> <reflection_along>   one line each for nonlocal and twoway
  //   version 2 (the law above):
  //     hsrod-near-field-coupling 2
  //     source <free text>
  //     beta_range <beta_min> <beta_max>
  //     <model> <load> <parameter> <c0> [<c1> ...]   model nonlocal|twoway, load friction|driving,
  //                                                  parameter ln_blend_length|reflection|reflection_along|
  //                                                  ln_blend_length_along; all 16 lines but the last
  //                                                  parameter's (default: that of ln_blend_length)
  // Read strictly; throws std::runtime_error naming the file, line and problem
  // (every law is also checked at beta_min, beta_max and in between).
  static NearFieldCalibration read(const std::string& path);
  // "" if usable, else the problem: blend_length in [0, 10], reflections in [-10, 10], finite.
  static std::string range_problem(const NearFieldCoupling& c);
  static std::string range_problem(const NearFieldAtBeta& c);
};

// Rotne-Prager-Yamakawa mobility of two spheres of diameter d [m] at planform
// offset r [m] in unbounded fluid of viscosity mu [Pa s], in-plane block [m/(N s)].
Eigen::Matrix2d rotne_prager_mobility(const Eigen::Vector2d& offset, double viscosity, double diameter);

// Blend weight w(r) of the 3-D near field at centre distance r [m] in a gap H [m] (0 when off):
// the larger of the weights of the transverse (kappa) and the along (kappa_e) components.
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

// hsrod calibration: fit of the confinement coefficients
// (drag-models/hydro/confinement_coefficients.h) to resolved force
// measurements.
//
// Plain C++17 + Eigen. Model (linear Stokes flow, one body per run, forces
// along the flow direction x):
//     F / n = a u_mean - b v                                     [N]
// F: total hydrodynamic force on the body (a sphere, or a rigid rod of n
// spheres along / across its axis) [N], u_mean: gap-averaged mean velocity of
// the undisturbed flow [m/s], v: body velocity [m/s]. Runs with the body held
// in a flow give a, runs dragging it through still fluid give b; any mix is
// fitted by linear least squares per (beta, body) (Eigen's column-pivoting
// QR). Coefficients (zeta_0 = 3 pi mu d):
//     sphere:  sphere_friction = b / zeta_0,  sphere_driving = a / b
//     rod:     {parallel,perpendicular}_friction = b / (sphere_friction zeta_0),
//              {parallel,perpendicular}_driving  = a / b
// Columns without data at a beta keep the default table's value there
// (ConfinementTable::default_table()); the table's source line says which
// columns were fitted.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "hydro/confinement_coefficients.h"

namespace hsrod::calib {

enum class FitBody { Sphere, RodParallel, RodPerpendicular };

struct ForceSample {
  double beta = 0.0;   // d / H [-]
  FitBody body = FitBody::Sphere;
  int n_spheres = 1;   // spheres in the body
  double d = 0.0;      // sphere diameter [m]
  double mu = 0.0;     // dynamic viscosity [Pa s]
  double u_mean = 0.0; // mean velocity of the undisturbed flow [m/s]
  double v = 0.0;      // body velocity along x [m/s]
  double force = 0.0;  // total force along x on the body [N]
};

struct LinearFit {
  double a = 0.0, b = 0.0;  // [N s/m]
  double rms_residual = 0.0;  // relative to the rms force [-]
  int n = 0;
};

// CSV with header beta,body,n_spheres,d,mu,u_mean,v,force ('#' comments);
// body = sphere | rod_parallel | rod_perpendicular. Throws std::runtime_error
// naming the line on bad input.
std::vector<ForceSample> read_force_samples(const std::string& path);
std::vector<ForceSample> parse_force_samples(const std::string& text, const std::string& origin);

// Fits F/n = a u - b v to the samples (throws std::invalid_argument if the
// samples do not determine both a and b).
LinearFit fit_linear(const std::vector<ForceSample>& samples);

// The coefficient table from all samples (betas = those of the samples).
ConfinementTable fit_table(const std::vector<ForceSample>& samples, const std::string& source);

// ---------------------------------------------------------------------------
// Curve fits over beta (and the rod's sphere count n) of the coefficients
// measured by the resolved campaign (calibration/tools/hsrod_campaign.py),
// weighted nonlinear least squares with Eigen's Levenberg-Marquardt
// (unsupported/Eigen/NonLinearOptimization, MINPACK's lmder), parameter
// standard errors from the covariance s^2 (J^T W J)^-1 at the solution.
//
// Forms (drag-models/hydro/confinement_forms.h; each with its known beta -> 0
// or n = 1 limit built in):
//   SphereFriction  K(beta): Faxen's mid-plane series with its leading
//                   coefficient p0 free (Faxen: 1.004); two params: p0 and
//                   the beta^3 coefficient p3 (Faxen: 0.418)
//   SphereDriving   lambda(beta) = 3/2 (1 - p0 beta^2) (Faxen's law: 1/3);
//                   two params: p0 and a beta^4 coefficient p2 (Faxen: 0)
//   RodColumn       per-sphere friction of a straight rod of n spheres over
//                   the lone sphere's, rod_n_law(c_inf, 1, 0, n, e),
//                   c_inf = p0 + p1 beta + ..., then the shielding
//                   e(beta) = polynomial of layout.shielding_terms terms
//                   (0: e = 0, no shielding)
//   RodColumnGrowth the same with the growth term g = beta^2 (k0 + k1 beta
//                   ...) across the axis: params = (c_inf polynomial...,
//                   layout.growth_terms k..., layout.shielding_terms e...)
//   RodHeld         per-sphere held-in-flow load (over the lone sphere's
//                   friction x gap-mean velocity):
//                   rod_n_law(c_inf lambda_inf, lambda_s, g lambda_s, n, e lambda_s),
//                   lambda_inf = 3/2 (1 - beta (q0 + q1 beta ...)) (params),
//                   c_inf, g and e = `rod_friction_inf`, `growth`,
//                   `shielding` (given, from the friction fit; no shielding
//                   given: e = 0), lambda_s = `lone` (given).
//   RodVelocity     force-free velocity of the rod (over the gap-mean
//                   velocity), the RodHeld load over the friction n-law:
//                   confinement_form::rod_velocity(c_inf, lambda_inf,
//                   lambda_s, g, g, n, e), lambda_inf as in RodHeld (params);
//                   fitted to the velocities directly, which the mesh
//                   changes far less than the loads (ratios of loads on
//                   one mesh: calibration/README.md)
//   RodVelocityRatio the same velocity with its own held growth
//                   g_held = beta^2 (k_held0 + k_held1 beta ...) (params =
//                   (lambda_inf polynomial..., layout.held_growth_terms
//                   k_held...); RodVelocity has g_held = g) over a given
//                   velocity, `divisor`(beta, n) (r = lambda_perp /
//                   lambda_par, with lambda_par from a RodVelocity fit): the
//                   perpendicular velocity fitted to the measured r, so that
//                   r - 1 (a few 1e-3 at beta 0.3) keeps its sign and size
enum class CurveForm { SphereFriction, SphereDriving, RodColumn, RodColumnGrowth, RodHeld, RodVelocity, RodVelocityRatio };

struct CurvePoint {
  double beta = 0.0;   // d / H [-]
  int n = 1;           // spheres in the rod [-]
  double value = 0.0;  // measured coefficient [-]
  double sigma = 0.0;  // its standard uncertainty [-] (> 0)
};

// How the rod forms split their parameters (see CurveForm); the defaults are
// the simplest forms (constant k, constant k_held, no shielding).
struct RodLayout {
  int growth_terms = 1;       // RodColumnGrowth: terms of k(beta) in g = beta^2 k(beta)
  int shielding_terms = 0;    // RodColumn, RodColumnGrowth: terms of e(beta)
  int held_growth_terms = 1;  // RodVelocityRatio: terms of k_held(beta)
};

struct CurveFit {
  CurveForm form = CurveForm::SphereFriction;
  RodLayout layout;
  std::vector<double> params, std_errors;
  double chi2_per_dof = 0.0;       // weighted residual sum of squares / (m - p)
  double rms_relative = 0.0;       // rms of (fit - value) / value [-]
  double max_relative = 0.0;       // largest |fit - value| / value [-]
  std::vector<double> relative_residuals;  // per point, in input order
  // given functions of beta: the lone-sphere limit (RodHeld: lambda_s), the
  // infinite rod's friction c_inf and the growth coefficient g (RodHeld)
  std::function<double(double)> lone, rod_friction_inf, growth, shielding;
  std::function<double(double, int)> divisor;  // RodVelocityRatio: lambda_par(beta, n)
  // RodColumn*: c_inf(beta); RodHeld, RodVelocity*: lambda_inf(beta); spheres: the value
  double asymptote(double beta) const;
  // RodColumnGrowth: g(beta) = beta^2 k(beta); else 0
  double growth_at(double beta) const;
  // RodColumn*: the shielding e(beta) (0 without shielding terms); RodHeld,
  // RodVelocity*: the given e (0 if none)
  double shielding_at(double beta) const;
  double operator()(double beta, int n = 1) const;
  // RodVelocityRatio: the velocity itself (the value times the divisor); else operator()
  double velocity(double beta, int n) const;
  // RodVelocityRatio: g_held(beta) = beta^2 k_held(beta); RodVelocity: the given g
  double held_growth_at(double beta) const;
};

// Fits `form` to the points from the start values `start` (its size sets
// the number of parameters; RodColumn: the polynomial degree + 1, plus the
// layout's blocks). Throws std::invalid_argument for fewer points than
// parameters, sigma <= 0, a layout that leaves no polynomial term, or a
// RodColumn / RodHeld fit without its given functions; std::runtime_error if
// LM fails.
CurveFit fit_curve(CurveForm form, const std::vector<CurvePoint>& points, std::vector<double> start,
                   std::function<double(double)> lone = {}, std::function<double(double)> rod_friction_inf = {},
                   std::function<double(double)> growth = {},
                   std::function<double(double, int)> divisor = {}, const RodLayout& layout = {},
                   std::function<double(double)> shielding = {});

}  // namespace hsrod::calib

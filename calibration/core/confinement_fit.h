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
//                   coefficient p0 free (Faxen: 1.004)
//   SphereDriving   lambda(beta) = 3/2 (1 - p0 beta^2) (Faxen's law: 1/3)
//   RodColumn       per-sphere friction of a straight rod of n spheres over
//                   the lone sphere's, rod_n_law(c_inf, 1, 0, n),
//                   c_inf = p0 + p1 beta + ... (all params)
//   RodColumnGrowth the same with the growth term g = k beta^2 across the
//                   axis: params = (polynomial..., k)
//   RodHeld         per-sphere held-in-flow load (over the lone sphere's
//                   friction x gap-mean velocity):
//                   rod_n_law(c_inf lambda_inf, lambda_s, g lambda_s, n),
//                   lambda_inf = 3/2 (1 - beta (q0 + q1 beta ...)) (params),
//                   c_inf and g = `rod_friction_inf`, `growth` (given, from
//                   the friction fit), lambda_s = `lone` (given).
enum class CurveForm { SphereFriction, SphereDriving, RodColumn, RodColumnGrowth, RodHeld };

struct CurvePoint {
  double beta = 0.0;   // d / H [-]
  int n = 1;           // spheres in the rod [-]
  double value = 0.0;  // measured coefficient [-]
  double sigma = 0.0;  // its standard uncertainty [-] (> 0)
};

struct CurveFit {
  CurveForm form = CurveForm::SphereFriction;
  std::vector<double> params, std_errors;
  double chi2_per_dof = 0.0;       // weighted residual sum of squares / (m - p)
  double rms_relative = 0.0;       // rms of (fit - value) / value [-]
  double max_relative = 0.0;       // largest |fit - value| / value [-]
  std::vector<double> relative_residuals;  // per point, in input order
  // given functions of beta: the lone-sphere limit (RodHeld: lambda_s), the
  // infinite rod's friction c_inf and the growth coefficient g (RodHeld)
  std::function<double(double)> lone, rod_friction_inf, growth;
  // RodColumn*: c_inf(beta); RodHeld: lambda_inf(beta); spheres: the value
  double asymptote(double beta) const;
  // RodColumnGrowth: g(beta) = k beta^2; else 0
  double growth_at(double beta) const;
  double operator()(double beta, int n = 1) const;
};

// Fits `form` to the points from the start values `start` (its size sets
// the number of parameters; RodColumn: the polynomial degree + 1). Throws
// std::invalid_argument for fewer points than parameters, sigma <= 0, or a
// RodColumn / RodHeld fit without its given functions; std::runtime_error if
// LM fails.
CurveFit fit_curve(CurveForm form, const std::vector<CurvePoint>& points, std::vector<double> start,
                   std::function<double(double)> lone = {}, std::function<double(double)> rod_friction_inf = {},
                   std::function<double(double)> growth = {});

}  // namespace hsrod::calib

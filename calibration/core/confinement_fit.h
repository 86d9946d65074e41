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

}  // namespace hsrod::calib

// hsrod calibration: resolution, stability and cost report of a resolved run.
//
// Plain C++17. The solver fills RunParameters and prints the report before
// the first time step; violations of hard limits are returned as errors so
// the solver can stop before any time is spent.
//
// Criteria (SI units):
//  - resolution: cells per sphere diameter n_d = d / h, h = cbrt(V_cell) at the
//    sphere centre. The resolved study (Brasel et al. 2024, Soft Matter, Sec. 2)
//    requires >= 8; below `min_cells_per_diameter` is an error.
//  - fluid Courant number  Co = U_max dt / h  (explicit transport; PISO accuracy):
//    warning above max_courant.
//  - viscous number nu dt / h^2: measured with this solver on graded meshes,
//    transient runs with the momentum predictor or the consistent (SIMPLEC)
//    variant diverge at nu dt/h^2 >> 1 (180 in the test); warning above 10.
//  - particle Reynolds number Re_p = U d / nu (Stokes-regime check, information).
//  - solid-fluid coupling (the particle reacting to the fluid): the coupling
//    interval dt_c = N_ci dt_DEM must resolve the particle's Stokes relaxation
//    time tau_p = rho_p d^2 / (18 mu); explicit drag exchange is stable for
//    dt_c < 2 tau_p (forward Euler on dv/dt = -(v - u)/tau_p) and accurate for
//    dt_c <= tau_p. Error above 2 tau_p, warning above tau_p.
//  - fluid-solid coupling (the fluid reacting to the moving body): the immersed
//    body must not move more than a fraction of a cell per coupling interval,
//    CFL_p = v_p dt_c / h <= 0.5 (else the forcing skips cells). Error above 1.
//  - momentum exchange in coupled mode (momentum_exchange.h): the fluid
//    load of step n acts on the particle during step n+1; its response to a
//    particle velocity change (drag zeta ~ 3 pi mu d, acceleration reaction
//    m_a = c rho_f V: added mass 1/2, forced fluid shell (1 + h/d)^3 - 1,
//    Basset impulse 9 sqrt(nu dt_c/pi)/a) makes a two-step recurrence whose
//    spectral radius is the gain per coupling interval. Reported: the worst
//    case over zeta in [1, 1.5] zeta_0 and m_a in [1/2, 3/2] c rho_f V, for the
//    chosen scheme (explicit, or semi-implicit: implicit drag Ksl on the DEM
//    side plus virtual mass C_v rho_f V) and, for comparison, for the
//    explicit one. Gain >= 1 is an error (measured, explicit:
//    rho_p/rho_f = 1.17 at d/h = 4.8 diverged); an oscillatory root above
//    0.7 a warning (a gain just below 1 with real positive roots is the
//    physical relaxation exp(-dt_c/tau) of a short interval).
//    With the explicit scheme dt_c >= 2 tau_p is an error (forward Euler on
//    dv/dt = -(v - u)/tau_p); with the semi-implicit one the drag is
//    integrated at the DEM step and dt_c > tau_p is only an accuracy warning.
//  - cost: cells x iterations x measured cost per cell-iteration.
#pragma once

#include <string>
#include <vector>

namespace hsrod::calib {

struct RunParameters {
  double d_min = 0.0;             // smallest sphere diameter [m]
  double h_sphere = 0.0;          // largest cell size at any sphere centre [m]
  double u_ref = 0.0;             // reference (max) fluid velocity [m/s]
  double v_particle = 0.0;        // max sphere speed [m/s]
  double dt = 0.0;                // CFD time step [s]
  double nu = 0.0;                // kinematic viscosity [m^2/s]
  double rho_f = 0.0;             // fluid density [kg/m^3]
  double rho_p = 0.0;             // particle density [kg/m^3]; 0 = not given
  double dt_dem = 0.0;            // DEM time step [s]; 0 = no coupling
  int coupling_interval = 0;      // DEM steps per coupling
  bool coupled = false;           // free coupled motion
  bool semi_implicit = false;     // exchange semiImplicit (else explicit)
  double virtual_mass_coeff = 0;  // C_v [-] (semi-implicit exchange)
  double drag_factor = 1.0;       // K_d [-]: Ksl = K_d 3 pi mu d (semi-implicit exchange)
  bool steady = false;            // pseudo-time (steadyState ddt)
  long n_cells = 0;
  double n_iterations = 0.0;      // time steps (transient) or max iterations (steady)
  int n_correctors = 1;           // PISO/PIMPLE pressure solves per iteration
  double cost_per_cell_iter = 0;  // [s], measured on the reference machine
  bool momentum_predictor = false;  // PIMPLE momentumPredictor (transient)
  bool consistent = false;          // PIMPLE consistent (SIMPLEC) (transient)
  double min_cells_per_diameter = 6.0;
  double max_courant = 1.0;
};

struct Report {
  double cells_per_diameter = 0, courant = 0, reynolds = 0, viscous_number = 0;
  double tau_p = 0, dt_couple = 0, solid_fluid_ratio = 0, particle_cfl = 0, density_ratio = 0;
  double amplification = 0;           // gain per coupling interval of the chosen exchange [-]
  double amplification_explicit = 0;  // the same for the explicit exchange [-]
  double oscillation = 0;             // worst oscillatory root of the chosen exchange [-]
  double reaction_coeff = 0;          // estimated acceleration reaction c [rho_f V]
  double est_cost_s = 0;
  std::vector<std::string> errors, warnings;
  std::string text;  // human readable table
};

Report make_report(const RunParameters& p);

}  // namespace hsrod::calib

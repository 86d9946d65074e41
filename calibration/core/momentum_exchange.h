// hsrod calibration: the CFD -> DEM momentum exchange of coupled runs and
// its linear stability.
//
// Plain C++17 (no OpenFOAM, no LIGGGHTS).
//
// The fluid step n moves the immersed spheres with the DEM velocity v^n and
// returns the hydrodynamic load F^n; LIGGGHTS then integrates one coupling
// interval dt_c with it. F^n reacts to the particle velocity through
//   - the drag, -zeta (v^n - u)                          zeta ~ 3 pi mu d  [kg/s]
//   - an acceleration reaction, -m_a (v^n - v^(n-1))/dt_c: the added mass
//     (1/2 rho_f V for a sphere), the fluid shell the forcing ties to the
//     body (cells within ~h/2 of the surface: ((1 + h/d)^3 - 1) rho_f V) and,
//     dominant for long intervals, the Basset history force: a velocity step
//     dv gives F_B = 6 a^2 sqrt(pi rho_f mu) dv / sqrt(t) (Maxey & Riley
//     1983, Phys. Fluids 26:883), an impulse 12 a^2 rho_f sqrt(pi nu dt_c) dv
//     over one interval = 9 sqrt(nu dt_c/pi)/a rho_f V dv. Measured with
//     rodIbFoam (rho_p = rho_f, d/h = 7.2, dt_c = 4 tau_p): virtual mass
//     1/2 + shell alone oscillated with growth -1.73 per interval; with the
//     Basset term included the run converged (calibration.coupled_settling).
// Explicit exchange (F^n held for the whole interval) amplifies velocity
// disturbances unless dt_c < 2 tau_p and m_a < m_p; at the paper's density
// ratio rho_p/rho_f = 1 the second condition fails on any mesh (Uhlmann
// 2005, J. Comput. Phys. 209:448, reports the limit rho_p/rho_f ~ 1.2).
//
// Semi-implicit exchange (this file):
//   1. drag implicit on the DEM side: LIGGGHTS' fix couple/cfd/force/implicit
//      applies  F = F_0 + Ksl (u_f - v)  at every DEM step with the current v;
//      we pass u_f = v^n and F_0 = F^n, so the total load is
//          F^n - Ksl (v - v^n),      Ksl = K_d 3 pi mu d,
//      equal to F^n at v = v^n and following the particle's own velocity
//      within the interval (the drag part of the response is then resolved
//      at the DEM step, not the coupling interval). The same for the spin:
//          T^n - Krot (omega - omega^n),  Krot = K_d 8 pi mu a^3
//      (fix couple/cfd/torque/implicit of this package).
//   2. virtual mass (Schwarz, Kempe & Froehlich 2015, J. Comput. Phys.
//      281:591): the DEM mass becomes m_p + m_v, m_v = C_v rho_f V, and the
//      load gains + m_v (v^n - v^(n-1))/dt_c. At a steady state both vanish;
//      in the linearised recurrence the explicit acceleration reaction
//      (m_v - m_a) replaces -m_a and is divided by m_p + m_v.
//
// Linear model (per velocity component, e = v - v_terminal; exact solution
// over the interval of  (m_p + m_v) de/dt = -Ksl (e - e^n) - zeta e^n
// + (m_v - m_a)(e^n - e^(n-1))/dt_c):
//     e^(n+1) = (1 - phi zeta + phi D) e^n - phi D e^(n-1),
//     phi = (1 - exp(-Ksl dt_c/(m_p + m_v)))/Ksl  (dt_c/(m_p + m_v) if Ksl = 0),
//     D = (m_v - m_a)/dt_c.
// Its spectral radius (largest |root| of z^2 - A z + B) is the gain per
// coupling interval; >= 1 diverges.
#pragma once

#include <array>
#include <map>
#include <vector>

#include "sphere_set.h"

namespace hsrod::calib {

struct ExchangeModel {
  double mass = 0.0;          // particle mass m_p [kg]
  double drag = 0.0;          // true drag coefficient zeta [kg/s]
  double ksl = 0.0;           // implicit drag coefficient given to the DEM [kg/s]; 0 = explicit
  double added_mass = 0.0;    // true acceleration reaction of the resolved fluid m_a [kg]
  double virtual_mass = 0.0;  // virtual mass on the DEM side m_v [kg]
  double dt_couple = 0.0;     // coupling interval dt_c [s]
};

// Spectral radius of the linearised exchange recurrence (see above) [-].
// A value just below 1 may be the slow physical relaxation exp(-dt_c/tau)
// of a short interval; numerical trouble shows as a root that is negative
// or complex (an oscillation from one interval to the next).
double exchange_spectral_radius(const ExchangeModel& m);
// Largest |z| among the oscillatory roots (negative real or complex); 0 if none [-].
double exchange_oscillation(const ExchangeModel& m);

struct ExchangeGain {
  double radius = 0.0;       // worst spectral radius [-]; >= 1 diverges
  double oscillation = 0.0;  // worst modulus of an oscillatory root [-]
};
// Estimated acceleration reaction per coupling interval in units of rho_f V:
//   c = 1/2 + ((1 + h/d)^3 - 1) + 9 sqrt(nu dt_c / pi) / a   [-]
// d sphere diameter [m], h cell size [m], nu [m^2/s], dt_c [s].
double acceleration_reaction_coeff(double d, double h, double nu, double dt_couple);

// Worst case over the uncertain coefficients: zeta in [1, 1.5] x zeta_0
// (confinement, neighbours) and m_a in [1/2, 3/2] x c rho_f V. Measured
// (rodIbFoam, rho_p = rho_f, d/h = 7.2, dt_c = 4 tau_p, C_v = 0.98): the
// velocity error grew by -1.73 per interval, which this model gives for
// m_a = 5.3 rho_f V; the estimate c is 5.77 (within 10 %).
ExchangeGain exchange_worst_gain(double mass, double fluid_mass, double zeta0, double reaction_coeff,
                                 double ksl, double virtual_mass, double dt_couple);

// Settings of a coupled run's exchange (immersedBoundaryProperties).
struct ExchangeSettings {
  bool semi_implicit = false;   // exchange semiImplicit|explicit
  double virtual_mass_coeff = 0.0;  // C_v [-] (m_v = C_v rho_f V)
  double drag_factor = 1.0;     // K_d: Ksl = K_d 3 pi mu d, Krot = K_d 8 pi mu a^3 [-]
  double mu = 0.0;              // dynamic viscosity [Pa s]
  double rho_f = 0.0;           // fluid density [kg/m^3]
  double dt_couple = 0.0;       // coupling interval [s]
};

// What LIGGGHTS receives for one sphere (fix couple/cfd/force/implicit and
// fix couple/cfd/torque/implicit): force F_0 [N], torque T_0 [N m], Ksl [kg/s],
// u_f [m/s], Krot [kg m^2/s] per axis.
struct DemLoad {
  long id = 0;
  Vec3 force{}, torque{}, uf{}, krot{};
  double ksl = 0.0;
};

class MomentumExchange {
 public:
  explicit MomentumExchange(const ExchangeSettings& s);
  // Virtual mass of a sphere of diameter d [kg].
  double virtual_mass(double d) const;
  // Loads for LIGGGHTS from the fluid loads of the step (spheres carry v^n,
  // omega^n, F^n, T^n). Remembers v^n for the next call's m_v dv/dt term.
  std::vector<DemLoad> loads(const std::vector<Sphere>& spheres);

 private:
  ExchangeSettings s_;
  std::map<long, Vec3> prev_v_;  // v^(n-1) by sphere id [m/s]
};

}  // namespace hsrod::calib

// hsrod calibration: stability and cost report (see stability_report.h).
#include "stability_report.h"

#include "momentum_exchange.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace hsrod::calib {

namespace {
std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// Each phase appends its lines to the report text t and its findings to
// r.errors / r.warnings, in the order the report lists them.

// spatial resolution: cells per sphere diameter at the sphere centres
void report_resolution(const RunParameters& p, Report& r, std::ostringstream& t) {
  r.cells_per_diameter = p.d_min / p.h_sphere;
  t << "  cells per sphere diameter d/h    " << fmt("%8.2f", r.cells_per_diameter)
    << "   (need >= " << p.min_cells_per_diameter << ", paper: >= 8)\n";
  if (r.cells_per_diameter < p.min_cells_per_diameter) {
    r.errors.push_back("mesh too coarse for the spheres: " + fmt("%.2f", r.cells_per_diameter) +
                       " cells per diameter at a sphere centre, minimum " +
                       fmt("%.1f", p.min_cells_per_diameter) +
                       " (refine the mesh around the spheres or set minCellsPerDiameter)");
  } else if (r.cells_per_diameter < 8.0) {
    r.warnings.push_back("fewer than 8 cells per diameter: drag error of several percent expected");
  }
}

// fluid time step: Courant and viscous numbers
void report_time_step(const RunParameters& p, Report& r, std::ostringstream& t) {
  r.courant = p.u_ref * p.dt / p.h_sphere;
  r.viscous_number = p.nu * p.dt / (p.h_sphere * p.h_sphere);
  if (p.steady) {
    t << "  steady (pseudo-time) run: Courant/viscous numbers not limiting\n";
  } else {
    t << "  Courant number U dt / h          " << fmt("%8.3g", r.courant) << "   (max "
      << p.max_courant << ")\n";
    t << "  viscous number nu dt / h^2       " << fmt("%8.3g", r.viscous_number)
      << "   (implicit diffusion: information only)\n";
    if (r.viscous_number > 10.0 && (p.momentum_predictor || p.consistent)) {
      r.warnings.push_back("viscous number " + fmt("%.3g", r.viscous_number) +
                           " > 10 with momentumPredictor/consistent on: measured unstable, "
                           "switch both off and use nOuterCorrectors");
    }
    if (r.courant > p.max_courant) {
      r.warnings.push_back("Courant number " + fmt("%.3g", r.courant) + " above " +
                           fmt("%.3g", p.max_courant));
    }
  }
}

// particle response: Stokes relaxation time, density ratio
void report_particle_response(const RunParameters& p, Report& r, std::ostringstream& t) {
  const double mu = p.rho_f * p.nu;
  r.tau_p = p.rho_p * p.d_min * p.d_min / (18.0 * mu);
  r.density_ratio = p.rho_p / p.rho_f;
  t << "  Stokes relaxation tau_p           " << fmt("%8.3g", r.tau_p) << " s\n";
  t << "  density ratio rho_p/rho_f         " << fmt("%8.3g", r.density_ratio) << '\n';
}

// stability of the momentum exchange over one coupling interval, per sphere
// of the smallest diameter (momentum_exchange.h)
void report_exchange_gain(const RunParameters& p, Report& r, std::ostringstream& t) {
  const double pi = 3.14159265358979323846;
  const double mu = p.rho_f * p.nu;
  const double vol = pi * p.d_min * p.d_min * p.d_min / 6.0;
  const double mass = p.rho_p * vol, mf = p.rho_f * vol;
  const double zeta0 = 3.0 * pi * mu * p.d_min;
  const double shell = std::pow(1.0 + p.h_sphere / p.d_min, 3) - 1.0;
  r.reaction_coeff = acceleration_reaction_coeff(p.d_min, p.h_sphere, p.nu, r.dt_couple);
  const double c = r.reaction_coeff;
  const ExchangeGain ex = exchange_worst_gain(mass, mf, zeta0, c, 0.0, 0.0, r.dt_couple);
  const ExchangeGain chosen =
      p.semi_implicit ? exchange_worst_gain(mass, mf, zeta0, c, p.drag_factor * zeta0,
                                            p.virtual_mass_coeff * mf, r.dt_couple)
                      : ex;
  r.amplification_explicit = ex.radius;
  r.amplification = chosen.radius;
  r.oscillation = chosen.oscillation;
  t << "  acceleration reaction c           " << fmt("%8.3g", c)
    << " rho_f V   (1/2 + shell " << fmt("%.3g", shell) << " + Basset 9 sqrt(nu dt_c/pi)/a)\n";
  t << "  exchange " << (p.semi_implicit ? "semi-implicit" : "explicit     ")
    << " gain             " << fmt("%8.3g", r.amplification)
    << "   (spectral radius per coupling interval, worst case; stable < 1)\n";
  t << "  exchange oscillatory root         " << fmt("%8.3g", r.oscillation)
    << "   (interval-to-interval oscillation; warning > 0.7)\n";
  if (p.semi_implicit) {
    t << "    Ksl = " << fmt("%.3g", p.drag_factor) << " x 3 pi mu d, virtual mass "
      << fmt("%.3g", p.virtual_mass_coeff) << " rho_f V; explicit exchange would give "
      << fmt("%.3g", r.amplification_explicit) << '\n';
  }
  if (r.amplification >= 1.0) {
    r.errors.push_back(
        std::string(p.semi_implicit ? "semi-implicit" : "explicit") + " coupling unstable: gain " +
        fmt("%.3g", r.amplification) +
        " >= 1 (light particles / coarse mesh / long coupling interval: " +
        (p.semi_implicit ? "set virtualMassCoeff near c, check dragFactor, "
                         : "use exchange semiImplicit, raise d/h, ") +
        "shorten the coupling interval, or set allowUnstableCoupling)");
  } else if (r.oscillation > 0.7) {
    r.warnings.push_back("exchange oscillatory root " + fmt("%.3g", r.oscillation) +
                         " above 0.7: expect slowly damped oscillations");
  }
}

// the coupling interval against the solid-fluid (dt_c / tau_p) and
// fluid-solid (v_p dt_c / h) criteria
void report_coupling(const RunParameters& p, Report& r, std::ostringstream& t) {
  r.dt_couple = p.dt_dem * p.coupling_interval;
  t << "  coupling interval dt_c            " << fmt("%8.3g", r.dt_couple) << " s ("
    << p.coupling_interval << " DEM steps)\n";
  if (r.tau_p > 0) {
    r.solid_fluid_ratio = r.dt_couple / r.tau_p;
    const bool semi = p.coupled && p.semi_implicit;
    t << "  solid-fluid  dt_c / tau_p         " << fmt("%8.3g", r.solid_fluid_ratio)
      << (semi ? "   (semi-implicit drag: accurate <= 1)\n" : "   (stable < 2, accurate <= 1)\n");
    if (!semi && r.solid_fluid_ratio >= 2.0) {
      r.errors.push_back("coupling interval breaks the solid-fluid criterion: dt_c/tau_p = " +
                         fmt("%.3g", r.solid_fluid_ratio) +
                         " >= 2 (reduce the coupling interval or use exchange semiImplicit)");
    } else if (r.solid_fluid_ratio > 1.0) {
      r.warnings.push_back("dt_c/tau_p above 1: the lagged part of the load is under-resolved");
    }
  }
  if (p.coupled && r.tau_p > 0 && p.h_sphere > 0 && p.d_min > 0) report_exchange_gain(p, r, t);
  if (p.h_sphere > 0) {
    r.particle_cfl = p.v_particle * r.dt_couple / p.h_sphere;
    t << "  fluid-solid  v_p dt_c / h         " << fmt("%8.3g", r.particle_cfl)
      << "   (accurate <= 0.5, max 1)\n";
    if (r.particle_cfl > 1.0) {
      r.errors.push_back("coupling interval breaks the fluid-solid criterion: spheres move " +
                         fmt("%.3g", r.particle_cfl) + " cells per coupling interval (> 1)");
    } else if (r.particle_cfl > 0.5) {
      r.warnings.push_back("spheres move more than half a cell per coupling interval");
    }
  }
}

// estimated cost of the run on one core
void report_cost(const RunParameters& p, Report& r, std::ostringstream& t) {
  r.est_cost_s = double(p.n_cells) * p.n_iterations * p.cost_per_cell_iter *
                 std::max(1, p.n_correctors);
  t << "  cells " << p.n_cells << ", " << (p.steady ? "max iterations " : "time steps ")
    << fmt("%.4g", p.n_iterations) << ": estimated cost " << fmt("%.3g", r.est_cost_s)
    << " s on one core" << (p.steady ? " (upper bound)" : "") << '\n';
}

}  // namespace

Report make_report(const RunParameters& p) {
  Report r;
  std::ostringstream t;
  t << "hsrod resolved-run report (SI units)\n";
  if (p.h_sphere > 0 && p.d_min > 0) report_resolution(p, r, t);
  if (p.h_sphere > 0 && p.dt > 0) report_time_step(p, r, t);
  if (p.nu > 0 && p.d_min > 0) {
    r.reynolds = p.u_ref * p.d_min / p.nu;
    t << "  particle Reynolds number U d/nu  " << fmt("%8.3g", r.reynolds) << '\n';
  }
  if (p.rho_p > 0 && p.rho_f > 0 && p.nu > 0) report_particle_response(p, r, t);
  if (p.dt_dem > 0 && p.coupling_interval > 0) report_coupling(p, r, t);
  if (p.n_cells > 0 && p.n_iterations > 0 && p.cost_per_cell_iter > 0) report_cost(p, r, t);
  for (const auto& w : r.warnings) t << "  WARNING: " << w << '\n';
  for (const auto& e : r.errors) t << "  ERROR: " << e << '\n';
  r.text = t.str();
  return r;
}

}  // namespace hsrod::calib

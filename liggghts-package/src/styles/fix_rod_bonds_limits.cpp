/* ----------------------------------------------------------------------
   hsrod - fix rod/bonds: the explicit stability limits of the rod's bonds
   (rod/stability_limits.h), printed once and checked against the timestep.
   See fix_rod_bonds.h.
------------------------------------------------------------------------- */

#include "fix_rod_bonds.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "update.h"

#include "common/math_constants.h"
#include "rod/rod_layout.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>

using namespace LAMMPS_NS;

void FixRodBonds::ensure_limits(double d, double density, bool damped) {
  // The limits depend only on the spheres and the material: computed once
  // and reused by later runs (the damped limit takes an eigen-bisection).
  if (d == limits_diameter_ && density == limits_density_ && (limits_.damping_included || !damped)) return;
  hsrod::RodSpec chain;
  chain.number_of_sections = 20;  // omega_max of a chain has converged by 20 spheres
  chain.sphere_diameter = d;
  const hsrod::BeamBondMaterial bond = bond_set_.material(0.5 * d, 0.5 * d);
  try {
    limits_ = hsrod::compute_stability_limits(hsrod::make_rod_layout(chain),
                                              {d, density, bond_set_.youngs_modulus, bond_set_.poisson_ratio}, bond,
                                              0.0, damped);
  } catch (const std::exception &e) {
    error->all(FLERR, (std::string("fix rod/bonds: ") + e.what()).c_str());
  }
  limits_diameter_ = d;
  limits_density_ = density;
}

double FixRodBonds::explicit_bond_limit() {
  if (limits_diameter_ > 0.0 && !limits_.damping_included) {
    ensure_limits(limits_diameter_, limits_density_, true);
    explicit_limit_ = limits_.explicit_bond_limit;
  }
  return explicit_limit_;
}

void FixRodBonds::compute_stability_limits() {
  // The stiffest, lightest sphere of the group bounds the explicit step.
  double dmin = 1e300, mass_min = 1e300;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    dmin = std::min(dmin, 2.0 * atom->radius[i]);
    mass_min = std::min(mass_min, atom->rmass[i]);
  }
  double local[2] = {dmin, mass_min}, global[2];
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MIN, world);
  if (global[0] > 1e299) {
    explicit_limit_ = 0.0;
    return;
  }
  const double d = global[0];
  const double density = global[1] / (hsrod::kPi * d * d * d / 6.0);

  // Under fix rod/implicit the explicit limit does not bind: the damping's
  // reduction (an eigen-bisection) is left to explicit_bond_limit().
  ensure_limits(d, density, !integrated_implicitly_);
  const hsrod::RodStabilityLimits &limits = limits_;
  explicit_limit_ = limits.explicit_bond_limit;  // includes the bond damping

  if (comm->me == 0 && !limits_printed_) {
    const std::string table = limits.table(update->dt);
    char head[256];
    std::snprintf(head, sizeof(head),
                  "fix rod/bonds %s: stability limits for d = %g m, rho = %g kg/m3, E = %g Pa "
                  "(timestep %g s, explicit limit %s %g s)\n",
                  id, d, density, bond_set_.youngs_modulus, update->dt,
                  limits.damping_included ? "with damping" : "without the bond damping's reduction", explicit_limit_);
    if (screen) fprintf(screen, "%s%s", head, table.c_str());
    if (logfile) fprintf(logfile, "%s%s", head, table.c_str());
    limits_printed_ = true;
  }
  const bool first_report = !limits_reported_;
  limits_reported_ = true;
  if (integrated_implicitly_) {
    if (first_report && comm->me == 0 && screen)
      fprintf(screen, "fix rod/bonds %s: bonds integrated implicitly (fix rod/implicit): the explicit limits above do "
                      "not bind this run\n", id);
    return;
  }
  if (update->dt > 0.2 * limits.rayleigh_time && comm->me == 0 && first_report) {
    char msg[256];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/bonds: timestep %g s exceeds 20%% of the Rayleigh time %g s; Hertz contacts "
                  "may be inaccurate", update->dt, limits.rayleigh_time);
    error->warning(FLERR, msg);
  }
  if (timestep_check_ && update->dt > explicit_limit_) {
    char msg[512];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/bonds: timestep %g s exceeds the explicit stability limit %g s of the rod's "
                  "bonds (2/omega_max, E = %g Pa, d = %g m); reduce the timestep or set "
                  "'timestep_check no' to run anyway", update->dt, explicit_limit_, bond_set_.youngs_modulus, d);
    error->all(FLERR, msg);
  }
}


// hsrod calibration: the DEM side of the resolved CFD-DEM coupling.
//
// Drives a LIGGGHTS instance (Debian's libliggghts, same Open MPI) through
// its own CFD coupling interface, as CFDEMcoupling's resolved solvers do:
// the input script must define
//     fix cfd  all couple/cfd couple_every <N> mpi
//     fix cfd2 all couple/cfd/force transfer_torque yes            (explicit)
// or, for the semi-implicit exchange (momentum_exchange.h),
//     fix cfd2 all couple/cfd/force/implicit transfer_torque yes
//     fix cfd3 all couple/cfd/torque/implicit                      (hsrod)
// (library_cfd_coupling.h: data_liggghts_to_of / data_of_to_liggghts).
// When built with the hsrod LIGGGHTS package (HSROD_DEM_WITH_PACKAGE) the
// instance gets the package's styles (create_rod, fix rod/bonds, ...) by the
// same run-time registration as the `hsrod` executable.
// Every coupling interval the CFD side calls run(N), pull() to read the
// spheres (x, v, omega, radius by atom tag) into a SphereSet and, after the
// fluid step, push() to hand the hydrodynamic force/torque to LIGGGHTS,
// which applies them during the next N DEM steps.
//
// Header free of LIGGGHTS and OpenFOAM types (pimpl) so that it can be
// included next to fvCFD.H (LIGGGHTS' Pair vs Foam::Pair).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "momentum_exchange.h"
#include "sphere_set.h"

namespace hsrod::calib {

class DemCoupling {
 public:
  // comm: an MPI_Comm passed as its integer/handle value (MPI must be
  // initialised). script: LIGGGHTS input file run once at start.
  DemCoupling(void* mpi_comm, const std::string& script, bool echo_screen);
  ~DemCoupling();
  DemCoupling(const DemCoupling&) = delete;
  DemCoupling& operator=(const DemCoupling&) = delete;

  double timestep() const;                 // DEM time step [s]
  long natoms() const;                     // number of atoms (spheres)
  void run(int nsteps);                    // advance the DEM by nsteps
  // Replace the spheres of `set` by the current DEM atoms (ordered by tag),
  // with their molecule (rod) IDs when the atom style has them.
  void pull(SphereSet& set);
  // Hand the loads to LIGGGHTS. Only one rank may contribute (the data are
  // summed over ranks): pass contribute=false elsewhere. semi_implicit: also
  // Ksl, uf and KslRotation (needs fix couple/cfd/force/implicit).
  void push(const std::vector<DemLoad>& loads, bool contribute, bool semi_implicit);
  // Smallest and largest particle density rmass / (pi d^3/6) [kg/m^3].
  std::pair<double, double> density_range() const;
  // Virtual mass: rmass += coeff rho_f pi d^3/6 on every atom [kg]. Call once,
  // before the first run (the DEM then integrates with m_p + m_v).
  void add_virtual_mass(double coeff, double rho_f);
  // Number of fixes of exactly this style in the DEM input (e.g.
  // "couple/cfd/force/implicit"), to check the input against the exchange.
  int count_fix_style(const std::string& style) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hsrod::calib

// hsrod calibration: the DEM side of the resolved CFD-DEM coupling.
//
// Drives a LIGGGHTS instance (Debian's libliggghts, same Open MPI) through
// its own CFD coupling interface, as CFDEMcoupling's resolved solvers do:
// the input script must define
//     fix cfd  all couple/cfd couple_every <N> mpi
//     fix cfd2 all couple/cfd/force transfer_torque yes
// (library_cfd_coupling.h: data_liggghts_to_of / data_of_to_liggghts).
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
#include <vector>

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
  // Replace the spheres of `set` by the current DEM atoms (ordered by tag).
  void pull(SphereSet& set);
  // Hand the loads of `set` to LIGGGHTS. Only one rank may contribute
  // (the data are summed over ranks): pass contribute=false elsewhere.
  void push(const SphereSet& set, bool contribute);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hsrod::calib

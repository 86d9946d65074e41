// hsrod calibration: DEM side of the coupling (see dem_coupling.h).
// LIGGGHTS code only: no OpenFOAM header may be included here.
#include "dem_coupling.h"

#include <mpi.h>

#include <liggghts/input.h>
#include <liggghts/lammps.h>
#include <liggghts/library_cfd_coupling.h>
#include <liggghts/update.h>
#include <liggghts/atom.h>

#include <cstring>
#include <sstream>
#include <stdexcept>

namespace hsrod::calib {

struct DemCoupling::Impl {
  LAMMPS_NS::LAMMPS* lmp = nullptr;
  std::vector<std::string> args;
  std::vector<char*> argv;
  // exchange buffers, grown by LIGGGHTS' memory manager on every call
  double **x = nullptr, **v = nullptr, **om = nullptr, **rad = nullptr;
  double **f = nullptr, **t = nullptr;
};

DemCoupling::DemCoupling(void* mpi_comm, const std::string& script, bool echo_screen)
    : impl_(new Impl) {
  // LAMMPS gets its own argv (never OpenFOAM's)
  impl_->args = {"liggghts", "-log", "log.liggghts"};
  if (!echo_screen) {
    impl_->args.push_back("-screen");
    impl_->args.push_back("none");
  }
  for (auto& a : impl_->args) impl_->argv.push_back(a.data());
  MPI_Comm comm = *static_cast<MPI_Comm*>(mpi_comm);
  impl_->lmp = new LAMMPS_NS::LAMMPS(static_cast<int>(impl_->argv.size()), impl_->argv.data(), comm);
  impl_->lmp->input->file(script.c_str());
  locate_coupling_fix(impl_->lmp);  // errors out (LIGGGHTS) without fix couple/cfd
}

DemCoupling::~DemCoupling() { delete impl_->lmp; }

double DemCoupling::timestep() const { return impl_->lmp->update->dt; }

long DemCoupling::natoms() const { return static_cast<long>(impl_->lmp->atom->natoms); }

void DemCoupling::run(int nsteps) {
  std::ostringstream cmd;
  cmd << "run " << nsteps << (impl_->lmp->update->ntimestep > 0 ? " pre no post no" : "");
  impl_->lmp->input->one(cmd.str().c_str());
}

void DemCoupling::pull(SphereSet& set) {
  void* lmp = impl_->lmp;
  double**& x = impl_->x;
  double**& v = impl_->v;
  double**& om = impl_->om;
  double**& rad = impl_->rad;
  allocate_external_double(x, 3, "nparticles", 0.0, lmp);
  allocate_external_double(v, 3, "nparticles", 0.0, lmp);
  allocate_external_double(om, 3, "nparticles", 0.0, lmp);
  allocate_external_double(rad, 1, "nparticles", 0.0, lmp);
  data_liggghts_to_of("x", "vector-atom", lmp, reinterpret_cast<void*&>(x), "double");
  data_liggghts_to_of("v", "vector-atom", lmp, reinterpret_cast<void*&>(v), "double");
  data_liggghts_to_of("omega", "vector-atom", lmp, reinterpret_cast<void*&>(om), "double");
  data_liggghts_to_of("radius", "scalar-atom", lmp, reinterpret_cast<void*&>(rad), "double");
  const int n = liggghts_get_maxtag(lmp);
  std::vector<Sphere> spheres;
  for (int i = 0; i < n; ++i) {
    if (!(rad[i][0] > 0.0)) continue;  // tag not in use
    Sphere s;
    s.id = i + 1;
    s.d = 2.0 * rad[i][0];
    for (int k = 0; k < 3; ++k) {
      s.x[k] = x[i][k];
      s.v[k] = v[i][k];
      s.omega[k] = om[i][k];
    }
    spheres.push_back(s);
  }
  set.set_spheres(std::move(spheres));
}

void DemCoupling::push(const SphereSet& set, bool contribute) {
  void* lmp = impl_->lmp;
  double**& f = impl_->f;
  double**& t = impl_->t;
  allocate_external_double(f, 3, "nparticles", 0.0, lmp);
  allocate_external_double(t, 3, "nparticles", 0.0, lmp);
  const int n = liggghts_get_maxtag(lmp);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) f[i][k] = t[i][k] = 0.0;
  if (contribute) {
    for (const auto& s : set.spheres()) {
      if (s.id < 1 || s.id > n) throw std::runtime_error("sphere id outside the DEM tag range");
      for (int k = 0; k < 3; ++k) {
        f[s.id - 1][k] = s.force[k];
        t[s.id - 1][k] = s.torque[k];
      }
    }
  }
  data_of_to_liggghts("dragforce", "vector-atom", lmp, f, "double");
  data_of_to_liggghts("hdtorque", "vector-atom", lmp, t, "double");
}

}  // namespace hsrod::calib

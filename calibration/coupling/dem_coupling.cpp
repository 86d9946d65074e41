// hsrod calibration: DEM side of the coupling (see dem_coupling.h).
// LIGGGHTS code only: no OpenFOAM header may be included here.
#include "common/math_constants.h"
#include "dem_coupling.h"

#include <mpi.h>

#include <liggghts/input.h>
#include <liggghts/lammps.h>
#include <liggghts/library_cfd_coupling.h>
#include <liggghts/modify.h>
#include <liggghts/update.h>
#include <liggghts/atom.h>

#ifdef HSROD_DEM_WITH_PACKAGE
#include "style_registration.h"  // liggghts-package: create_rod, fix rod/bonds, ...
#endif

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
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
  double **ksl = nullptr, **uf = nullptr, **krot = nullptr;
};

namespace {
using hsrod::kPi;
}

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
#ifdef HSROD_DEM_WITH_PACKAGE
  hsrod::register_styles(impl_->lmp);  // as the hsrod executable does (main.cpp)
#endif
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
  // molecule (rod) IDs by tag: not part of the coupling interface, read
  // from the atoms directly (same process) and summed over ranks
  std::vector<long> mol(n, 0);
  LAMMPS_NS::Atom* atom = impl_->lmp->atom;
  if (atom->molecule_flag && atom->molecule) {
    for (int i = 0; i < atom->nlocal; ++i) {
      const int tag = atom->tag[i];
      if (tag >= 1 && tag <= n) mol[tag - 1] = atom->molecule[i];
    }
    MPI_Allreduce(MPI_IN_PLACE, mol.data(), n, MPI_LONG, MPI_SUM, impl_->lmp->world);
  }
  std::vector<Sphere> spheres;
  for (int i = 0; i < n; ++i) {
    if (!(rad[i][0] > 0.0)) continue;  // tag not in use
    Sphere s;
    s.id = i + 1;
    s.d = 2.0 * rad[i][0];
    s.mol = mol[i];
    for (int k = 0; k < 3; ++k) {
      s.x[k] = x[i][k];
      s.v[k] = v[i][k];
      s.omega[k] = om[i][k];
    }
    spheres.push_back(s);
  }
  set.set_spheres(std::move(spheres));
}

void DemCoupling::push(const std::vector<DemLoad>& loads, bool contribute, bool semi_implicit) {
  void* lmp = impl_->lmp;
  Impl& m = *impl_;
  allocate_external_double(m.f, 3, "nparticles", 0.0, lmp);
  allocate_external_double(m.t, 3, "nparticles", 0.0, lmp);
  if (semi_implicit) {
    allocate_external_double(m.ksl, 1, "nparticles", 0.0, lmp);
    allocate_external_double(m.uf, 3, "nparticles", 0.0, lmp);
    allocate_external_double(m.krot, 3, "nparticles", 0.0, lmp);
  }
  const int n = liggghts_get_maxtag(lmp);
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      m.f[i][k] = m.t[i][k] = 0.0;
      if (semi_implicit) m.uf[i][k] = m.krot[i][k] = 0.0;
    }
    if (semi_implicit) m.ksl[i][0] = 0.0;
  }
  if (contribute) {
    for (const auto& l : loads) {
      if (l.id < 1 || l.id > n) throw std::runtime_error("sphere id outside the DEM tag range");
      const long i = l.id - 1;
      for (int k = 0; k < 3; ++k) {
        m.f[i][k] = l.force[k];
        m.t[i][k] = l.torque[k];
        if (semi_implicit) {
          m.uf[i][k] = l.uf[k];
          m.krot[i][k] = l.krot[k];
        }
      }
      if (semi_implicit) m.ksl[i][0] = l.ksl;
    }
  }
  data_of_to_liggghts("dragforce", "vector-atom", lmp, m.f, "double");
  data_of_to_liggghts("hdtorque", "vector-atom", lmp, m.t, "double");
  if (semi_implicit) {
    data_of_to_liggghts("Ksl", "scalar-atom", lmp, m.ksl, "double");
    data_of_to_liggghts("uf", "vector-atom", lmp, m.uf, "double");
    data_of_to_liggghts("KslRotation", "vector-atom", lmp, m.krot, "double");
  }
}

int DemCoupling::count_fix_style(const std::string& style) const {
  std::vector<char> name(style.begin(), style.end());
  name.push_back('\0');
  return impl_->lmp->modify->n_fixes_style_strict(name.data());
}

std::pair<double, double> DemCoupling::density_range() const {
  LAMMPS_NS::Atom* atom = impl_->lmp->atom;
  double lo = std::numeric_limits<double>::max(), hi = 0.0;
  if (atom->rmass && atom->radius) {
    for (int i = 0; i < atom->nlocal; ++i) {
      const double r = atom->radius[i];
      const double rho = atom->rmass[i] / (4.0 / 3.0 * kPi * r * r * r);
      lo = std::min(lo, rho);
      hi = std::max(hi, rho);
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, &lo, 1, MPI_DOUBLE, MPI_MIN, impl_->lmp->world);
  MPI_Allreduce(MPI_IN_PLACE, &hi, 1, MPI_DOUBLE, MPI_MAX, impl_->lmp->world);
  return {lo, hi};
}

void DemCoupling::add_virtual_mass(double coeff, double rho_f) {
  LAMMPS_NS::Atom* atom = impl_->lmp->atom;
  if (!atom->rmass || !atom->radius)
    throw std::runtime_error("virtual mass needs per-atom rmass and radius (atom_style granular)");
  for (int i = 0; i < atom->nlocal; ++i) {
    const double r = atom->radius[i];
    atom->rmass[i] += coeff * rho_f * 4.0 / 3.0 * kPi * r * r * r;
  }
}

}  // namespace hsrod::calib

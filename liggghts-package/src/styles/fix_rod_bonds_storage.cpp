/* ----------------------------------------------------------------------
   hsrod - fix rod/bonds: per-atom orientations and bond rest states (they
   migrate with the atoms, go into restart files and, for orientations, to
   ghost atoms), and their reading for rod gathers. See fix_rod_bonds.h.
------------------------------------------------------------------------- */

#include "fix_rod_bonds.h"
#include "quaternion_storage.h"

#include "atom.h"
#include "memory.h"

#include <cstring>

using namespace LAMMPS_NS;

namespace {
using hsrod_glue::store_quaternion;
using hsrod_glue::to_quaternion;
}  // namespace

Eigen::Quaterniond FixRodBonds::orientation(int i) const { return to_quaternion(orientation_[i]); }

void FixRodBonds::set_orientation(int i, const Eigen::Quaterniond &q) { store_quaternion(q.normalized(), orientation_[i]); }

void FixRodBonds::rest_states(int i, std::vector<GatheredBond> &out) const {
  out.clear();
  const BondRestRecord *rec = records(i);
  // Each record kept matches a distinct bond of the topology (one record
  // per partner), so once the sphere's bonds are all found the remaining
  // slots hold only broken bonds' records: not reading them spares up to 7
  // cache lines per sphere and step (the slots fill from the first).
  const int bonds = atom->num_bond[i];
  for (int r = 0; r < max_bonds_per_sphere && static_cast<int>(out.size()) < bonds; r++) {
    if (rec[r].partner_tag == 0.0) continue;
    // Only bonds that are still in the topology.
    bool present = false;
    for (int m = 0; m < atom->num_bond[i]; m++)
      if (atom->bond_atom[i][m] == static_cast<int>(rec[r].partner_tag)) present = true;
    if (!present) continue;
    out.push_back({static_cast<int>(rec[r].partner_tag),
                   Eigen::Vector3d(rec[r].rest_vector[0], rec[r].rest_vector[1], rec[r].rest_vector[2]),
                   to_quaternion(rec[r].rest_rotation)});
  }
}

/* ---------------------------------------------------------------------- per-atom data */

void FixRodBonds::reset_atom(int i) {
  store_quaternion(Eigen::Quaterniond::Identity(), orientation_[i]);
  for (int a = 0; a < max_bonds_per_sphere * record_doubles; a++) bond_rest_[i][a] = 0.0;
}

void FixRodBonds::grow_arrays(int nmax) {
  memory->grow(orientation_, nmax, 4, "rod/bonds:orientation");
  memory->grow(bond_rest_, nmax, max_bonds_per_sphere * record_doubles, "rod/bonds:bond_rest");
}

void FixRodBonds::copy_arrays(int i, int j, int) {
  std::memcpy(orientation_[j], orientation_[i], 4 * sizeof(double));
  std::memcpy(bond_rest_[j], bond_rest_[i], max_bonds_per_sphere * record_doubles * sizeof(double));
}

void FixRodBonds::set_arrays(int i) { reset_atom(i); }

int FixRodBonds::pack_exchange(int i, double *buf) {
  std::memcpy(buf, orientation_[i], 4 * sizeof(double));
  std::memcpy(buf + 4, bond_rest_[i], max_bonds_per_sphere * record_doubles * sizeof(double));
  return peratom_doubles;
}

int FixRodBonds::unpack_exchange(int nlocal, double *buf) {
  std::memcpy(orientation_[nlocal], buf, 4 * sizeof(double));
  std::memcpy(bond_rest_[nlocal], buf + 4, max_bonds_per_sphere * record_doubles * sizeof(double));
  return peratom_doubles;
}

int FixRodBonds::pack_restart(int i, double *buf) {
  buf[0] = peratom_doubles + 1;
  pack_exchange(i, buf + 1);
  return peratom_doubles + 1;
}

void FixRodBonds::unpack_restart(int nlocal, int nth) {
  double **extra = atom->extra;
  // Skip the data of the fixes stored before this one.
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  unpack_exchange(nlocal, &extra[nlocal][m]);
}

int FixRodBonds::size_restart(int) { return peratom_doubles + 1; }

int FixRodBonds::maxsize_restart() { return peratom_doubles + 1; }

int FixRodBonds::pack_comm(int n, int *list, double *buf, int, int *) {
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int j = list[k];
    for (int a = 0; a < 4; a++) buf[m++] = orientation_[j][a];
  }
  return 4;  // LIGGGHTS' Comm expects datums per atom, not the total
}

void FixRodBonds::unpack_comm(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int a = 0; a < 4; a++) orientation_[i][a] = buf[m++];
}

double FixRodBonds::memory_usage() { return static_cast<double>(atom->nmax) * peratom_doubles * sizeof(double); }

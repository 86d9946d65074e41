#include "rod_gather.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"

#include <mpi.h>

#include <algorithm>
#include <set>

using namespace LAMMPS_NS;

namespace {
// Flat record: tag mol x3 v3 w3 f3 t3 radius mass q4 nbonds, then per bond: partner rest3 q4.
const int kFixed = 2 + 5 * 3 + 2 + 4 + 1;
const int kPerBond = 1 + 3 + 4;
}  // namespace

void RodGather::size_rods() {
  for (auto it = rods.begin(); it != rods.end();) {
    const auto count = fill_.find(it->first);
    if (count == fill_.end() || count->second == 0) it = rods.erase(it);
    else ++it;
  }
  for (auto it = fill_.begin(); it != fill_.end();) {
    if (it->second == 0) {
      it = fill_.erase(it);
      continue;
    }
    rods[it->first].resize(it->second);
    it->second = 0;
    ++it;
  }
}

void RodGather::sort_rods() {
  const auto by_tag = [](const GatheredSphere &a, const GatheredSphere &b) { return a.tag < b.tag; };
  for (auto &entry : rods)
    if (!std::is_sorted(entry.second.begin(), entry.second.end(), by_tag))
      std::sort(entry.second.begin(), entry.second.end(), by_tag);
}

// On one process the records are this process's spheres: copied straight
// from the atom arrays into the rods, in the order (and with the values:
// tags, molecules and quaternions pass a double exactly) of the flat
// records that several processes exchange, without writing and re-reading
// those (a pass over ~300 bytes per sphere and step).
void RodGather::gather_serial(int groupbit, const RodBondRecords *bond_fix) {
  for (auto &entry : fill_) entry.second = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && atom->molecule[i] > 0) ++fill_[atom->molecule[i]];
  size_rods();
  int last_molecule = 0;
  std::vector<GatheredSphere> *rod = nullptr;
  int *filled = nullptr;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || atom->molecule[i] <= 0) continue;
    const int molecule = atom->molecule[i];
    if (!rod || molecule != last_molecule) {
      rod = &rods[molecule];
      filled = &fill_[molecule];
      last_molecule = molecule;
    }
    GatheredSphere &s = (*rod)[(*filled)++];
    double unwrapped[3];
    domain->unmap(atom->x[i], atom->image[i], unwrapped);
    s.tag = atom->tag[i];
    s.molecule = molecule;
    s.position = Eigen::Vector3d(unwrapped[0], unwrapped[1], unwrapped[2]);
    s.velocity = Eigen::Vector3d(atom->v[i][0], atom->v[i][1], atom->v[i][2]);
    s.angular_velocity = Eigen::Vector3d(atom->omega[i][0], atom->omega[i][1], atom->omega[i][2]);
    s.force = Eigen::Vector3d(atom->f[i][0], atom->f[i][1], atom->f[i][2]);
    s.torque = Eigen::Vector3d(atom->torque[i][0], atom->torque[i][1], atom->torque[i][2]);
    s.radius = atom->radius[i];
    s.mass = atom->rmass[i];
    if (bond_fix) {
      s.orientation = bond_fix->orientation(i);
      bond_fix->rest_states(i, s.bonds);
    } else {
      s.orientation = Eigen::Quaterniond::Identity();
      s.bonds.clear();
    }
  }
  sort_rods();
}

void RodGather::gather(int groupbit, const RodBondRecords *bond_fix) {
  // Every buffer here is a member that keeps its memory: a rod step
  // gathers every timestep, and re-allocating the records, the rods'
  // vectors and each sphere's bond list cost more than the copying.
  if (comm->nprocs == 1) {
    gather_serial(groupbit, bond_fix);
    return;
  }
  std::vector<double> &mine = send_;
  mine.clear();
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || atom->molecule[i] <= 0) continue;
    double unwrapped[3];
    domain->unmap(atom->x[i], atom->image[i], unwrapped);
    mine.push_back(atom->tag[i]);
    mine.push_back(atom->molecule[i]);
    for (int a = 0; a < 3; a++) mine.push_back(unwrapped[a]);
    for (int a = 0; a < 3; a++) mine.push_back(atom->v[i][a]);
    for (int a = 0; a < 3; a++) mine.push_back(atom->omega[i][a]);
    for (int a = 0; a < 3; a++) mine.push_back(atom->f[i][a]);
    for (int a = 0; a < 3; a++) mine.push_back(atom->torque[i][a]);
    mine.push_back(atom->radius[i]);
    mine.push_back(atom->rmass[i]);
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
    bond_scratch_.clear();
    if (bond_fix) {
      q = bond_fix->orientation(i);
      bond_fix->rest_states(i, bond_scratch_);
    }
    mine.push_back(q.w());
    mine.push_back(q.x());
    mine.push_back(q.y());
    mine.push_back(q.z());
    mine.push_back(static_cast<double>(bond_scratch_.size()));
    for (const auto &b : bond_scratch_) {
      mine.push_back(b.partner_tag);
      for (int a = 0; a < 3; a++) mine.push_back(b.rest_vector[a]);
      mine.push_back(b.rest_rotation.w());
      mine.push_back(b.rest_rotation.x());
      mine.push_back(b.rest_rotation.y());
      mine.push_back(b.rest_rotation.z());
    }
  }
  allgather_into(world, comm->nprocs, mine, received_, counts_, displs_);
  const std::vector<double> &all = received_;
  const int total = static_cast<int>(all.size());

  // Spheres per rod, then each rod's vector sized to them (its elements,
  // with their bond lists' memory, are reused from the last gather).
  for (auto &entry : fill_) entry.second = 0;
  for (int m = 0; m < total;) {
    ++fill_[static_cast<int>(all[m + 1])];
    m += kFixed + kPerBond * static_cast<int>(all[m + kFixed - 1]);
  }
  size_rods();

  int last_molecule = 0;
  std::vector<GatheredSphere> *rod = nullptr;
  int *filled = nullptr;
  for (int m = 0; m < total;) {
    const int molecule = static_cast<int>(all[m + 1]);
    if (!rod || molecule != last_molecule) {
      rod = &rods[molecule];
      filled = &fill_[molecule];
      last_molecule = molecule;
    }
    GatheredSphere &s = (*rod)[(*filled)++];
    s.tag = static_cast<int>(all[m]);
    s.molecule = molecule;
    const double *p = &all[m + 2];
    s.position = Eigen::Vector3d(p[0], p[1], p[2]);
    s.velocity = Eigen::Vector3d(p[3], p[4], p[5]);
    s.angular_velocity = Eigen::Vector3d(p[6], p[7], p[8]);
    s.force = Eigen::Vector3d(p[9], p[10], p[11]);
    s.torque = Eigen::Vector3d(p[12], p[13], p[14]);
    s.radius = p[15];
    s.mass = p[16];
    s.orientation = Eigen::Quaterniond(p[17], p[18], p[19], p[20]);
    const int nb = static_cast<int>(p[21]);
    m += kFixed;
    s.bonds.clear();
    for (int b = 0; b < nb; b++, m += kPerBond) {
      const double *r = &all[m];
      s.bonds.push_back({static_cast<int>(r[0]), Eigen::Vector3d(r[1], r[2], r[3]),
                         Eigen::Quaterniond(r[4], r[5], r[6], r[7])});
    }
  }
  sort_rods();
}

std::vector<int> RodGather::rod_ids(int groupbit) {
  std::set<int> local;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && atom->molecule[i] > 0) local.insert(atom->molecule[i]);
  const std::vector<int> all = allgather_all(world, comm->nprocs, std::vector<int>(local.begin(), local.end()));
  const std::set<int> unique(all.begin(), all.end());
  return std::vector<int>(unique.begin(), unique.end());
}

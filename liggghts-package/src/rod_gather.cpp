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

void RodGather::gather(int groupbit, const RodBondRecords *bond_fix) {
  rods.clear();
  std::vector<double> mine;
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
    std::vector<GatheredBond> bonds;
    if (bond_fix) {
      q = bond_fix->orientation(i);
      bonds = bond_fix->rest_states(i);
    }
    mine.push_back(q.w());
    mine.push_back(q.x());
    mine.push_back(q.y());
    mine.push_back(q.z());
    mine.push_back(static_cast<double>(bonds.size()));
    for (const auto &b : bonds) {
      mine.push_back(b.partner_tag);
      for (int a = 0; a < 3; a++) mine.push_back(b.rest_vector[a]);
      mine.push_back(b.rest_rotation.w());
      mine.push_back(b.rest_rotation.x());
      mine.push_back(b.rest_rotation.y());
      mine.push_back(b.rest_rotation.z());
    }
  }
  const std::vector<double> all = allgather_all(world, comm->nprocs, mine);
  const int total = static_cast<int>(all.size());

  for (int m = 0; m < total;) {
    GatheredSphere s;
    s.tag = static_cast<int>(all[m]);
    s.molecule = static_cast<int>(all[m + 1]);
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
    for (int b = 0; b < nb; b++, m += kPerBond) {
      const double *r = &all[m];
      s.bonds.push_back({static_cast<int>(r[0]), Eigen::Vector3d(r[1], r[2], r[3]),
                         Eigen::Quaterniond(r[4], r[5], r[6], r[7])});
    }
    rods[s.molecule].push_back(s);
  }
  for (auto &rod : rods)
    std::sort(rod.second.begin(), rod.second.end(),
              [](const GatheredSphere &a, const GatheredSphere &b) { return a.tag < b.tag; });
}

std::vector<int> RodGather::rod_ids(int groupbit) {
  std::set<int> local;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && atom->molecule[i] > 0) local.insert(atom->molecule[i]);
  const std::vector<int> all = allgather_all(world, comm->nprocs, std::vector<int>(local.begin(), local.end()));
  const std::set<int> unique(all.begin(), all.end());
  return std::vector<int>(unique.begin(), unique.end());
}

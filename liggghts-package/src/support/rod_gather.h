/* ----------------------------------------------------------------------
   hsrod - gathers whole rods (all spheres of each molecule in a group) on
   every processor, for the styles that need a rod at once (shape measures,
   non-local drag, the implicit rod step). Every proc receives the same data
   in the same order, so work done on it is identical on all procs and a
   run on N ranks matches a serial one.
------------------------------------------------------------------------- */

#ifndef HSROD_ROD_GATHER_H
#define HSROD_ROD_GATHER_H

#include "pointers.h"
#include "rod_bond_records.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <mpi.h>

#include <algorithm>
#include <map>
#include <vector>

namespace LAMMPS_NS {


struct GatheredSphere {
  int tag = 0, molecule = 0;
  Eigen::Vector3d position;             // unwrapped [m]
  Eigen::Vector3d velocity, angular_velocity;  // [m/s], [rad/s]
  Eigen::Vector3d force, torque;        // as currently accumulated in f, torque [N], [N m]
  double radius = 0.0, mass = 0.0;      // [m], [kg]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  std::vector<GatheredBond> bonds;      // bonds stored on this sphere (with `bonds` fix only)
};

// Concatenation of every proc's `mine`, in rank order, on every proc.
template <typename T>
std::vector<T> allgather_all(MPI_Comm world, int nprocs, const std::vector<T> &mine);
// The same into `all`, with the counts and displacements in the caller's buffers.
template <typename T>
void allgather_into(MPI_Comm world, int nprocs, const std::vector<T> &mine, std::vector<T> &all,
                    std::vector<int> &counts, std::vector<int> &displs);

class RodGather : protected Pointers {
 public:
  explicit RodGather(class LAMMPS *instance) : Pointers(instance) {}
  // Gathers the group's spheres; `bonds` (may be null; fix rod/bonds) adds
  // orientations and bond rest states. Rods are keyed by molecule ID,
  // spheres sorted by tag.
  void gather(int groupbit, const RodBondRecords *bonds);
  std::map<int, std::vector<GatheredSphere>> rods;

  // Sorted molecule IDs (> 0) of the group's spheres on all procs, the same
  // list on every proc: the rows of the per-rod computes.
  std::vector<int> rod_ids(int groupbit);

 private:
  void gather_serial(int groupbit, const RodBondRecords *bonds);
  void size_rods();  // rods sized to fill_'s counts (which are reset to 0)
  void sort_rods();
  // Kept between gathers by an owner that gathers every step (fix rod/implicit).
  std::vector<double> send_, received_;
  std::vector<int> counts_, displs_;
  std::vector<GatheredBond> bond_scratch_;
  std::map<int, int> fill_;  // spheres per rod in the current gather
};

template <typename T>
void allgather_into(MPI_Comm world, int nprocs, const std::vector<T> &mine, std::vector<T> &all,
                    std::vector<int> &counts, std::vector<int> &displs) {
  const MPI_Datatype type = sizeof(T) == sizeof(double) ? MPI_DOUBLE : MPI_INT;
  static_assert(sizeof(T) == sizeof(double) || sizeof(T) == sizeof(int), "int or double data only");
  int n = static_cast<int>(mine.size());
  counts.resize(nprocs);
  displs.assign(nprocs, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  int total = 0;
  for (int p = 0; p < nprocs; p++) {
    displs[p] = total;
    total += counts[p];
  }
  all.resize(std::max(total, 1));
  MPI_Allgatherv(mine.data(), n, type, all.data(), counts.data(), displs.data(), type, world);
  all.resize(total);
}

template <typename T>
std::vector<T> allgather_all(MPI_Comm world, int nprocs, const std::vector<T> &mine) {
  std::vector<T> all;
  std::vector<int> counts, displs;
  allgather_into(world, nprocs, mine, all, counts, displs);
  return all;
}

}  // namespace LAMMPS_NS

#endif

// Runs LIGGGHTS (with the hsrod styles) in-process for integration tests:
// commands go in as script lines, per-atom data comes out gathered by ID.
#pragma once

#include "atom.h"
#include "input.h"
#include "lammps.h"
#include "library.h"
#include "modify.h"
#include "fix.h"
#include "style_registration.h"

#include <Eigen/Core>
#include <mpi.h>

#include <cstdio>
#include <string>
#include <vector>

namespace hsrod_test {

class LiggghtsSession {
 public:
  explicit LiggghtsSession(MPI_Comm comm = MPI_COMM_WORLD, bool quiet = true) {
    std::vector<std::string> args = {"hsrod", "-log", "none"};
    if (quiet) {
      args.push_back("-screen");
      args.push_back("none");
    }
    args_ = args;
    for (auto &a : args_) argv_.push_back(&a[0]);
    lmp_ = new LAMMPS_NS::LAMMPS(static_cast<int>(argv_.size()), argv_.data(), comm);
    hsrod::register_styles(lmp_);
  }
  ~LiggghtsSession() { delete lmp_; }
  LiggghtsSession(const LiggghtsSession &) = delete;
  LiggghtsSession &operator=(const LiggghtsSession &) = delete;

  void command(const std::string &line) { lmp_->input->one(line.c_str()); }
  void commands(const std::vector<std::string> &lines) {
    for (const auto &l : lines) command(l);
  }

  int natoms() const { return static_cast<int>(lmp_->atom->natoms); }

  // Per-atom 3-vectors ("x", "v", "omega", "f") ordered by atom ID, on every rank.
  std::vector<Eigen::Vector3d> gather(const char *name) {
    const int n = natoms();
    std::vector<double> flat(3 * n);
    lammps_gather_atoms(lmp_, const_cast<char *>(name), 1, 3, flat.data());
    std::vector<Eigen::Vector3d> out(n);
    for (int i = 0; i < n; i++) out[i] = Eigen::Vector3d(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
    return out;
  }

  LAMMPS_NS::Fix *fix(const std::string &id) {
    const int k = lmp_->modify->find_fix(id.c_str());
    return k < 0 ? nullptr : lmp_->modify->fix[k];
  }

  LAMMPS_NS::LAMMPS *lammps() { return lmp_; }

 private:
  std::vector<std::string> args_;
  std::vector<char *> argv_;
  LAMMPS_NS::LAMMPS *lmp_ = nullptr;
};

// Full precision for numbers pasted into script lines (std::to_string
// would print 1e-8 as 0.000000).
inline std::string num(double value) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.17g", value);
  return buf;
}

// A small LIGGGHTS script header: SI units, spheres with bonds, a box.
inline std::vector<std::string> rod_box_header(double half_size, const std::string &boundary = "f f f",
                                               const std::string &newton = "off") {
  const std::string h = std::to_string(half_size);
  return {"units si",
          "atom_style hybrid granular molecular",
          "atom_modify map array sort 0 0",
          "boundary " + boundary,
          "newton " + newton,
          "communicate single cutoff 1e-5 vel yes",
          "region box block -" + h + " " + h + " -" + h + " " + h + " -" + h + " " + h + " units box",
          "create_box 1 box"};
}

}  // namespace hsrod_test

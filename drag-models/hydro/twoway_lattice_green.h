// The free-space response of the level-4 window lattice (hydro/twoway_window_model.h)
// between sphere footprints, tabulated once: the lattice Green's function.
//
// Away from walls the window's discrete Brinkman operator is the same
// wherever the window lies on the lattice (its uniform cells of size h
// anchored at the planform corner), so the velocity at one node caused by a
// unit force at another depends on their offset only, G_ab(x_k - x_l) for
// force component b and velocity component a. Solving a large wall-free
// window once for a unit force at one u node and one v node gives G for
// every offset within `reach`, and the footprint mobility of any rod is then
//     M_{2i+a, 2j+b} = sum_k sum_l w_ik w_jl G_ba(x_k - x_l)
// over the nodes k of sphere i's footprint and l of sphere j's, with no
// further solve. Level 4 uses it for the part of the mobility that needs
// the fine lattice (the spheres' near field) and solves a coarser window
// for the walls' reflection only (twoway_window_model.h, "two scales").
#pragma once

#include "flow/brinkman_window.h"

#include <Eigen/Core>

#include <vector>

namespace hsrod {

// One sphere's footprint on an unbounded lattice of spacing h [m] whose
// cell faces lie at anchor + k h: the MAC nodes of each component within
// Peskin's 4-point kernel of width w [m] around `centre`, their doubled
// lattice coordinates (u node (i, j): (2i, 2j + 1); v node: (2i + 1, 2j))
// and weights normalised to sum 1. With `geometry`, nodes that lie in a wall
// (as BrinkmanWindow decides) are left out before normalising.
struct LatticeFootprint {
  std::vector<Eigen::Vector2i> nodes[2];  // doubled lattice coordinates per component (0: u, 1: v)
  std::vector<double> weights[2];
};
LatticeFootprint lattice_footprint(const Eigen::Vector2d& centre, const Eigen::Vector2d& anchor, double h,
                                   double kernel_width, const ChannelGeometry* geometry = nullptr);
// Position [m] of a node given by its doubled lattice coordinates.
Eigen::Vector2d lattice_node_position(const Eigen::Vector2i& doubled, const Eigen::Vector2d& anchor, double h);

class LatticeGreenTable {
 public:
  // `free_window`: a wall-free window whose lattice has uniform cells of
  // size h with faces at multiples of h (anchor (0, 0)) at least `reach` [m]
  // around the origin; G is read for offsets up to `reach` from the unit
  // forces at the u node (0, h/2) and the v node (h/2, 0).
  LatticeGreenTable(const BrinkmanWindow& free_window, double kernel_width, double reach);

  // True if the footprints of spheres at `centres` [m] are all within reach of each other.
  bool covers(const std::vector<Eigen::Vector3d>& centres) const;
  // In-plane footprint mobility M [m/(N s)] (2n x 2n, x and y per sphere)
  // of spheres at `centres` on the lattice anchored at `anchor` [m].
  // Throws std::out_of_range if an offset exceeds the table (see covers()).
  Eigen::MatrixXd mobility(const std::vector<Eigen::Vector3d>& centres, const Eigen::Vector2d& anchor) const;
  // A sphere's footprint on this table's lattice anchored at `anchor` [m].
  LatticeFootprint footprint(const Eigen::Vector3d& centre, const Eigen::Vector2d& anchor) const {
    return lattice_footprint(centre.head<2>(), anchor, h_, kernel_width_);
  }
  // The 2 x 2 block of M: velocity at footprint i per force at footprint j.
  Eigen::Matrix2d pair(const LatticeFootprint& i, const LatticeFootprint& j) const;

 private:
  double h_ = 0.0, kernel_width_ = 0.0, reach_ = 0.0;  // h [m], w [m], largest offset tabulated [m]
  int half_ = 0;                    // doubled offsets in [-half_, half_] per axis
  std::vector<double> table_[2][2];  // [force component][velocity component], row-major over doubled offsets
};

}  // namespace hsrod

// Several rods in one scene: which rods are stepped together.
//
// The implicit step (overdamped_rod_step.h) solves one rod's spheres at once.
// Two rods that touch, or that the drag model couples hydrodynamically
// (level 3), must be solved together: a Hertz contact between two rods is
// as stiff as one with a wall (2 E* sqrt(R* delta) ~ 1 N/m against a drag
// of ~3e-8 N s/m per sphere: a relaxation time ~3e-8 s, 100x below the
// step), so treating the partner's position as given (lagged, or iterated
// rod by rod) is an explicit coupling that diverges at the implicit step,
// or converges only at a rate ~ k dt / (k dt + zeta) -> 1. The rods of a
// cluster are therefore merged into one OverdampedRod (spheres rod after
// rod, OverdampedRod::rod_of_sphere) and stepped by one solve in which the
// contact's stiffness and friction couple both rods exactly as a rod's
// self-contact couples its own spheres; a rod with no partner within reach
// is stepped alone, as before.
#pragma once

#include "dynamics/overdamped_rod_step.h"

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace hsrod {

// Groups of rods (indices into `rods`, each group ascending, groups ordered
// by their first rod) whose spheres come within `reach` [m] of each other
// (centre distance), joined transitively: rods a, b are in one group when a
// chain of rods, each within reach of the next, links them. A rod alone is
// a group of one. Found through a cell list over all spheres (O(N)).
std::vector<std::vector<int>> rod_clusters(const std::vector<std::vector<Eigen::Vector3d>>& rods, double reach);

// The buffers of the two searches here, kept by a caller that searches
// every step (no allocation of the all-sphere lists per step; the cell
// list re-sorted from the last step's order).
struct RodSearchBuffers {
  std::vector<Eigen::Vector3d> start, moved;  // all spheres: centres, displacements [m]
  std::vector<double> radius;                 // [m]
  std::vector<int> group_of;
  PairSearchCells cells;
  std::vector<std::pair<int, int>> pairs;
};
std::vector<std::vector<int>> rod_clusters(const std::vector<std::vector<Eigen::Vector3d>>& rods, double reach,
                                           RodSearchBuffers& buffers);

// Pairs (a, b), a < b, ascending, of rods with a sphere of a and one of b
// within `reach` [m] (centre distance): the neighbours each rod sees the
// disturbance of when rods are solved apart (hydro/cross_rod_disturbance.h).
// The same cell list over all spheres as rod_clusters.
std::vector<std::pair<int, int>> rods_within_reach(const std::vector<std::vector<Eigen::Vector3d>>& rods, double reach,
                                                   RodSearchBuffers& buffers);

// Groups of spheres (the rods or clusters of a step: each group's sphere
// centres at the step's start and end [m], and radii [m]) that meet within
// the step: pairs (a, b), a < b, ascending, with a sphere of a and one of b
// that come closer than the sum of their radii somewhere along their
// straight paths from start to end (closest approach of the two segments,
// so that a sphere carried through another within one step counts too).
// A step's contact set is that of its start; groups stepped apart that
// meet are to be stepped again together (contact detection within the
// step). Candidates from a cell list of the start positions with reach
// 2 r_max + 2 (largest displacement).
std::vector<std::pair<int, int>> groups_meeting_in_step(const std::vector<const std::vector<Eigen::Vector3d>*>& starts,
                                                        const std::vector<const std::vector<Eigen::Vector3d>*>& ends,
                                                        const std::vector<const std::vector<double>*>& radii);
std::vector<std::pair<int, int>> groups_meeting_in_step(const std::vector<const std::vector<Eigen::Vector3d>*>& starts,
                                                        const std::vector<const std::vector<Eigen::Vector3d>*>& ends,
                                                        const std::vector<const std::vector<double>*>& radii,
                                                        RodSearchBuffers& buffers);

// The rods as one OverdampedRod to step together: spheres rod after rod,
// bonds re-indexed, rod_of_sphere set (k for the spheres of rods[k]).
// (fix rod/implicit builds the same from the gathered spheres by tag.)
OverdampedRod merge_rods(const std::vector<OverdampedRod>& rods);

}  // namespace hsrod

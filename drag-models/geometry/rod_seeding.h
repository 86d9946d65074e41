// Seeding a suspension: where to put many straight rods in a channel
// planform so that no two overlap and none touches a wall or a cylinder.
//
// A rod of n spheres of diameter d at centre distance s is taken as the
// capsule around its axis segment (length (n - 1) s, radius d / 2): two rods
// are apart when their axis segments are at least d + min_gap apart, a rod
// is clear of the walls when every sphere centre is at least d / 2 + min_gap
// from the nearest side wall or cylinder. The capsule contains the spheres,
// so the test errs on the safe side for spheres at a spacing s > d.
//
// Layouts:
//  - random: random sequential addition (uniform centres over the region,
//    angles uniform or fixed), with a cell list so that each trial costs
//    O(1); it stops with an error when `max_trials_per_rod` trials in a row
//    fail, i.e. near the jamming limit of random sequential addition
//    (for needles much longer than thick it falls with the aspect ratio).
//  - lattice: rods at one angle on a rectangular lattice spread evenly over
//    the region (the largest pitch that holds all of them), sites that touch
//    a wall or cylinder skipped; with a jitter, each rod then moved and
//    turned at random within the jitter (seeded), redrawn until it is clear
//    of the walls and of the rods before it: a seed set of lattices whose
//    rows still arrive together.
#pragma once

#include "geometry/channel_geometry.h"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <vector>

namespace hsrod {

enum class SeedingLayout { random, lattice };

struct RodSeedingRequest {
  int rods = 1;                    // rods to place (>= 1)
  int spheres = 2;                 // spheres per rod (>= 1)
  double sphere_diameter = 0.0;    // d [m] (> 0)
  double spacing = 0.0;            // centre distance along the rod [m] (>= d; 0: d)
  double min_gap = 0.0;            // smallest surface gap rod-rod and rod-wall [m] (>= 0)
  SeedingLayout layout = SeedingLayout::random;
  std::optional<double> angle;     // in-plane angle from the y axis [rad] (create_rod's alpha); random if empty
  std::uint64_t seed = 1;          // random layout: the sequence (same seed, same rods)
  double x_min = 0.0, x_max = 0.0; // the region along x to fill [m]; both 0: the whole planform
  int max_trials_per_rod = 10000;  // failed trials in a row before giving up (random, or a jittered site)
  double jitter_position = 0.0;    // lattice: each rod moved by up to this in x and in y [m] (>= 0)
  double jitter_angle = 0.0;       // lattice: and turned by up to this [rad] (0 to pi/2)
};

struct SeededRod {
  Eigen::Vector2d centre;  // rod centre in the planform [m]
  double angle = 0.0;      // in-plane angle from the y axis [rad]: axis (sin a, cos a)
};

// Rods already in the scene, as axis segments, that seeded rods must keep
// clear of (their sphere diameter may differ).
struct RodObstacle {
  Eigen::Vector2d end_a, end_b;  // axis end points [m]
  double sphere_diameter = 0.0;  // [m]
};

// Places request.rods rods in the planform. Throws std::invalid_argument
// naming the parameter and its accepted range for bad input (counts,
// diameter, spacing, gap, a region outside the planform), and
// std::runtime_error when the rods cannot be packed (the number placed and
// the area fraction reached, against the one requested).
std::vector<SeededRod> seed_rods(const ChannelGeometry& planform, const RodSeedingRequest& request,
                                 const std::vector<RodObstacle>& existing = {});

// Area fraction of the region's fluid that `rods` rods of the request cover
// (capsule area (n - 1) s d + pi d^2 / 4 each) [-].
double rod_area_fraction(const ChannelGeometry& planform, const RodSeedingRequest& request, int rods);

// Fluid area of the request's region (side walls and cylinders excluded),
// from a 512 x 512 sample of the planform [m^2].
double region_fluid_area(const ChannelGeometry& planform, const RodSeedingRequest& request);

// Rods that hold a number concentration c [rods/m^2] over the region's
// fluid area: the nearest integer to c A [-] (c >= 0).
int rods_at_concentration(const ChannelGeometry& planform, const RodSeedingRequest& request, double concentration);

// Distance [m] between the segments [a0, a1] and [b0, b1] (2-D).
double segment_distance(const Eigen::Vector2d& a0, const Eigen::Vector2d& a1, const Eigen::Vector2d& b0,
                        const Eigen::Vector2d& b1);

}  // namespace hsrod

// Reflection of the depth-averaged flow off the walls that span the gap (side
// walls y = y_lo, y_hi and pore cylinders of ChannelGeometry), by images of a
// point force, for level 3 (nonlocal_model.h, WallReflection::images).
//
// Beyond the Brinkman screening length l = H / sqrt(12) a force F on the
// depth-averaged fluid is seen as the Hele-Shaw potential dipole
//     u = F.(2 rhat rhat - I) H / (24 pi mu r^2)   (brinkman_green.h),
// i.e. in complex form u - i v = -m / (z - z0)^2 with the doublet strength
// m = -H f / (24 pi mu), f = F_x + i F_y. Walls that span the gap are
// impermeable for the gap-averaged (Darcy) flow:
//  - straight side wall: the mirror image of the force, F* = (F_t, -F_n) at
//    the mirrored point. The mirrored pair is symmetric about the wall, so
//    its normal velocity vanishes there for the full Brinkman G too (the
//    exact image of a free-slip wall; the no-slip remainder, the
//    lubrication-like part near the wall, is hydro/wall_proximity.h's).
//  - cylinder of radius a, centre c: Milne-Thomson's circle theorem
//    (Milne-Thomson, Theoretical Hydrodynamics, 5th ed., sec. 6.21): a
//    doublet m at z0 (relative to c) has the image doublet
//    -conj(m) a^2 / conj(z0)^2 at a^2 / conj(z0). In terms of forces the
//    image force is f' = q conj(f), q = -a^2 / conj(z0)^2, a symmetric 2x2
//    map T = [[Re q, Im q], [Im q, -Re q]] (|q| < 1 outside the cylinder);
//    its field is taken as the potential dipole (the theorem holds for
//    potential flow: exact beyond ~l from the image point).
// A pore cylinder centred on a side wall (a half-cylinder bump) takes the
// circle images of the force and of its mirror image in that wall, which
// together are the exact potential-flow images of the bump. Images of images
// in the opposite wall are left out (they are ~(distance to the wall /
// channel width)^2 of the first reflection).
//
// Multiple reflections (WallReflection::reflections): the first images above
// leave a normal velocity on every other wall (the opposite side wall, the
// other throat cylinder). The method of reflections (Happel & Brenner, Low
// Reynolds Number Hydrodynamics, sec. 8.2) cancels it generation by
// generation: each image of generation g is reflected in every reflector but
// the one that made it. Reflectors: each side wall together with the pore
// cylinders centred on it (its exact image operator is {mirror, circle,
// circle of the mirror}, the bump above), and each other cylinder (circle
// image). The reflectors are disjoint, so the series converges to the
// potential-flow Neumann images of the whole planform. The chains of mirror
// images between the two side walls (the lattice z0 + 2 k W i and its
// mirror, whose terms fall as 1 / k^2 only) are summed in closed form,
//     sum_k 1 / (w - 2 k W i)^2 = (pi / 2W)^2 / sinh^2(pi w / 2W),
// for the source and for every circle image (a "head"). A head's lattice
// copies are reflected in each cylinder: the near copies one by one, the
// copies beyond 12 radii gathered into one dipole at the cylinder's centre
// (their images lie within a / 12 of it; strength by the same closed form
// minus the near terms). The series of heads is cut when a generation's
// weight (sum of |map| (W / |image - source|)^2) is below
// ReflectionControl::tolerance of the first generation's, heads lighter than
// `prune` dropped (ImageSeries::converged: the cut was reached within
// max_generations). Several cylinders centred on the same side wall do not
// reflect each other (as in the first images).
//
// Images are the Neumann Green's function's reflected part, so the image
// mobility is reciprocal, M_ik = M_ki^T (Lorentz reciprocity); the plane-
// wall images are exactly so (G(S r) = S G(r) S), the circle images to round-
// off (test_wall_images.cpp).
#pragma once

#include "geometry/channel_geometry.h"

#include <Eigen/Core>
#include <vector>

namespace hsrod {

// One image of a point force: where it acts and the map from the force.
struct ForceImage {
  Eigen::Vector2d position;   // image point [m]
  Eigen::Matrix2d map;        // image force = map * force [-]
  bool full_brinkman = true;  // field: the full Brinkman G (plane mirror) or the far-field dipole
  bool strip_lattice = false; // field: the dipoles of the image and of all its mirrors in the side walls
};

// The images of a force at planform point x [m] in the walls of `walls`.
std::vector<ForceImage> force_images(const ChannelGeometry& walls, const Eigen::Vector2d& x);

// Hele-Shaw potential dipole u = F.(2 rhat rhat - I) H / (24 pi mu r^2) as a
// 2x2 tensor [m/(N s)]; offset r != 0 [m], viscosity [Pa s], gap height H [m].
Eigen::Matrix2d hele_shaw_dipole(const Eigen::Vector2d& offset, double viscosity, double gap_height);

// Gap-averaged velocity at x_target [m] induced by the wall images of a unit
// force on the fluid at x_source [m]: sum over images of G(x_target - z) T
// [m/(N s)]. Not symmetrised (the caller does).
Eigen::Matrix2d image_mobility(const ChannelGeometry& walls, const Eigen::Vector2d& x_target,
                               const Eigen::Vector2d& x_source, double viscosity, double gap_height);

// When to stop the series of multiple reflections.
struct ReflectionControl {
  // Defaults: ~80 images per force in the pore passage's throat, normal
  // velocity left on its cylinders <= 1 % of the force's own (prune 1e-5:
  // <= 0.1 %, ~900 images; tests/drag-models/hydro/test_wall_reflections.cpp).
  double tolerance = 1e-3;    // stop when a generation's weight is below this of the first's [-]
  double prune = 1e-3;        // drop an image whose own weight is below this [-]
  int max_generations = 40;   // at most this many generations of reflections
  int max_images = 20000;     // stop (not converged) beyond this many images, e.g. in a dense pillar array
};

// (cos, sin) of pi (y - y_lo) / (2W) of a point at height y [m] in the strip
// y_lo..y_lo + W [-]: the lattice sum between two points follows from theirs
// by angle addition (wall_images.cpp, strip_lattice).
struct LatticePhase {
  double cos = 1.0, sin = 0.0;
};

// The multiple reflections of a force at x_source [m]: the source's two first
// mirrors (full Brinkman), the rest of its strip lattice (closed form) and
// the circle images, each with its strip lattice (strip_lattice).
struct ImageSeries {
  Eigen::Vector2d source = Eigen::Vector2d::Zero();  // [m]
  std::vector<ForceImage> images;                     // explicit images
  std::vector<LatticePhase> phases;                   // each image's lattice phase (LatticePhase)
  double y_lo = 0.0, width = 0.0;                     // the strip of the lattice [m]
  int generations = 0;                                // generations computed
  double last_weight = 0.0;                           // last generation's weight / the first's [-]
  bool converged = false;                             // last_weight < tolerance within max_generations, max_images
};

ImageSeries reflected_force_images(const ChannelGeometry& walls, const Eigen::Vector2d& x_source,
                                   const ReflectionControl& control = {});

// Gap-averaged velocity at x_target [m] of the images of `series` per unit
// force at its source [m/(N s)].
Eigen::Matrix2d image_mobility(const ImageSeries& series, const Eigen::Vector2d& x_target, double viscosity,
                               double gap_height);

// The dipole lattice of the strip's mirror images, minus the source itself
// and its first mirror in each wall, as a 2x2 tensor [m/(N s)] at x_target
// for a force at x_source (the closed form above).
Eigen::Matrix2d strip_lattice_remainder(double y_lo, double width, const Eigen::Vector2d& x_target,
                                        const Eigen::Vector2d& x_source, double viscosity, double gap_height);

}  // namespace hsrod

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

}  // namespace hsrod

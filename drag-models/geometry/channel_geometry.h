// Planform of a Hele-Shaw channel scene (Braesel et al., Soft Matter 2024, Fig. 1).
//
// A channel of length L along x (flow direction), width W along y and gap
// height H along z, with obstacles that span the whole gap (z-cylinders).
// The planform is the rectangle [x_lo, x_lo + L] x [y_lo, y_lo + W] minus the
// cylinders. The side walls y = y_lo and y = y_lo + W and the cylinder
// surfaces are no-slip walls; x = x_lo is the inlet and x = x_lo + L the
// outlet (open boundaries, not walls). The gap walls are z = 0 and z = H.
//
// The same description drives the background-flow solver, the LIGGGHTS walls
// and the resolved OpenFOAM case, so it validates its input strictly.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace hsrod {

// An obstacle spanning the gap: a cylinder with axis along z.
struct ZCylinder {
  double center_x = 0.0;  // m
  double center_y = 0.0;  // m
  double radius = 0.0;    // m
};

class ChannelGeometry {
 public:
  // length, width, gap_height: L, W, H [m], all > 0.
  // x_lo, y_lo: lower corner of the planform [m].
  // cylinders: obstacles; each centre must lie in the planform rectangle
  // (on the side walls is allowed), each cylinder must stay clear of the
  // inlet and outlet planes (x_lo < x - R, x + R < x_lo + L), and together
  // they must leave the channel open at every x.
  // Throws std::invalid_argument naming the parameter and its accepted range.
  ChannelGeometry(double length, double width, double gap_height, double x_lo = 0.0,
                  double y_lo = 0.0, std::vector<ZCylinder> cylinders = {});

  double length() const { return length_; }          // L [m]
  double width() const { return width_; }            // W [m]
  double gap_height() const { return gap_height_; }  // H [m]
  double x_lo() const { return x_lo_; }              // inlet plane [m]
  double x_hi() const { return x_lo_ + length_; }    // outlet plane [m]
  double y_lo() const { return y_lo_; }              // lower side wall [m]
  double y_hi() const { return y_lo_ + width_; }     // upper side wall [m]
  const std::vector<ZCylinder>& cylinders() const { return cylinders_; }
  // A number given to each constructed geometry (copies share it, the walls
  // never change after construction): equal identities mean equal walls, so
  // a caller may keep distances it computed against one.
  std::uint64_t identity() const { return identity_; }

  // True when the planform has no obstacle (all cylinders of zero radius).
  bool is_straight() const;

  // True when (x, y) [m] lies in the planform: x_lo <= x <= x_hi, strictly
  // between the side walls and strictly outside every cylinder.
  bool is_fluid(double x, double y) const;

  // Signed distance [m] from (x, y) to the nearest side wall or cylinder
  // surface: > 0 in the fluid, < 0 inside a wall or obstacle. The inlet and
  // outlet planes are not walls (the side walls are taken to continue beyond
  // them). Exact in the fluid; inside overlapping solids it is the
  // penetration depth into the deepest single solid.
  double signed_distance(double x, double y) const;

  // Unit normal of the nearest wall or cylinder surface, pointing into the
  // fluid (the gradient of signed_distance); useful for contact forces.
  Eigen::Vector2d wall_normal(double x, double y) const;

  // Distance [m] from `origin` along the unit vector `direction` to the first
  // point where the ray enters a wall or obstacle, or +infinity if there is
  // none within max_distance [m]. Exact for planes and circles; returns 0 if
  // `origin` is not in the fluid.
  double ray_distance_to_wall(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                              double max_distance) const;

  // Open (fluid) width [m] of the cross-section at x: W minus the union of the
  // chords the cylinders cut out of the line x = const.
  double open_width(double x) const;

  // Smallest open width [m] over x; W for a straight channel. For the pore
  // constriction this is the pore width W - 2R. Evaluated exactly at every
  // cylinder centre and on a fine sampling (1/1000 of each diameter) of the
  // cylinders' x-extent.
  double narrowest_opening() const;

 private:
  double length_, width_, gap_height_, x_lo_, y_lo_;
  std::vector<ZCylinder> cylinders_;
  std::uint64_t identity_;
};

}  // namespace hsrod

#include "geometry/pore_constriction.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hsrod {

ChannelGeometry make_straight_channel(double length, double width, double gap_height,
                                      double x_lo, double y_lo) {
  return ChannelGeometry(length, width, gap_height, x_lo, y_lo);
}

ChannelGeometry make_pore_constriction(double length, double width, double gap_height,
                                       double pore_radius, double x_pore, double x_lo,
                                       double y_lo) {
  // Check R against W first: the generic ChannelGeometry checks would only
  // say that the cylinders close the channel.
  if (std::isfinite(width) && width > 0.0 &&
      !(std::isfinite(pore_radius) && pore_radius >= 0.0 && pore_radius < 0.5 * width)) {
    std::ostringstream msg;
    msg << "make_pore_constriction: pore radius R must satisfy 0 <= R < W/2 = " << 0.5 * width
        << " m so that the pore width W - 2R is positive (got R = " << pore_radius << " m)";
    throw std::invalid_argument(msg.str());
  }
  return ChannelGeometry(length, width, gap_height, x_lo, y_lo,
                         {ZCylinder{x_pore, y_lo, pore_radius},
                          ZCylinder{x_pore, y_lo + width, pore_radius}});
}

}  // namespace hsrod

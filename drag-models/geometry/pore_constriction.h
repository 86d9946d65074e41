// Scene builders for the two planforms of the reference study (Braesel et al.
// 2024, Soft Matter, Table 1 and Fig. 1): a straight Hele-Shaw channel and a
// channel with a pore constriction.
#pragma once

#include "geometry/channel_geometry.h"

namespace hsrod {

// Straight channel L x W x H [m] without obstacles.
ChannelGeometry make_straight_channel(double length, double width, double gap_height,
                                      double x_lo = 0.0, double y_lo = 0.0);

// Pore constriction: two z-cylinders of radius R [m] centred on the two side
// walls at x = x_pore [m], leaving a pore of width d_pore = W - 2R.
// Requires 0 <= R < W/2 and x_lo + R < x_pore < x_lo + L - R; throws
// std::invalid_argument otherwise. Paper scene: L = 600 um, W = 200 um,
// R = 85 um (d_pore = 30 um), H = d / beta = 20 um for d = 3 um, beta = 0.15.
ChannelGeometry make_pore_constriction(double length, double width, double gap_height,
                                       double pore_radius, double x_pore, double x_lo = 0.0,
                                       double y_lo = 0.0);

// Pore width d_pore = W - 2R [m] of a constriction built by make_pore_constriction.
inline double pore_width(double width, double pore_radius) { return width - 2.0 * pore_radius; }

}  // namespace hsrod

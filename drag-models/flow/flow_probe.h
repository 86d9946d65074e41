// Probes of a background flow: the gap-averaged velocity, its
// gradient and the pressure at planform points, and integrals over a straight
// section (flow rate, mean pressure), for output (compute hele_shaw/probe)
// and checks. Everything is read from a BackgroundFlow (background_flow.h);
// nothing is solved here.
#pragma once

#include "flow/background_flow.h"

#include <Eigen/Core>

#include <vector>

namespace hsrod {

// The flow at one planform point.
struct FlowSample {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();          // (x, y) [m]
  bool in_fluid = false;                                        // inside the planform, outside walls
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();          // gap-averaged u [m/s]
  Eigen::Matrix2d velocity_gradient = Eigen::Matrix2d::Zero();  // G(a, b) = d u_a / d x_b [1/s]
  double pressure = 0.0;                                        // gauge, 0 at the outlet [Pa]; 0 in walls
};

// Samples `flow` at (x, y) [m]. Points in a wall or obstacle (or beyond the
// inlet/outlet planes) have in_fluid = false and zero velocity, gradient and
// pressure.
FlowSample sample_flow(const BackgroundFlow& flow, const Eigen::Vector2d& point);

// The midpoints of `pieces` equal pieces of the segment from `a` to `b` [m]:
// the nodes of the midpoint rule along it. Throws std::invalid_argument for
// pieces < 1 or a == b.
std::vector<Eigen::Vector2d> segment_midpoints(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                               int pieces);

// Integrals over the straight section a -> b (midpoint rule on `pieces`
// pieces; walls crossed by the section contribute zero velocity).
struct SectionIntegrals {
  // Gap-integrated flow rate through the section, Q = H int u . n ds [m^3/s],
  // n the unit normal obtained by turning the direction a -> b clockwise
  // (a section from the lower to the upper side wall counts +x flow positive).
  double flow_rate = 0.0;
  double fluid_length = 0.0;         // length of the section lying in the fluid [m]
  double mean_pressure = 0.0;        // p averaged over the fluid part [Pa]
  double flux_weighted_pressure = 0.0;  // int p u.n ds / int u.n ds [Pa] (0 if no flux)
  double max_speed = 0.0;            // largest |u| of the nodes [m/s]
};
SectionIntegrals integrate_section(const BackgroundFlow& flow, const Eigen::Vector2d& a,
                                   const Eigen::Vector2d& b, int pieces);

// Pressure drop of the background flow between the cross-sections x = x_up
// and x = x_down [m] (x_up < x_down), each the full width of the channel:
// the difference of the flux-weighted mean pressures, which is the mechanical
// energy the flow loses between them per unit volume (Q dp is the dissipated
// power of a Stokes-Brinkman flow between the sections when the profile is the
// same shape at both). `pieces` midpoint-rule pieces across the width.
double section_pressure_drop(const BackgroundFlow& flow, double x_up, double x_down, int pieces);

}  // namespace hsrod

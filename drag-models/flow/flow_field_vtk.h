// VTK output of a background flow for ParaView: the gap-averaged
// velocity and pressure on a regular lattice over the planform as XML image
// data (.vti), optionally reconstructed in 3-D through the gap with the
// parabolic profile u(x, y) 6 (z/H)(1 - z/H) (background_flow.h), the
// planform walls (side walls, z-cylinders) as polygon data (.vtp), and a
// ParaView collection (.pvd) listing the frames of a run.
// Format: VTK XML file formats, ASCII (VTK User's Guide, "VTK File Formats").
#pragma once

#include "flow/background_flow.h"
#include "flow/window_flow_field.h"

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace hsrod {

// A regular lattice of points over the planform and the gap: nx x ny (x nz)
// points from (x0, y0, z0) with spacings hx, hy, hz [m]; x varies fastest,
// then y, then z (VTK's point order).
struct FieldLattice {
  double x0 = 0.0, y0 = 0.0, z0 = 0.0;  // m
  double hx = 0.0, hy = 0.0, hz = 0.0;  // m (hz unused when nz == 1)
  int nx = 0, ny = 0, nz = 1;
  long points() const { return static_cast<long>(nx) * ny * nz; }
  Eigen::Vector3d point(int i, int j, int k) const { return {x0 + i * hx, y0 + j * hy, z0 + k * hz}; }
};

// The lattice covering the planform [x_lo, x_hi] x [y_lo, y_hi] with points on
// its edges and spacing at most `spacing` [m] in x and y; with gap_layers > 0,
// also gap_layers + 1 point layers from z_bottom to z_bottom + H (a 3-D image),
// else one layer at z_bottom + H/2 (the mid-plane). Throws
// std::invalid_argument for spacing <= 0, gap_layers < 0, or more than
// max_points points.
FieldLattice planform_lattice(const ChannelGeometry& geometry, double spacing, double z_bottom, int gap_layers,
                              long max_points = 20'000'000);

// Flow values at every lattice point (lattice order).
struct FieldSamples {
  std::vector<Eigen::Vector3d> velocity;  // m/s: gap-averaged (u_x, u_y, 0) in 2-D, the 3-D profile in 3-D
  std::vector<double> pressure;           // Pa (gap pressure, uniform across the gap); 0 in walls
  std::vector<double> speed;              // |velocity| [m/s]
  std::vector<unsigned char> fluid;       // 1 in the fluid, 0 in walls and obstacles
};

// Samples `flow` on `lattice`. With lattice.nz > 1 the velocity is the 3-D
// reconstruction at each layer's height above `z_bottom` [m] (the lower gap
// wall), else the gap average. `disturbances`: the rods' window flows at
// level 4 (window_flow_field.h), added to the background's velocity and
// pressure in the fluid (the 3-D reconstruction applies the same parabolic
// profile to the sum, as the gap-averaged equations assume).
FieldSamples sample_field(const BackgroundFlow& flow, const FieldLattice& lattice, double z_bottom,
                          const std::vector<WindowFlowField>& disturbances = {});

// Writes lattice + samples as a VTK XML ImageData file (ASCII, Float64 point
// arrays "velocity" (3 components), "pressure", "speed", UInt8 "fluid";
// field data "time" [s] and "step"). Throws std::runtime_error if the file
// cannot be written.
void write_field_vti(const std::string& path, const FieldLattice& lattice, const FieldSamples& samples,
                     double time, long step);

// Writes the walls of the planform as VTK XML PolyData: the two side walls
// (rectangles y = y_lo, y = y_hi over x_lo..x_hi and the gap), each
// z-cylinder as `segments` quads around its axis (only the facets whose
// middle lies inside the channel rectangle, so a pore cylinder centred on a
// side wall shows as its half in the channel), and the two gap walls as
// outlines (lines) of the planform rectangle at z_bottom and z_bottom + H.
// Cell data "wall" = 0 side wall, 1 + c cylinder c, -1 gap outline.
void write_walls_vtp(const std::string& path, const ChannelGeometry& geometry, double z_bottom, int segments = 64);

// Writes a ParaView collection file listing (time [s], file name) frames.
void write_collection_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& frames);

}  // namespace hsrod

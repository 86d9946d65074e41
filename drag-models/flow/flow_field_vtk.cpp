#include "flow/flow_field_vtk.h"
#include "common/math_constants.h"

#include "flow/flow_probe.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace hsrod {
namespace {

std::ofstream open_for_writing(const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write VTK file '" + path + "'");
  out << std::setprecision(17);
  return out;
}

void check_written(std::ofstream& out, const std::string& path) {
  out.close();
  if (!out) throw std::runtime_error("error while writing VTK file '" + path + "'");
}

}  // namespace

FieldLattice planform_lattice(const ChannelGeometry& g, double spacing, double z_bottom, int gap_layers,
                              long max_points) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw std::invalid_argument("planform_lattice: spacing must be > 0 m");
  if (gap_layers < 0) throw std::invalid_argument("planform_lattice: gap_layers must be >= 0");
  FieldLattice l;
  const int cx = std::max(1, static_cast<int>(std::ceil(g.length() / spacing - 1e-9)));
  const int cy = std::max(1, static_cast<int>(std::ceil(g.width() / spacing - 1e-9)));
  l.nx = cx + 1;
  l.ny = cy + 1;
  l.x0 = g.x_lo();
  l.y0 = g.y_lo();
  l.hx = g.length() / cx;
  l.hy = g.width() / cy;
  if (gap_layers > 0) {
    l.nz = gap_layers + 1;
    l.z0 = z_bottom;
    l.hz = g.gap_height() / gap_layers;
  } else {
    l.nz = 1;
    l.z0 = z_bottom + 0.5 * g.gap_height();
    l.hz = g.gap_height();
  }
  if (static_cast<double>(l.nx) * l.ny * l.nz > static_cast<double>(max_points)) {
    std::ostringstream msg;
    msg << "planform_lattice: " << l.nx << " x " << l.ny << " x " << l.nz << " points exceed " << max_points
        << "; choose a larger spacing or fewer gap layers";
    throw std::invalid_argument(msg.str());
  }
  return l;
}

FieldSamples sample_field(const BackgroundFlow& flow, const FieldLattice& l, double z_bottom,
                          const std::vector<WindowFlowField>& disturbances) {
  FieldSamples s;
  const long n = l.points();
  s.velocity.assign(n, Eigen::Vector3d::Zero());
  s.pressure.assign(n, 0.0);
  s.speed.assign(n, 0.0);
  s.fluid.assign(n, 0);
  const double gap = flow.geometry().gap_height();
  long plane = static_cast<long>(l.nx) * l.ny;
  for (int j = 0; j < l.ny; ++j)
    for (int i = 0; i < l.nx; ++i) {
      const Eigen::Vector3d p = l.point(i, j, 0);
      FlowSample f = sample_flow(flow, p.head<2>());
      if (f.in_fluid && !disturbances.empty()) {
        f.velocity += disturbance_velocity(disturbances, p.x(), p.y());
        f.pressure += disturbance_pressure(disturbances, p.x(), p.y());
      }
      for (int k = 0; k < l.nz; ++k) {
        const long at = k * plane + static_cast<long>(j) * l.nx + i;
        const double profile = l.nz > 1 ? BackgroundFlow::gap_profile(l.z0 + k * l.hz - z_bottom, gap) : 1.0;
        s.velocity[at] = Eigen::Vector3d(profile * f.velocity.x(), profile * f.velocity.y(), 0.0);
        s.speed[at] = s.velocity[at].norm();
        s.pressure[at] = f.pressure;
        s.fluid[at] = f.in_fluid ? 1 : 0;
      }
    }
  return s;
}

void write_field_vti(const std::string& path, const FieldLattice& l, const FieldSamples& s, double time, long step) {
  if (static_cast<long>(s.velocity.size()) != l.points())
    throw std::invalid_argument("write_field_vti: samples do not match the lattice");
  std::ofstream out = open_for_writing(path);
  const std::string extent = "0 " + std::to_string(l.nx - 1) + " 0 " + std::to_string(l.ny - 1) + " 0 " +
                             std::to_string(l.nz - 1);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"ImageData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <ImageData WholeExtent=\"" << extent << "\" Origin=\"" << l.x0 << " " << l.y0 << " " << l.z0
      << "\" Spacing=\"" << l.hx << " " << l.hy << " " << l.hz << "\">\n"
      << "    <FieldData>\n"
      << "      <DataArray type=\"Float64\" Name=\"time\" NumberOfTuples=\"1\" format=\"ascii\">" << time
      << "</DataArray>\n"
      << "      <DataArray type=\"Int64\" Name=\"step\" NumberOfTuples=\"1\" format=\"ascii\">" << step
      << "</DataArray>\n"
      << "    </FieldData>\n"
      << "    <Piece Extent=\"" << extent << "\">\n"
      << "      <PointData Scalars=\"pressure\" Vectors=\"velocity\">\n"
      << "        <DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Eigen::Vector3d& v : s.velocity) out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  out << "        </DataArray>\n"
      << "        <DataArray type=\"Float64\" Name=\"pressure\" format=\"ascii\">\n";
  for (double p : s.pressure) out << p << '\n';
  out << "        </DataArray>\n"
      << "        <DataArray type=\"Float64\" Name=\"speed\" format=\"ascii\">\n";
  for (double v : s.speed) out << v << '\n';
  out << "        </DataArray>\n"
      << "        <DataArray type=\"UInt8\" Name=\"fluid\" format=\"ascii\">\n";
  for (unsigned char f : s.fluid) out << static_cast<int>(f) << '\n';
  out << "        </DataArray>\n"
      << "      </PointData>\n"
      << "      <CellData>\n      </CellData>\n"
      << "    </Piece>\n"
      << "  </ImageData>\n"
      << "</VTKFile>\n";
  check_written(out, path);
}

void write_walls_vtp(const std::string& path, const ChannelGeometry& g, double z_bottom, int segments) {
  if (segments < 3) throw std::invalid_argument("write_walls_vtp: segments must be >= 3");
  const double z1 = z_bottom, z2 = z_bottom + g.gap_height();
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<int>> quads, lines;
  std::vector<int> quad_tag, line_tag;
  auto add_quad = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b, int tag) {
    const int base = static_cast<int>(points.size());
    points.emplace_back(a.x(), a.y(), z1);
    points.emplace_back(b.x(), b.y(), z1);
    points.emplace_back(b.x(), b.y(), z2);
    points.emplace_back(a.x(), a.y(), z2);
    quads.push_back({base, base + 1, base + 2, base + 3});
    quad_tag.push_back(tag);
  };
  add_quad({g.x_lo(), g.y_lo()}, {g.x_hi(), g.y_lo()}, 0);
  add_quad({g.x_lo(), g.y_hi()}, {g.x_hi(), g.y_hi()}, 0);
  const double two_pi = 2.0 * kPi;
  for (size_t c = 0; c < g.cylinders().size(); ++c) {
    const ZCylinder& cyl = g.cylinders()[c];
    if (!(cyl.radius > 0.0)) continue;
    for (int s = 0; s < segments; ++s) {
      const double t0 = two_pi * s / segments, t1 = two_pi * (s + 1) / segments, tm = 0.5 * (t0 + t1);
      const Eigen::Vector2d mid(cyl.center_x + cyl.radius * std::cos(tm), cyl.center_y + cyl.radius * std::sin(tm));
      if (mid.y() < g.y_lo() || mid.y() > g.y_hi() || mid.x() < g.x_lo() || mid.x() > g.x_hi()) continue;
      add_quad({cyl.center_x + cyl.radius * std::cos(t0), cyl.center_y + cyl.radius * std::sin(t0)},
               {cyl.center_x + cyl.radius * std::cos(t1), cyl.center_y + cyl.radius * std::sin(t1)},
               1 + static_cast<int>(c));
    }
  }
  for (double z : {z1, z2}) {
    const int base = static_cast<int>(points.size());
    points.emplace_back(g.x_lo(), g.y_lo(), z);
    points.emplace_back(g.x_hi(), g.y_lo(), z);
    points.emplace_back(g.x_hi(), g.y_hi(), z);
    points.emplace_back(g.x_lo(), g.y_hi(), z);
    lines.push_back({base, base + 1, base + 2, base + 3, base});
    line_tag.push_back(-1);
  }
  std::ofstream out = open_for_writing(path);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << points.size() << "\" NumberOfVerts=\"0\" NumberOfLines=\""
      << lines.size() << "\" NumberOfStrips=\"0\" NumberOfPolys=\"" << quads.size() << "\">\n"
      << "      <Points>\n"
      << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Eigen::Vector3d& p : points) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  out << "        </DataArray>\n      </Points>\n";
  auto cells = [&](const char* section, const std::vector<std::vector<int>>& list) {
    out << "      <" << section << ">\n"
        << "        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& cell : list) {
      for (int id : cell) out << id << ' ';
      out << '\n';
    }
    out << "        </DataArray>\n"
        << "        <DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
    long offset = 0;
    for (const auto& cell : list) out << (offset += static_cast<long>(cell.size())) << '\n';
    out << "        </DataArray>\n      </" << section << ">\n";
  };
  // VTK orders the cell data of polydata as verts, lines, strips, polys.
  out << "      <CellData Scalars=\"wall\">\n"
      << "        <DataArray type=\"Int32\" Name=\"wall\" format=\"ascii\">\n";
  for (int t : line_tag) out << t << '\n';
  for (int t : quad_tag) out << t << '\n';
  out << "        </DataArray>\n      </CellData>\n";
  cells("Lines", lines);
  cells("Polys", quads);
  out << "    </Piece>\n  </PolyData>\n</VTKFile>\n";
  check_written(out, path);
}

void write_collection_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& frames) {
  std::ofstream out = open_for_writing(path);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
  for (const auto& f : frames)
    out << "    <DataSet timestep=\"" << f.first << "\" group=\"\" part=\"0\" file=\"" << f.second << "\"/>\n";
  out << "  </Collection>\n</VTKFile>\n";
  check_written(out, path);
}

}  // namespace hsrod

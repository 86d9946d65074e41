#include "flow/flow_probe.h"

#include <cmath>
#include <stdexcept>

namespace hsrod {

FlowSample sample_flow(const BackgroundFlow& flow, const Eigen::Vector2d& point) {
  FlowSample s;
  s.position = point;
  const ChannelGeometry& g = flow.geometry();
  s.in_fluid = point.x() >= g.x_lo() && point.x() <= g.x_hi() && g.is_fluid(point.x(), point.y());
  if (!s.in_fluid) return s;
  s.velocity = flow.velocity(point.x(), point.y());
  s.velocity_gradient = flow.velocity_gradient(point.x(), point.y());
  s.pressure = flow.pressure(point.x(), point.y());
  return s;
}

std::vector<Eigen::Vector2d> segment_midpoints(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                               int pieces) {
  if (pieces < 1) throw std::invalid_argument("segment_midpoints: pieces must be >= 1");
  if (!((b - a).norm() > 0.0)) throw std::invalid_argument("segment_midpoints: the segment has zero length");
  std::vector<Eigen::Vector2d> points(pieces);
  for (int k = 0; k < pieces; ++k) points[k] = a + (b - a) * ((k + 0.5) / pieces);
  return points;
}

SectionIntegrals integrate_section(const BackgroundFlow& flow, const Eigen::Vector2d& a,
                                   const Eigen::Vector2d& b, int pieces) {
  const std::vector<Eigen::Vector2d> nodes = segment_midpoints(a, b, pieces);
  const double ds = (b - a).norm() / pieces;                       // m
  const Eigen::Vector2d t = (b - a).normalized();
  const Eigen::Vector2d n(t.y(), -t.x());                          // clockwise turn of t
  SectionIntegrals out;
  double flux = 0.0, pressure_length = 0.0, pressure_flux = 0.0;  // per unit gap height
  for (const Eigen::Vector2d& p : nodes) {
    const FlowSample s = sample_flow(flow, p);
    if (!s.in_fluid) continue;
    const double un = s.velocity.dot(n);
    flux += un * ds;
    out.fluid_length += ds;
    pressure_length += s.pressure * ds;
    pressure_flux += s.pressure * un * ds;
    out.max_speed = std::max(out.max_speed, s.velocity.norm());
  }
  out.flow_rate = flow.geometry().gap_height() * flux;
  if (out.fluid_length > 0.0) out.mean_pressure = pressure_length / out.fluid_length;
  if (flux != 0.0) out.flux_weighted_pressure = pressure_flux / flux;
  return out;
}

double section_pressure_drop(const BackgroundFlow& flow, double x_up, double x_down, int pieces) {
  if (!(x_up < x_down)) throw std::invalid_argument("section_pressure_drop: x_up must be < x_down");
  const ChannelGeometry& g = flow.geometry();
  auto section = [&](double x) {
    return integrate_section(flow, {x, g.y_lo()}, {x, g.y_hi()}, pieces).flux_weighted_pressure;
  };
  return section(x_up) - section(x_down);
}

}  // namespace hsrod

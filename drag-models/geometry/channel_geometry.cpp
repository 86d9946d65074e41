#include "geometry/channel_geometry.h"

#include <atomic>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace hsrod {
namespace {

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("ChannelGeometry: " + what);
}

std::string num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

void require_positive(double value, const char* name) {
  if (!std::isfinite(value) || value <= 0.0)
    fail(std::string(name) + " must be a finite number > 0 m (got " + num(value) + ")");
}

}  // namespace

namespace {
std::uint64_t next_identity() {
  static std::atomic<std::uint64_t> count{0};
  return ++count;
}
}  // namespace

ChannelGeometry::ChannelGeometry(double length, double width, double gap_height, double x_lo,
                                 double y_lo, std::vector<ZCylinder> cylinders)
    : length_(length),
      width_(width),
      gap_height_(gap_height),
      x_lo_(x_lo),
      y_lo_(y_lo),
      cylinders_(std::move(cylinders)),
      identity_(next_identity()) {
  require_positive(length_, "length L");
  require_positive(width_, "width W");
  require_positive(gap_height_, "gap_height H");
  if (!std::isfinite(x_lo_) || !std::isfinite(y_lo_))
    fail("lower corner (x_lo, y_lo) must be finite (got (" + num(x_lo_) + ", " + num(y_lo_) + "))");

  for (std::size_t k = 0; k < cylinders_.size(); ++k) {
    const ZCylinder& c = cylinders_[k];
    const std::string id = "cylinder " + std::to_string(k) + ": ";
    if (!std::isfinite(c.radius) || c.radius < 0.0)
      fail(id + "radius R must be a finite number >= 0 m (got " + num(c.radius) + ")");
    if (!std::isfinite(c.center_x) || !std::isfinite(c.center_y) || c.center_x < x_lo_ ||
        c.center_x > x_hi() || c.center_y < y_lo_ || c.center_y > y_hi())
      fail(id + "centre (" + num(c.center_x) + ", " + num(c.center_y) +
           ") m must lie inside the channel [" + num(x_lo_) + ", " + num(x_hi()) + "] x [" +
           num(y_lo_) + ", " + num(y_hi()) + "] m");
    if (c.radius > 0.0 && (c.center_x - c.radius <= x_lo_ || c.center_x + c.radius >= x_hi()))
      fail(id + "must stay clear of the inlet and outlet: need x_lo < x - R and x + R < x_lo + L, "
                "i.e. x in (" + num(x_lo_ + c.radius) + ", " + num(x_hi() - c.radius) +
           ") m for R = " + num(c.radius) + " m (got x = " + num(c.center_x) + " m)");
  }
  for (const ZCylinder& c : cylinders_) {
    if (c.radius > 0.0 && open_width(c.center_x) <= 0.0)
      fail("the cylinders close the channel at x = " + num(c.center_x) +
           " m (open width 0); the planform must stay connected from inlet to outlet");
  }
}

bool ChannelGeometry::is_straight() const {
  return std::none_of(cylinders_.begin(), cylinders_.end(),
                      [](const ZCylinder& c) { return c.radius > 0.0; });
}

bool ChannelGeometry::is_fluid(double x, double y) const {
  return x >= x_lo_ && x <= x_hi() && signed_distance(x, y) > 0.0;
}

double ChannelGeometry::signed_distance(double x, double y) const {
  double d = std::min(y - y_lo_, y_hi() - y);
  for (const ZCylinder& c : cylinders_) {
    if (c.radius <= 0.0) continue;
    const double dx = x - c.center_x, dy = y - c.center_y;
    // A cylinder whose surface is farther than d cannot lower it: no hypot
    // (the drag, the contacts and the guard ask for this at every sphere
    // several times a step). The margin 1e-9 exceeds the rounding of the
    // squares, so the result is the same to the last bit.
    const double reach = d + c.radius;
    if (reach > 0.0 && dx * dx + dy * dy > reach * reach * (1.0 + 1e-9)) continue;
    d = std::min(d, std::hypot(dx, dy) - c.radius);
  }
  return d;
}

Eigen::Vector2d ChannelGeometry::wall_normal(double x, double y) const {
  double best = y - y_lo_;
  Eigen::Vector2d normal(0.0, 1.0);
  if (y_hi() - y < best) {
    best = y_hi() - y;
    normal = Eigen::Vector2d(0.0, -1.0);
  }
  for (const ZCylinder& c : cylinders_) {
    if (c.radius <= 0.0) continue;
    const Eigen::Vector2d r(x - c.center_x, y - c.center_y);
    const double rn = r.norm();
    if (rn - c.radius < best) {
      best = rn - c.radius;
      normal = rn > 0.0 ? Eigen::Vector2d(r / rn) : Eigen::Vector2d(1.0, 0.0);
    }
  }
  return normal;
}

double ChannelGeometry::ray_distance_to_wall(const Eigen::Vector2d& origin,
                                             const Eigen::Vector2d& direction,
                                             double max_distance) const {
  const double inf = std::numeric_limits<double>::infinity();
  if (signed_distance(origin.x(), origin.y()) <= 0.0) return 0.0;
  double t_hit = inf;
  // Side walls y = y_lo (approached with dy < 0) and y = y_hi (dy > 0).
  if (direction.y() < 0.0) t_hit = std::min(t_hit, (y_lo_ - origin.y()) / direction.y());
  if (direction.y() > 0.0) t_hit = std::min(t_hit, (y_hi() - origin.y()) / direction.y());
  // Cylinders: first root of |origin + t d - c|^2 = R^2 (origin is outside).
  for (const ZCylinder& c : cylinders_) {
    if (c.radius <= 0.0) continue;
    const Eigen::Vector2d r = origin - Eigen::Vector2d(c.center_x, c.center_y);
    const double b = r.dot(direction);
    const double disc = b * b - (r.squaredNorm() - c.radius * c.radius);
    if (disc < 0.0) continue;
    const double t = -b - std::sqrt(disc);
    if (t >= 0.0) t_hit = std::min(t_hit, t);
  }
  return t_hit <= max_distance ? t_hit : inf;
}

double ChannelGeometry::open_width(double x) const {
  std::vector<std::pair<double, double>> blocked;
  for (const ZCylinder& c : cylinders_) {
    const double dx = x - c.center_x;
    if (c.radius <= 0.0 || std::abs(dx) >= c.radius) continue;
    const double half_chord = std::sqrt(c.radius * c.radius - dx * dx);
    const double a = std::max(y_lo_, c.center_y - half_chord);
    const double b = std::min(y_hi(), c.center_y + half_chord);
    if (b > a) blocked.emplace_back(a, b);
  }
  std::sort(blocked.begin(), blocked.end());
  double covered = 0.0, end = -std::numeric_limits<double>::infinity();
  for (const auto& [a, b] : blocked) {
    if (a > end) {
      covered += b - a;
      end = b;
    } else if (b > end) {
      covered += b - end;
      end = b;
    }
  }
  return std::max(0.0, width_ - covered);
}

double ChannelGeometry::narrowest_opening() const {
  double narrowest = width_;
  for (const ZCylinder& c : cylinders_) {
    if (c.radius <= 0.0) continue;
    narrowest = std::min(narrowest, open_width(c.center_x));
    constexpr int kSamples = 2000;
    for (int s = 0; s <= kSamples; ++s) {
      const double x = c.center_x - c.radius + 2.0 * c.radius * s / kSamples;
      narrowest = std::min(narrowest, open_width(x));
    }
  }
  return narrowest;
}

}  // namespace hsrod

#include "geometry/rod_seeding.h"

#include "common/math_constants.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace hsrod {

namespace {

struct Region {
  double x_min, x_max, y_min, y_max;  // [m]
};

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

double spacing_of(const RodSeedingRequest& r) { return r.spacing > 0.0 ? r.spacing : r.sphere_diameter; }
double axis_length(const RodSeedingRequest& r) { return (r.spheres - 1) * spacing_of(r); }

Eigen::Vector2d axis_of(double angle) { return {std::sin(angle), std::cos(angle)}; }

void check_request(const ChannelGeometry& planform, const RodSeedingRequest& r) {
  if (r.rods < 1) throw std::invalid_argument("rods must be >= 1, got " + std::to_string(r.rods));
  if (r.spheres < 1) throw std::invalid_argument("spheres must be >= 1, got " + std::to_string(r.spheres));
  if (!(r.sphere_diameter > 0.0) || !std::isfinite(r.sphere_diameter))
    throw std::invalid_argument("diameter must be a finite number > 0 m, got " + number(r.sphere_diameter));
  if (r.spacing != 0.0 && !(r.spacing >= r.sphere_diameter && std::isfinite(r.spacing)))
    throw std::invalid_argument("spacing must be >= the diameter " + number(r.sphere_diameter) + " m, got " +
                                number(r.spacing));
  if (!(r.min_gap >= 0.0) || !std::isfinite(r.min_gap))
    throw std::invalid_argument("min_gap must be a finite number >= 0 m, got " + number(r.min_gap));
  if (r.angle && !std::isfinite(*r.angle)) throw std::invalid_argument("angle must be finite");
  if (r.max_trials_per_rod < 1) throw std::invalid_argument("max_trials_per_rod must be >= 1");
  if (!(r.jitter_position >= 0.0) || !std::isfinite(r.jitter_position) || !(r.jitter_angle >= 0.0) ||
      !(r.jitter_angle <= 0.5 * kPi))
    throw std::invalid_argument("jitter must be a position >= 0 m and an angle of 0 to 90 degrees, got " +
                                number(r.jitter_position) + " m, " + number(r.jitter_angle * 180.0 / kPi) + " deg");
  if ((r.jitter_position > 0.0 || r.jitter_angle > 0.0) && r.layout != SeedingLayout::lattice)
    throw std::invalid_argument("jitter needs layout lattice (random rods are random already)");
  const bool whole = r.x_min == 0.0 && r.x_max == 0.0;
  if (!whole && !(r.x_min >= planform.x_lo() && r.x_max <= planform.x_hi() && r.x_min < r.x_max))
    throw std::invalid_argument("region x " + number(r.x_min) + " .. " + number(r.x_max) +
                                " m must be a non-empty range inside the planform's " + number(planform.x_lo()) +
                                " .. " + number(planform.x_hi()) + " m");
}

Region region_of(const ChannelGeometry& planform, const RodSeedingRequest& r) {
  const bool whole = r.x_min == 0.0 && r.x_max == 0.0;
  return {whole ? planform.x_lo() : r.x_min, whole ? planform.x_hi() : r.x_max, planform.y_lo(), planform.y_hi()};
}

// Fluid area of the region [m^2], from a 512 x 512 sample of the planform
// (the cylinders' share to ~0.2 %: enough for a concentration).
double fluid_area(const ChannelGeometry& planform, const Region& g) {
  constexpr int kSamples = 512;
  int fluid = 0;
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kSamples; ++j)
      fluid += planform.is_fluid(g.x_min + (i + 0.5) * (g.x_max - g.x_min) / kSamples,
                                 g.y_min + (j + 0.5) * (g.y_max - g.y_min) / kSamples);
  return (g.x_max - g.x_min) * (g.y_max - g.y_min) * fluid / (double(kSamples) * kSamples);
}

// The rods placed so far, in a uniform cell list keyed by the cell of the
// rod's centre: a cell is at least one rod length plus the contact
// distance, so a rod can touch only rods of the 3 x 3 cells around its own.
class PlacedRods {
 public:
  PlacedRods(const Region& g, double cell) : g_(g), cell_(cell) {}

  void add(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double diameter) {
    const int k = static_cast<int>(segments_.size());
    segments_.push_back({a, b, diameter});
    cells_[key(0.5 * (a + b))].push_back(k);
  }
  // True when the segment [a, b] of spheres of diameter d keeps gap from every placed rod.
  bool clear(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double d, double gap) const {
    const Eigen::Vector2d c = 0.5 * (a + b);
    const long ix = index(c.x() - g_.x_min), iy = index(c.y() - g_.y_min);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy) {
        const auto it = cells_.find(pack(ix + dx, iy + dy));
        if (it == cells_.end()) continue;
        for (int k : it->second) {
          const Segment& s = segments_[k];
          if (segment_distance(a, b, s.a, s.b) < 0.5 * (d + s.diameter) + gap) return false;
        }
      }
    return true;
  }

 private:
  struct Segment {
    Eigen::Vector2d a, b;
    double diameter;
  };
  long index(double offset) const { return static_cast<long>(std::floor(offset / cell_)); }
  static long long pack(long ix, long iy) { return (static_cast<long long>(ix) << 32) ^ (iy & 0xffffffffLL); }
  long long key(const Eigen::Vector2d& c) const { return pack(index(c.x() - g_.x_min), index(c.y() - g_.y_min)); }

  Region g_;
  double cell_;  // [m]
  std::vector<Segment> segments_;
  std::unordered_map<long long, std::vector<int>> cells_;
};

// True when every sphere of the rod lies in the region and keeps d/2 + gap
// from the side walls and cylinders.
bool clear_of_walls(const ChannelGeometry& planform, const Region& g, const RodSeedingRequest& r,
                    const SeededRod& rod) {
  const double clearance = 0.5 * r.sphere_diameter + r.min_gap;
  const Eigen::Vector2d t = axis_of(rod.angle);
  for (int k = 0; k < r.spheres; ++k) {
    const Eigen::Vector2d p = rod.centre + (k - 0.5 * (r.spheres - 1)) * spacing_of(r) * t;
    if (p.x() < g.x_min || p.x() > g.x_max) return false;
    if (!planform.is_fluid(p.x(), p.y()) || planform.signed_distance(p.x(), p.y()) < clearance) return false;
  }
  return true;
}

[[noreturn]] void cannot_pack(const ChannelGeometry& planform, const RodSeedingRequest& r, int placed,
                              const std::string& why) {
  throw std::runtime_error("cannot pack " + std::to_string(r.rods) + " rods (area fraction " +
                           number(rod_area_fraction(planform, r, r.rods)) + ") in the region: " + why + "; " +
                           std::to_string(placed) + " placed (area fraction " +
                           number(rod_area_fraction(planform, r, placed)) +
                           "); use fewer rods, a smaller min_gap or a larger region");
}

std::vector<SeededRod> seed_random(const ChannelGeometry& planform, const RodSeedingRequest& r, const Region& g,
                                   PlacedRods& placed) {
  std::mt19937_64 rng(r.seed);
  std::uniform_real_distribution<double> ux(g.x_min, g.x_max), uy(g.y_min, g.y_max), ua(0.0, kPi);
  std::vector<SeededRod> out;
  const double half = 0.5 * axis_length(r);
  int failures = 0;
  while (static_cast<int>(out.size()) < r.rods) {
    SeededRod rod;
    rod.centre = {ux(rng), uy(rng)};
    rod.angle = r.angle ? *r.angle : ua(rng);
    const Eigen::Vector2d a = rod.centre - half * axis_of(rod.angle), b = rod.centre + half * axis_of(rod.angle);
    if (clear_of_walls(planform, g, r, rod) && placed.clear(a, b, r.sphere_diameter, r.min_gap)) {
      placed.add(a, b, r.sphere_diameter);
      out.push_back(rod);
      failures = 0;
    } else if (++failures >= r.max_trials_per_rod) {
      cannot_pack(planform, r, static_cast<int>(out.size()),
                  std::to_string(r.max_trials_per_rod) + " random trials in a row found no free place");
    }
  }
  return out;
}

std::vector<SeededRod> seed_lattice(const ChannelGeometry& planform, const RodSeedingRequest& r, const Region& g,
                                    PlacedRods& placed) {
  const double angle = r.angle ? *r.angle : 0.0;
  const Eigen::Vector2d t = axis_of(angle);
  const double d = r.sphere_diameter, half = 0.5 * axis_length(r);
  // The rod's bounding box plus the gap: the smallest pitch along x and y.
  const double px0 = 2.0 * half * std::abs(t.x()) + d + r.min_gap;
  const double py0 = 2.0 * half * std::abs(t.y()) + d + r.min_gap;
  const double lx = g.x_max - g.x_min, ly = g.y_max - g.y_min;
  // The sites of a lattice of pitch scale * (px0, py0), centred in the region.
  auto sites = [&](double scale) {
    const int nx = static_cast<int>(std::floor(lx / (scale * px0))), ny = static_cast<int>(std::floor(ly / (scale * py0)));
    std::vector<SeededRod> s;
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j < ny; ++j) {
        SeededRod rod;
        rod.centre = {g.x_min + (i + 0.5) * lx / nx, g.y_min + (j + 0.5) * ly / ny};
        rod.angle = angle;
        if (clear_of_walls(planform, g, r, rod)) s.push_back(rod);
      }
    return s;
  };
  if (static_cast<int>(sites(1.0).size()) < r.rods)
    cannot_pack(planform, r, static_cast<int>(sites(1.0).size()),
                "the densest lattice at this angle has " + std::to_string(sites(1.0).size()) + " free sites");
  // The largest pitch that still holds every rod (bisection on the scale).
  double lo = 1.0, hi = std::max(lx / px0, ly / py0) + 1.0;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (static_cast<int>(sites(mid).size()) >= r.rods ? lo : hi) = mid;
  }
  std::vector<SeededRod> all = sites(lo), out;
  const bool jittered = r.jitter_position > 0.0 || r.jitter_angle > 0.0;
  std::mt19937_64 rng(r.seed);
  std::uniform_real_distribution<double> shift(-r.jitter_position, r.jitter_position),
      turn(-r.jitter_angle, r.jitter_angle);
  for (const SeededRod& site : all) {
    if (static_cast<int>(out.size()) == r.rods) break;
    // The site itself, or the first jittered draw that is clear.
    for (int trial = 0; trial < (jittered ? r.max_trials_per_rod : 1); ++trial) {
      SeededRod rod = site;
      if (jittered) {
        rod.centre += Eigen::Vector2d(shift(rng), shift(rng));
        rod.angle += turn(rng);
        if (!clear_of_walls(planform, g, r, rod)) continue;
      }
      const Eigen::Vector2d ta = axis_of(rod.angle);
      const Eigen::Vector2d a = rod.centre - half * ta, b = rod.centre + half * ta;
      if (!placed.clear(a, b, d, r.min_gap)) continue;
      placed.add(a, b, d);
      out.push_back(rod);
      break;
    }
  }
  if (static_cast<int>(out.size()) < r.rods)
    cannot_pack(planform, r, static_cast<int>(out.size()),
                jittered ? "the lattice's free sites touch rods already there, or its pitch leaves no room for the jitter"
                         : "the lattice's free sites touch rods already there");
  return out;
}

}  // namespace

double segment_distance(const Eigen::Vector2d& a0, const Eigen::Vector2d& a1, const Eigen::Vector2d& b0,
                        const Eigen::Vector2d& b1) {
  // Closest points of two segments (clamped parameters; Ericson, Real-Time
  // Collision Detection, 2005, sec. 5.1.9).
  const Eigen::Vector2d d1 = a1 - a0, d2 = b1 - b0, r = a0 - b0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (a <= 1e-300 && e <= 1e-300) return r.norm();
  if (a <= 1e-300) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 1e-300) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return (a0 + s * d1 - (b0 + t * d2)).norm();
}

double region_fluid_area(const ChannelGeometry& planform, const RodSeedingRequest& request) {
  return fluid_area(planform, region_of(planform, request));
}

int rods_at_concentration(const ChannelGeometry& planform, const RodSeedingRequest& request, double concentration) {
  if (!(concentration >= 0.0) || !std::isfinite(concentration))
    throw std::invalid_argument("concentration must be a finite number of rods per m^2, >= 0");
  return static_cast<int>(std::lround(concentration * region_fluid_area(planform, request)));
}

double rod_area_fraction(const ChannelGeometry& planform, const RodSeedingRequest& request, int rods) {
  const double d = request.sphere_diameter;
  const double capsule = axis_length(request) * d + 0.25 * kPi * d * d;
  return rods * capsule / fluid_area(planform, region_of(planform, request));
}

std::vector<SeededRod> seed_rods(const ChannelGeometry& planform, const RodSeedingRequest& request,
                                 const std::vector<RodObstacle>& existing) {
  check_request(planform, request);
  const Region g = region_of(planform, request);
  double largest = request.sphere_diameter;
  for (const RodObstacle& o : existing) largest = std::max(largest, o.sphere_diameter);
  double longest = axis_length(request);
  for (const RodObstacle& o : existing) longest = std::max(longest, (o.end_b - o.end_a).norm());
  PlacedRods placed(g, longest + largest + request.min_gap);
  for (const RodObstacle& o : existing) placed.add(o.end_a, o.end_b, o.sphere_diameter);
  return request.layout == SeedingLayout::random ? seed_random(planform, request, g, placed)
                                                 : seed_lattice(planform, request, g, placed);
}

}  // namespace hsrod

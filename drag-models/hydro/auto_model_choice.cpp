#include "hydro/auto_model_choice.h"

#include "hydro/model_registry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace hsrod {

namespace {

struct ErrorTriple {
  double force = 0, velocity = 0, r = 0;
};

ErrorTriple mix(const ErrorTriple& a, const ErrorTriple& b, double w) {
  return {a.force + w * (b.force - a.force), a.velocity + w * (b.velocity - a.velocity), a.r + w * (b.r - a.r)};
}

// Linear interpolation in n over one beta's rows (sorted by n), clamped.
ErrorTriple along_n(const std::map<int, ErrorTriple>& by_n, int n, bool& extrapolated) {
  if (n <= by_n.begin()->first) {
    extrapolated |= n < by_n.begin()->first;
    return by_n.begin()->second;
  }
  if (n >= by_n.rbegin()->first) {
    extrapolated |= n > by_n.rbegin()->first;
    return by_n.rbegin()->second;
  }
  auto hi = by_n.lower_bound(n);
  auto lo = std::prev(hi);
  if (hi->first == n) return hi->second;
  return mix(lo->second, hi->second, double(n - lo->first) / (hi->first - lo->first));
}

// Bending load level 3 adds across each rod times the beam compliance: the
// deflection a local level misses, over L (see the header).
double missed_deflection(const std::vector<RodGeometry>& rods, const BackgroundFlow& flow,
                         const HydrodynamicModel& level3, double bending_stiffness) {
  double worst = 0.0;
  for (const RodGeometry& g : rods) {
    RodDrag drag;
    level3.evaluate(g, flow, drag);
    const int n = g.size();
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& f : drag.driving_force) mean += f / n;
    const auto tangents = g.section_tangents();
    double bending_load = 0.0;  // [N]
    for (int k = 0; k < n; k++) {
      const Eigen::Vector3d t = tangents[g.section_of(k)];
      const Eigen::Vector3d excess = drag.driving_force[k] - mean;
      bending_load += (excess - t * t.dot(excess)).norm();
    }
    const double length = g.sections() * g.sphere_diameter;  // L [m]
    worst = std::max(worst, bending_load * std::pow(length, 3) /
                                (48.0 * bending_stiffness * g.spheres_per_section) / length);
  }
  return worst;
}

}  // namespace

double expected_near_wall_error(const std::vector<NearWallErrorRow>& record, int level, bool pore, double beta,
                                double gap_over_d, bool& extrapolated) {
  double nearest_beta = -1.0;
  for (const NearWallErrorRow& r : record)
    if (r.level == level && r.pore == pore && (nearest_beta < 0.0 || std::abs(r.beta - beta) < std::abs(nearest_beta - beta)))
      nearest_beta = r.beta;
  if (nearest_beta < 0.0) return 0.0;
  std::map<double, double> by_gap;
  for (const NearWallErrorRow& r : record)
    if (r.level == level && r.pore == pore && r.beta == nearest_beta) by_gap[r.gap_over_d] = r.force_error;
  const bool near = gap_over_d < 2.0 * by_gap.rbegin()->first;
  if (near && std::abs(nearest_beta - beta) > 1e-9) extrapolated = true;
  if (gap_over_d <= by_gap.begin()->first) {
    extrapolated |= gap_over_d < by_gap.begin()->first;
    return by_gap.begin()->second;
  }
  const auto far = *by_gap.rbegin();
  if (gap_over_d >= far.first)  // beyond the record: falls linearly to 0 at twice its largest gap
    return near ? far.second * (2.0 - gap_over_d / far.first) : 0.0;
  const auto hi = by_gap.lower_bound(gap_over_d);
  const auto lo = std::prev(hi);
  return lo->second + (hi->second - lo->second) * (gap_over_d - lo->first) / (hi->first - lo->first);
}

SceneWallGaps scene_wall_gaps(const std::vector<RodGeometry>& rods, const ChannelGeometry& geometry) {
  SceneWallGaps gaps;
  gaps.wall = gaps.pore = std::numeric_limits<double>::infinity();
  double d = 0.0;
  for (const RodGeometry& g : rods) {
    d = std::max(d, g.sphere_diameter);
    for (const Eigen::Vector3d& x : g.positions) {
      const double a = 0.5 * g.sphere_diameter;
      const double to_walls = std::min(x.y() - geometry.y_lo(), geometry.y_hi() - x.y()) - a;
      gaps.wall = std::min(gaps.wall, to_walls / g.sphere_diameter);
      for (const ZCylinder& c : geometry.cylinders())
        if (c.radius > 0.0)
          gaps.pore = std::min(gaps.pore, (std::hypot(x.x() - c.center_x, x.y() - c.center_y) - c.radius - a) /
                                              g.sphere_diameter);
    }
  }
  if (d > 0.0 && !geometry.is_straight())  // passing the narrowest opening on its centre line
    gaps.pore = std::min(gaps.pore, 0.5 * (geometry.narrowest_opening() - d) / d);
  gaps.wall = std::max(gaps.wall, 0.0);
  gaps.pore = std::max(gaps.pore, 0.0);
  return gaps;
}

ExpectedLevelError expected_level_error(const std::vector<LevelErrorRow>& record, int level, double beta, int n) {
  std::map<double, std::map<int, ErrorTriple>> grid;  // beta -> n -> errors
  for (const LevelErrorRow& r : record)
    if (r.level == level) grid[r.beta][r.n] = {r.force_error, r.velocity_error, r.r_error};
  ExpectedLevelError out;
  if (grid.empty()) return out;
  out.known = true;
  ErrorTriple e;
  if (beta <= grid.begin()->first || beta >= grid.rbegin()->first) {
    const auto& at = beta <= grid.begin()->first ? *grid.begin() : *grid.rbegin();
    out.extrapolated = std::abs(beta - at.first) > 1e-9;
    e = along_n(at.second, n, out.extrapolated);
  } else {
    auto hi = grid.lower_bound(beta);
    auto lo = std::prev(hi);
    const ErrorTriple a = along_n(lo->second, n, out.extrapolated);
    const ErrorTriple b = along_n(hi->second, n, out.extrapolated);
    e = mix(a, b, (beta - lo->first) / (hi->first - lo->first));
  }
  out.force = e.force;
  out.velocity = e.velocity;
  out.r = e.r;
  return out;
}

AutoModelChoice choose_auto_model(const std::vector<RodGeometry>& rods, const BackgroundFlow& flow, double beta,
                                  const HydrodynamicModel& level3, double bending_stiffness,
                                  double deflection_tolerance, double error_tolerance,
                                  const std::vector<LevelErrorRow>& record,
                                  const std::vector<NearWallErrorRow>& near_wall) {
  AutoModelChoice choice;
  choice.flexible = bending_stiffness > 0.0;
  if (choice.flexible) choice.estimated_deflection = missed_deflection(rods, flow, level3, bending_stiffness);
  const bool bending_matters = choice.flexible && choice.estimated_deflection > deflection_tolerance;
  int longest = 1;  // spheres along the longest rod (sections)
  for (const RodGeometry& g : rods) longest = std::max(longest, g.sections());

  // Expected error of every level: the worst over the rods (the longest rod
  // for the length dependence).
  // The near-wall record adds the error at the scene's gaps to walls and pores.
  std::vector<ExpectedLevelError> errors;
  choice.wall_gaps = scene_wall_gaps(rods, flow.geometry());
  for (int level = 1; level <= 4; ++level) {
    errors.push_back(expected_level_error(record, level, beta, longest));
    bool near_extrapolated = false;
    const double near_wall_error =
        std::max(expected_near_wall_error(near_wall, level, false, beta, choice.wall_gaps.wall, near_extrapolated),
                 expected_near_wall_error(near_wall, level, true, beta, choice.wall_gaps.pore, near_extrapolated));
    errors.back().extrapolated |= near_extrapolated && near_wall_error > 0.0;
    choice.near_wall_errors.push_back(near_wall_error);
    choice.level_errors.push_back(errors.back().known && find_model_level(level)
                                      ? std::max(errors.back().total(), near_wall_error)
                                      : -1.0);
  }
  auto allowed = [&](int level) { return choice.level_errors[level - 1] >= 0.0 && (!bending_matters || level >= 3); };
  int chosen = 0;
  for (int level = 1; level <= 4 && !chosen; ++level)
    if (allowed(level) && choice.level_errors[level - 1] <= error_tolerance) chosen = level;
  choice.within_tolerance = chosen != 0;
  if (!chosen)  // none within the tolerance: the most accurate allowed level
    for (int level = 1; level <= 4; ++level)
      if (allowed(level) && (!chosen || choice.level_errors[level - 1] < choice.level_errors[chosen - 1]))
        chosen = level;
  if (!chosen) chosen = bending_matters ? 3 : 2;  // no record at all: the previous policy
  choice.model = find_model_level(chosen)->name;
  choice.expected_error = std::max(0.0, choice.level_errors[chosen - 1]);
  choice.extrapolated = errors[chosen - 1].extrapolated;

  char buf[256];
  std::snprintf(buf, sizeof buf, "beta %.3g, rods of up to %d spheres", beta, longest);
  std::string s = buf;
  if (std::isfinite(choice.wall_gaps.wall)) {
    std::snprintf(buf, sizeof buf, ", %.2g d from a side wall", choice.wall_gaps.wall);
    s += buf;
  }
  if (std::isfinite(choice.wall_gaps.pore)) {
    std::snprintf(buf, sizeof buf, ", %.2g d from a pore cylinder", choice.wall_gaps.pore);
    s += buf;
  }
  s += "; expected error from the cross-check records (slit rows";
  bool any_near = false;
  for (double e : choice.near_wall_errors) any_near |= e > 0.0;
  s += any_near ? ", near walls and pores):" : "):";
  for (int level = 1; level <= 4; ++level) {
    const char* sep = level > 1 ? "," : "";
    if (choice.level_errors[level - 1] < 0.0) std::snprintf(buf, sizeof buf, "%s level %d -", sep, level);
    else std::snprintf(buf, sizeof buf, "%s level %d %.1f %%", sep, level, 100 * choice.level_errors[level - 1]);
    s += buf;
  }
  if (choice.flexible) {
    std::snprintf(buf, sizeof buf, "; deflection a local level misses %.3g of L (tolerance %.3g)%s",
                  choice.estimated_deflection, deflection_tolerance, bending_matters ? ": non-local levels only" : "");
    s += buf;
  }
  std::snprintf(buf, sizeof buf, " -> %s (level %d), expected error %.1f %% (tolerance %.0f %%)%s%s",
                choice.model.c_str(), chosen, 100 * choice.expected_error, 100 * error_tolerance,
                choice.within_tolerance ? "" : ": no allowed level within the tolerance, the most accurate one",
                choice.extrapolated ? "; scene outside the record (beta, n or gap clamped to its range)" : "");
  choice.summary = s + buf;
  return choice;
}

}  // namespace hsrod

#include "hydro/near_field_coupling.h"
#include "common/math_constants.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hsrod {

namespace {
// Leading coefficient of Faxen's mid-plane series (Happel & Brenner 1965,
// eq. 7-4.28): the two walls reduce a sphere's mobility by 1.004 (a / l) /
// (6 pi mu a) with l = H/2, i.e. by 1.004 / (3 pi mu H).
constexpr double kFaxenMidplane = 1.004;
// w = exp(-x) < 1e-10 beyond x = 23: such pairs keep the depth-averaged coupling.
constexpr double kBlendCutoff = 23.0;
}  // namespace

std::string NearFieldCalibration::range_problem(const NearFieldCoupling& c) {
  if (!std::isfinite(c.blend_length) || c.blend_length < 0.0 || c.blend_length > 10.0)
    return "blend_length " + std::to_string(c.blend_length) + " outside [0, 10] (gap heights)";
  if (!std::isfinite(c.reflection) || std::abs(c.reflection) > 10.0)
    return "reflection " + std::to_string(c.reflection) + " outside [-10, 10]";
  if (!std::isfinite(c.reflection_along) || std::abs(c.reflection_along) > 10.0)
    return "reflection_along " + std::to_string(c.reflection_along) + " outside [-10, 10]";
  return "";
}

NearFieldCalibration NearFieldCalibration::read(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("near-field coupling file " + path + ": cannot be read");
  NearFieldCalibration out;
  bool header = false, got_nonlocal = false, got_twoway = false;
  std::string line;
  for (int lineno = 1; std::getline(in, line); ++lineno) {
    const std::string where = path + ":" + std::to_string(lineno) + ": ";
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream ss(line);
    std::string key;
    if (!(ss >> key)) continue;
    if (!header) {
      int version = 0;
      if (key != "hsrod-near-field-coupling" || !(ss >> version) || version != 1)
        throw std::runtime_error(where + "expected the header 'hsrod-near-field-coupling 1'");
      header = true;
      continue;
    }
    if (key == "source") {
      std::getline(ss >> std::ws, out.source);
      continue;
    }
    if (key != "nonlocal" && key != "twoway")
      throw std::runtime_error(where + "unknown entry '" + key + "' (expected source, nonlocal or twoway)");
    NearFieldCoupling c;
    std::string extra;
    if (!(ss >> c.blend_length >> c.reflection >> c.reflection_along) || (ss >> extra))
      throw std::runtime_error(where + key + ": expected three numbers, blend_length, reflection and reflection_along");
    const std::string problem = range_problem(c);
    if (!problem.empty()) throw std::runtime_error(where + key + ": " + problem);
    bool& seen = key == "nonlocal" ? got_nonlocal : got_twoway;
    if (seen) throw std::runtime_error(where + key + " given twice");
    seen = true;
    (key == "nonlocal" ? out.nonlocal : out.twoway) = c;
  }
  if (!header) throw std::runtime_error("near-field coupling file " + path + ": empty (no header)");
  if (!got_nonlocal || !got_twoway)
    throw std::runtime_error("near-field coupling file " + path + ": needs one line each for nonlocal and twoway");
  return out;
}

Eigen::Matrix2d rotne_prager_mobility(const Eigen::Vector2d& offset, double mu, double d) {
  const double r = offset.norm(), a = 0.5 * d;
  const Eigen::Vector2d e = offset / r;
  const Eigen::Matrix2d ee = e * e.transpose(), I = Eigen::Matrix2d::Identity();
  if (r >= d)  // Rotne & Prager (1969)
    return ((1.0 + 2.0 * a * a / (3.0 * r * r)) * I + (1.0 - 2.0 * a * a / (r * r)) * ee) / (8.0 * kPi * mu * r);
  // Overlapping spheres (Yamakawa 1970): continuous at r = d, the self mobility at r = 0.
  return ((1.0 - 9.0 * r / (32.0 * a)) * I + (3.0 * r / (32.0 * a)) * ee) / (6.0 * kPi * mu * a);
}

double near_field_weight(double r, double H, const NearFieldCoupling& c) {
  if (!c.active()) return 0.0;
  const double x = r / (c.blend_length * H);
  return x > kBlendCutoff ? 0.0 : std::exp(-x);
}

Eigen::Matrix2d near_field_pair_mobility(const Eigen::Matrix2d& depth_averaged, const Eigen::Vector2d& offset,
                                         double mu, double H, double d, double self_mobility,
                                         const NearFieldCoupling& c) {
  const double w = near_field_weight(offset.norm(), H, c);
  if (w == 0.0) return depth_averaged;
  const double wall = kFaxenMidplane / (3.0 * kPi * mu * H);
  const Eigen::Vector2d e = offset / offset.norm();
  // Rotne-Prager scaled to the confined sphere's own mobility (its r -> 0 limit).
  const double confined = self_mobility * 3.0 * kPi * mu * d;
  const Eigen::Matrix2d slit = confined * rotne_prager_mobility(offset, mu, d) -
                               wall * (c.reflection * Eigen::Matrix2d::Identity() + c.reflection_along * std::pow(d / std::max(offset.norm(), d), 3) * e * e.transpose());
  return (1.0 - w) * depth_averaged + w * slit;
}

}  // namespace hsrod

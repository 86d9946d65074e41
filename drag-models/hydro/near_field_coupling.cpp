#include "hydro/near_field_coupling.h"
#include "common/math_constants.h"

#include <algorithm>
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
  if (!std::isfinite(c.blend_length_along) || c.blend_length_along < 0.0 || c.blend_length_along > 10.0)
    return "blend_length_along " + std::to_string(c.blend_length_along) + " outside [0, 10] (gap heights)";
  return "";
}

std::string NearFieldCalibration::range_problem(const NearFieldAtBeta& c) {
  const std::string f = range_problem(c.friction);
  if (!f.empty()) return "friction: " + f;
  const std::string d = range_problem(c.driving);
  return d.empty() ? d : "driving: " + d;
}

NearFieldLaw NearFieldLaw::constant(const NearFieldCoupling& c) {
  NearFieldLaw law;
  if (!c.active()) return law;
  law.active = true;
  for (auto& load : law.coefficients) {
    load[0] = {std::log(c.blend_length)};
    load[1] = {c.reflection};
    load[2] = {c.reflection_along};
    load[3] = {std::log(c.along())};
  }
  return law;
}

NearFieldAtBeta NearFieldLaw::at(double beta) const {
  if (!active) return {};
  const double x = std::clamp(beta, beta_min, beta_max) - kBetaReference;
  auto poly = [x](const std::vector<double>& c) {
    double v = 0.0;
    for (auto it = c.rbegin(); it != c.rend(); ++it) v = v * x + *it;  // Horner
    return v;
  };
  double value[2][4];  // [load][ln kappa, alpha, alpha_e, ln kappa_e]
  for (int load = 0; load < 2; ++load)
    for (int q = 0; q < 4; ++q)
      value[load][q] = poly(q == 3 && coefficients[load][3].empty() ? coefficients[load][0] : coefficients[load][q]);
  // Below the fitted range the held load's coupling tends to the friction's
  // as (beta / beta_min)^2: in the limit beta -> 0 the flow over a sphere is
  // the uniform mid-plane velocity (the curvature part of the held load,
  // Faxen's (d/2)^2/6 Laplacian of u, vanishes as beta^2), so the held load
  // is the resistance times it and a rod's free velocity tends to 3/2, never
  // above (Berthet et al. 2013).
  if (beta < beta_min && beta_min > 0.0) {
    const double w = std::pow(std::max(beta, 0.0) / beta_min, 2);
    for (int q = 0; q < 4; ++q) value[1][q] = value[0][q] + w * (value[1][q] - value[0][q]);
  }
  NearFieldCoupling out[2];
  for (int load = 0; load < 2; ++load)
    out[load] = {std::exp(value[load][0]), value[load][1], value[load][2], std::exp(value[load][3])};
  return {out[0], out[1]};
}

NearFieldCalibration NearFieldCalibration::read(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("near-field coupling file " + path + ": cannot be read");
  NearFieldCalibration out;
  int version = 0;
  bool got_range = false;
  bool got_v1[2] = {false, false};
  bool got_v2[2][2][4] = {};
  double beta_range[2] = {0.0, 1.0};
  const char* const kLoads[2] = {"friction", "driving"};
  const char* const kParameters[4] = {"ln_blend_length", "reflection", "reflection_along", "ln_blend_length_along"};
  std::string line;
  for (int lineno = 1; std::getline(in, line); ++lineno) {
    const std::string where = path + ":" + std::to_string(lineno) + ": ";
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream ss(line);
    std::string key;
    if (!(ss >> key)) continue;
    if (version == 0) {
      if (key != "hsrod-near-field-coupling" || !(ss >> version) || (version != 1 && version != 2))
        throw std::runtime_error(where + "expected the header 'hsrod-near-field-coupling 1' or '... 2'");
      continue;
    }
    if (key == "source") {
      std::getline(ss >> std::ws, out.source);
      continue;
    }
    if (version == 2 && key == "beta_range") {
      std::string extra;
      if (!(ss >> beta_range[0] >> beta_range[1]) || (ss >> extra) || !std::isfinite(beta_range[0]) ||
          !std::isfinite(beta_range[1]) || beta_range[0] <= 0.0 || beta_range[1] < beta_range[0] || beta_range[1] >= 1.0)
        throw std::runtime_error(where + "beta_range: expected beta_min <= beta_max in (0, 1)");
      got_range = true;
      continue;
    }
    if (key != "nonlocal" && key != "twoway")
      throw std::runtime_error(where + "unknown entry '" + key + "' (expected source, " +
                               (version == 2 ? "beta_range, " : "") + "nonlocal or twoway)");
    const int model = key == "nonlocal" ? 0 : 1;
    NearFieldLaw& law = model == 0 ? out.nonlocal : out.twoway;
    if (version == 1) {
      NearFieldCoupling c;
      std::string extra;
      if (!(ss >> c.blend_length >> c.reflection >> c.reflection_along) || (ss >> extra))
        throw std::runtime_error(where + key + ": expected three numbers, blend_length, reflection and reflection_along");
      const std::string problem = range_problem(c);
      if (!problem.empty()) throw std::runtime_error(where + key + ": " + problem);
      if (got_v1[model]) throw std::runtime_error(where + key + " given twice");
      got_v1[model] = true;
      law = NearFieldLaw::constant(c);
      continue;
    }
    std::string load_name, parameter_name;
    ss >> load_name >> parameter_name;
    int load = -1, parameter = -1;
    for (int k = 0; k < 2; ++k)
      if (load_name == kLoads[k]) load = k;
    for (int k = 0; k < 4; ++k)
      if (parameter_name == kParameters[k]) parameter = k;
    if (load < 0 || parameter < 0)
      throw std::runtime_error(where + key + ": expected '<friction|driving> <ln_blend_length|reflection|reflection_along|"
                                       "ln_blend_length_along> <coefficients>', not '" + load_name + " " + parameter_name + "'");
    std::vector<double> c;
    std::string word;
    while (ss >> word) {
      std::size_t used = 0;
      double v = 0.0;
      try {
        v = std::stod(word, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != word.size() || !std::isfinite(v))
        throw std::runtime_error(where + key + " " + load_name + " " + parameter_name + ": '" + word + "' is not a finite number");
      c.push_back(v);
    }
    if (c.empty() || c.size() > 6)
      throw std::runtime_error(where + key + " " + load_name + " " + parameter_name + ": expected 1 to 6 polynomial coefficients");
    if (got_v2[model][load][parameter]) throw std::runtime_error(where + key + " " + load_name + " " + parameter_name + " given twice");
    got_v2[model][load][parameter] = true;
    law.coefficients[load][parameter] = c;
    law.active = true;
  }
  if (version == 0) throw std::runtime_error("near-field coupling file " + path + ": empty (no header)");
  if (version == 1 && (!got_v1[0] || !got_v1[1]))
    throw std::runtime_error("near-field coupling file " + path + ": needs one line each for nonlocal and twoway");
  if (version == 2) {
    if (!got_range) throw std::runtime_error("near-field coupling file " + path + ": beta_range missing");
    for (int m = 0; m < 2; ++m)
      for (int l = 0; l < 2; ++l)
        for (int k = 0; k < 3; ++k)  // ln_blend_length_along may be left out
          if (!got_v2[m][l][k])
            throw std::runtime_error("near-field coupling file " + path + ": missing line '" +
                                     std::string(m == 0 ? "nonlocal " : "twoway ") + kLoads[l] + " " + kParameters[k] + "'");
    for (NearFieldLaw* law : {&out.nonlocal, &out.twoway}) {
      law->beta_min = beta_range[0];
      law->beta_max = beta_range[1];
      for (int k = 0; k <= 20; ++k) {  // the law must be usable over its whole range
        const double beta = beta_range[0] + (beta_range[1] - beta_range[0]) * k / 20.0;
        const std::string problem = range_problem(law->at(beta));
        if (!problem.empty())
          throw std::runtime_error("near-field coupling file " + path + ": " +
                                   (law == &out.nonlocal ? "nonlocal" : "twoway") + " at beta " + std::to_string(beta) +
                                   ": " + problem);
      }
    }
  }
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

namespace {
double weight(double r, double length) {
  const double x = r / length;
  return x > kBlendCutoff ? 0.0 : std::exp(-x);
}
}  // namespace

double near_field_weight(double r, double H, const NearFieldCoupling& c) {
  if (!c.active()) return 0.0;
  return weight(r, std::max(c.blend_length, c.along()) * H);
}

Eigen::Matrix2d near_field_pair_mobility(const Eigen::Matrix2d& depth_averaged, const Eigen::Vector2d& offset,
                                         double mu, double H, double d, double self_mobility,
                                         const NearFieldCoupling& c) {
  if (near_field_weight(offset.norm(), H, c) == 0.0) return depth_averaged;
  const double wall = kFaxenMidplane / (3.0 * kPi * mu * H);
  const Eigen::Vector2d e = offset / offset.norm();
  const Eigen::Matrix2d ee = e * e.transpose(), transverse = Eigen::Matrix2d::Identity() - ee;
  // Rotne-Prager scaled to the confined sphere's own mobility (its r -> 0 limit).
  const double confined = self_mobility * 3.0 * kPi * mu * d;
  const Eigen::Matrix2d slit = confined * rotne_prager_mobility(offset, mu, d) -
                               wall * (c.reflection * Eigen::Matrix2d::Identity() + c.reflection_along * std::pow(d / std::max(offset.norm(), d), 3) * ee);
  // The component along the line of centres and the transverse one cross
  // over to the Hele-Shaw far field at their own distances (the dipole
  // (2 e e - I) / r^2 beyond ~H keeps the sign of the 3-D coupling along e
  // but reverses it across): each blended with its own weight.
  const double w_t = weight(offset.norm(), c.blend_length * H), w_e = weight(offset.norm(), c.along() * H);
  const Eigen::Matrix2d difference = slit - depth_averaged;
  // (Cross terms, zero for level 3's isotropic forms, with the geometric mean: equal weights give one blend.)
  return depth_averaged + w_t * (transverse * difference * transverse) + w_e * (ee * difference * ee) +
         std::sqrt(w_t * w_e) * (transverse * difference * ee + ee * difference * transverse);
}

}  // namespace hsrod

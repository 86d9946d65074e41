#include "near_field_fit.h"

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "hydro/nonlocal_model.h"
#include "hydro/twoway_near_field.h"

namespace hsrod::calib {

namespace {
const char* const kProfiles[4] = {"friction_par", "friction_perp", "driving_par", "driving_perp"};

const std::vector<double>& profile_of(const RowResponse& m, int q) {
  return q == 0 ? m.friction_par : q == 1 ? m.friction_perp : q == 2 ? m.driving_par : m.driving_perp;
}

std::vector<const NearFieldCase*> fitted(const std::vector<NearFieldCase>& cases) {
  std::vector<const NearFieldCase*> out;
  for (const auto& c : cases)
    if (c.resolved.role == "fit") out.push_back(&c);
  return out;
}

struct Residuals {
  typedef double Scalar;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  typedef Eigen::VectorXd InputType;
  typedef Eigen::VectorXd ValueType;
  typedef Eigen::MatrixXd JacobianType;

  std::vector<const NearFieldCase*> cases;
  int m = 0;
  int inputs() const { return 3; }
  int values() const { return m; }
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
    // Outside the coupling's range (LM's trial steps may go there): a large, smooth penalty.
    const NearFieldCoupling c{std::max(x(0), 1e-6), x(1), x(2)};
    int k = 0;
    for (const NearFieldCase* nc : cases) {
      const RowResponse r = near_field_response(*nc, c);
      for (int q = 0; q < 4; ++q) {
        const std::vector<double>& model = profile_of(r, q);
        const std::vector<double>& res = nc->profiles.at(kProfiles[q]);
        double mean = 0.0;
        for (double v : res) mean += std::abs(v) / res.size();
        const double scale = mean * std::sqrt(double(res.size()));
        for (std::size_t i = 0; i < res.size(); ++i) f(k++) = (model[i] - res[i]) / scale;
      }
    }
    if (x(0) < 0.0) f *= 1.0 + 1e3 * x(0) * x(0);
    return 0;
  }
};
}  // namespace

std::vector<NearFieldCase> near_field_cases(const std::string& level, const std::vector<ResolvedRod>& series,
                                            const std::map<ProfileKey, std::vector<double>>& profiles,
                                            const ConfinementTable& table) {
  if (level != "nonlocal" && level != "twoway")
    throw std::invalid_argument("near field: level must be nonlocal or twoway, not '" + level + "'");
  auto text = [](double x) {
    std::string s = std::to_string(x);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return s;
  };
  std::vector<NearFieldCase> out;
  for (const ResolvedRod& s : series) {
    if (s.n < 2) continue;
    NearFieldCase c;
    c.resolved = s;
    bool complete = true;
    for (const char* q : kProfiles) {
      // keys as written by campaign_analysis.py: beta "0.15", n "10", spacing "1"
      const auto it = profiles.find({text(s.beta), std::to_string(s.n), text(s.spacing), q});
      if (it == profiles.end() || static_cast<int>(it->second.size()) != s.n) complete = false;
      else c.profiles[q] = it->second;
    }
    if (!complete) continue;
    const HydrodynamicParameters p = row_parameters(s.beta);
    std::unique_ptr<HydrodynamicModel> model;
    // Levels 3 and 4 split a sphere's friction the same way (LocalDragBase::obstruction_friction).
    c.obstruction_friction = NonlocalRodModel(p, table, NearFieldCoupling{}).obstruction_friction();
    if (level == "nonlocal") {
      auto m = std::make_unique<NonlocalRodModel>(p, table, NearFieldCoupling{});
      c.film_friction = m->film_friction();
      model = std::move(m);
    } else {
      auto m = std::make_unique<TwoWayWindowModel>(p, table);
      c.film_friction = m->film_friction();
      model = std::move(m);
    }
    c.depth_averaged = row_loads(*model, p, s.n, s.spacing);
    out.push_back(std::move(c));
  }
  return out;
}

RowResponse near_field_response(const NearFieldCase& c, const NearFieldCoupling& coupling) {
  RowLoads loads = c.depth_averaged;
  for (int a = 0; a < 2; ++a) {
    add_near_field(loads.rod[a], loads.parameters, c.film_friction, c.obstruction_friction, coupling, loads.still[a]);
    add_near_field(loads.rod[a], loads.parameters, c.film_friction, c.obstruction_friction, coupling, loads.stream[a]);
  }
  return row_response(loads);
}

double CaseErrors::worst_profile() const { return *std::max_element(profile_rms, profile_rms + 4); }
double CaseErrors::worst_total() const {
  double w = 0.0;
  for (double e : total) w = std::max(w, std::abs(e));
  return w;
}

CaseErrors case_errors(const NearFieldCase& c, const RowResponse& m) {
  CaseErrors e;
  for (int q = 0; q < 4; ++q) {
    const std::vector<double>& model = profile_of(m, q);
    const std::vector<double>& res = c.profiles.at(kProfiles[q]);
    double se = 0.0, mean = 0.0;
    for (std::size_t i = 0; i < res.size(); ++i) {
      se += std::pow(model[i] - res[i], 2);
      mean += std::abs(res[i]);
    }
    e.profile_rms[q] = std::sqrt(se / res.size()) / (mean / res.size());
  }
  const ResolvedRod& s = c.resolved;
  e.total[0] = m.R_par() / s.at("R_par") - 1.0;
  e.total[1] = m.R_perp() / s.at("R_perp") - 1.0;
  e.total[2] = m.D_par() / s.at("D_par") - 1.0;
  e.total[3] = m.D_perp() / s.at("D_perp") - 1.0;
  e.lambda[0] = m.lambda_par() / s.at("lambda_par") - 1.0;
  e.lambda[1] = m.lambda_perp() / s.at("lambda_perp") - 1.0;
  return e;
}

NearFieldFit fit_near_field(const std::vector<NearFieldCase>& cases, const NearFieldCoupling& start) {
  Residuals res;
  res.cases = fitted(cases);
  for (const NearFieldCase* c : res.cases) res.m += 4 * c->resolved.n;
  if (res.m < 3) throw std::invalid_argument("near-field fit: no fitted rows with per-sphere profiles");
  Eigen::NumericalDiff<Residuals> num(res);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Residuals>> lm(num);
  Eigen::VectorXd x(3);
  x << start.blend_length, start.reflection, start.reflection_along;
  const auto status = lm.minimize(x);
  if (status <= 0 || !x.allFinite() || x(0) <= 0.0)
    throw std::runtime_error("near-field fit: Levenberg-Marquardt failed (status " + std::to_string(int(status)) + ")");
  NearFieldFit out;
  out.status = static_cast<int>(status);
  out.coupling = {x(0), x(1), x(2)};
  out.points = res.m;
  out.rows = static_cast<int>(res.cases.size());
  Eigen::VectorXd f(res.m);
  res(x, f);
  Eigen::MatrixXd J(res.m, 3);
  num.df(x, J);
  const double chi2 = f.squaredNorm();
  out.rms_residual = std::sqrt(chi2 / res.m);
  const Eigen::Matrix3d cov = (J.transpose() * J).inverse() * (chi2 / std::max(1, res.m - 3));
  for (int k = 0; k < 3; ++k) out.std_error[k] = std::sqrt(std::max(0.0, cov(k, k)));
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) out.correlation(k, l) = cov(k, l) / std::max(1e-300, out.std_error[k] * out.std_error[l]);
  return out;
}

}  // namespace hsrod::calib

#include "near_field_fit.h"

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include <algorithm>
#include <initializer_list>
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
  int m = 0, degree = 0;
  double beta_min = 0.0, beta_max = 1.0;
  int inputs() const { return 8 * (degree + 1); }
  int values() const { return m; }
  NearFieldLaw law(const Eigen::VectorXd& x) const {
    NearFieldLaw out;
    out.active = true;
    out.beta_min = beta_min;
    out.beta_max = beta_max;
    int k = 0;
    for (auto& load : out.coefficients)
      for (auto& parameter : load) {
        parameter.assign(degree + 1, 0.0);
        for (double& c : parameter) c = x(k++);
      }
    return out;
  }
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
    const NearFieldLaw l = law(x);
    int k = 0;
    for (const NearFieldCase* nc : cases) {
      NearFieldAtBeta c = l.at(nc->resolved.beta);
      // Outside the coupling's range (LM's trial steps may go there): clipped, with a smooth penalty below.
      double penalty = 0.0;
      for (NearFieldCoupling* q : {&c.friction, &c.driving})
        for (double* v : {&q->reflection, &q->reflection_along})
          if (std::abs(*v) > 5.0) {
            penalty += std::pow(std::abs(*v) - 5.0, 2);
            *v = std::copysign(5.0, *v);
          }
      for (NearFieldCoupling* q : {&c.friction, &c.driving})
        for (double* v : {&q->blend_length, &q->blend_length_along})
          if (*v > 5.0) {
            penalty += std::pow(*v - 5.0, 2);
            *v = 5.0;
          }
      const RowResponse r = near_field_response(*nc, c);
      const int k0 = k;
      for (int q = 0; q < 4; ++q) {
        const std::vector<double>& model = profile_of(r, q);
        const std::vector<double>& res = nc->profiles.at(kProfiles[q]);
        double mean = 0.0;
        for (double v : res) mean += std::abs(v) / res.size();
        const double scale = mean * std::sqrt(double(res.size()));
        for (std::size_t i = 0; i < res.size(); ++i) f(k++) = (model[i] - res[i]) / scale;
      }
      const ResolvedRod& s = nc->resolved;
      f(k++) = (r.lambda_par() / s.at("lambda_par") - 1.0) / kVelocityScale * kProfileScale;
      f(k++) = (r.lambda_perp() / s.at("lambda_perp") - 1.0) / kVelocityScale * kProfileScale;
      f(k++) = (r.r() / s.at("r") - 1.0) / kRatioScale * kProfileScale;
      if (penalty > 0.0) f.segment(k0, k - k0) *= 1.0 + 1e3 * penalty;
    }
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
    c.obstruction_friction = NonlocalRodModel(p, table, NearFieldAtBeta{}).obstruction_friction();
    if (level == "nonlocal") {
      auto m = std::make_unique<NonlocalRodModel>(p, table, NearFieldAtBeta{});
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

RowResponse near_field_response(const NearFieldCase& c, const NearFieldLaw& law) {
  return near_field_response(c, law.at(c.resolved.beta));
}

RowResponse near_field_response(const NearFieldCase& c, const NearFieldAtBeta& coupling) {
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
  e.ratio = m.r() / s.at("r") - 1.0;
  e.r = m.r();
  return e;
}

NearFieldFit fit_near_field(const std::vector<NearFieldCase>& cases, const NearFieldCoupling& start, int degree) {
  if (degree < 0 || degree > 4) throw std::invalid_argument("near-field fit: degree in beta must be 0 to 4");
  if (!start.active()) throw std::invalid_argument("near-field fit: the start needs a blend length > 0");
  Residuals res;
  res.cases = fitted(cases);
  res.degree = degree;
  res.beta_min = 1.0;
  res.beta_max = 0.0;
  for (const NearFieldCase* c : res.cases) {
    res.m += 4 * c->resolved.n + 3;
    res.beta_min = std::min(res.beta_min, c->resolved.beta);
    res.beta_max = std::max(res.beta_max, c->resolved.beta);
  }
  const int p = res.inputs();
  if (res.m <= p) throw std::invalid_argument("near-field fit: fewer fitted profile points than parameters");
  Eigen::NumericalDiff<Residuals> num(res);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Residuals>> lm(num);
  lm.parameters.maxfev = 400 * (p + 1);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(p);
  for (int load = 0; load < 2; ++load) {
    x(load * 4 * (degree + 1)) = std::log(start.blend_length);
    x(load * 4 * (degree + 1) + (degree + 1)) = start.reflection;
    x(load * 4 * (degree + 1) + 2 * (degree + 1)) = start.reflection_along;
    x(load * 4 * (degree + 1) + 3 * (degree + 1)) = std::log(start.along());
  }
  const auto status = lm.minimize(x);
  if (status <= 0 || !x.allFinite())
    throw std::runtime_error("near-field fit: Levenberg-Marquardt failed (status " + std::to_string(int(status)) + ")");
  NearFieldFit out;
  out.status = static_cast<int>(status);
  out.law = res.law(x);
  out.degree = degree;
  out.beta_min = res.beta_min;
  out.beta_max = res.beta_max;
  out.points = res.m;
  out.rows = static_cast<int>(res.cases.size());
  Eigen::VectorXd f(res.m);
  res(x, f);
  Eigen::MatrixXd J(res.m, p);
  num.df(x, J);
  const double chi2 = f.squaredNorm();
  double profile_chi2 = 0.0;
  int profile_points = 0, k = 0;
  for (const NearFieldCase* c : res.cases) {
    for (int i = 0; i < 4 * c->resolved.n; ++i, ++k) profile_chi2 += f(k) * f(k);
    profile_points += 4 * c->resolved.n;
    const RowResponse r = near_field_response(*c, out.law);
    const ResolvedRod& s = c->resolved;
    out.worst_fitted_velocity = std::max({out.worst_fitted_velocity, std::abs(r.lambda_par() / s.at("lambda_par") - 1.0),
                                          std::abs(r.lambda_perp() / s.at("lambda_perp") - 1.0)});
    out.worst_fitted_ratio = std::max(out.worst_fitted_ratio, std::abs(r.r() / s.at("r") - 1.0));
    k += 3;
  }
  // Per fitted row the four profiles' squared RMS sum: the RMS over the rows' profiles.
  out.rms_profile_residual = std::sqrt(profile_chi2 / (4.0 * out.rows));
  const Eigen::MatrixXd cov = (J.transpose() * J).completeOrthogonalDecomposition().pseudoInverse() * (chi2 / (res.m - p));
  out.parameters.assign(x.data(), x.data() + p);
  for (int i = 0; i < p; ++i) out.std_error.push_back(std::sqrt(std::max(0.0, cov(i, i))));
  return out;
}

}  // namespace hsrod::calib

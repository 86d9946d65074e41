// hsrod calibration: confinement coefficient fit (see confinement_fit.h).
#include "common/math_constants.h"
#include "confinement_fit.h"
#include "hydro/confinement_forms.h"

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace hsrod::calib {

namespace {
using hsrod::kPi;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto b = item.find_first_not_of(" \t\r");
    const auto e = item.find_last_not_of(" \t\r");
    out.push_back(b == std::string::npos ? "" : item.substr(b, e - b + 1));
  }
  return out;
}

double number(const std::string& s, const std::string& where) {
  try {
    std::size_t pos = 0;
    const double v = std::stod(s, &pos);
    if (pos != s.size()) throw std::invalid_argument(s);
    return v;
  } catch (const std::exception&) {
    throw std::runtime_error(where + ": '" + s + "' is not a number");
  }
}
}  // namespace

std::vector<ForceSample> parse_force_samples(const std::string& text, const std::string& origin) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> header;
  std::vector<ForceSample> out;
  int lineno = 0;
  const std::vector<std::string> need = {"beta", "body", "n_spheres", "d", "mu", "u_mean", "v", "force"};
  std::map<std::string, std::size_t> col;
  while (std::getline(in, line)) {
    ++lineno;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto f = split(line);
    const std::string where = origin + " line " + std::to_string(lineno);
    if (header.empty()) {
      header = f;
      for (std::size_t k = 0; k < f.size(); ++k) col[f[k]] = k;
      for (const auto& n : need)
        if (!col.count(n)) throw std::runtime_error(where + ": header lacks column '" + n + "'");
      continue;
    }
    if (f.size() != header.size()) throw std::runtime_error(where + ": wrong number of columns");
    ForceSample s;
    s.beta = number(f[col["beta"]], where);
    const std::string body = f[col["body"]];
    if (body == "sphere") s.body = FitBody::Sphere;
    else if (body == "rod_parallel") s.body = FitBody::RodParallel;
    else if (body == "rod_perpendicular") s.body = FitBody::RodPerpendicular;
    else throw std::runtime_error(where + ": body '" + body + "' unknown (sphere, rod_parallel, rod_perpendicular)");
    s.n_spheres = static_cast<int>(number(f[col["n_spheres"]], where));
    s.d = number(f[col["d"]], where);
    s.mu = number(f[col["mu"]], where);
    s.u_mean = number(f[col["u_mean"]], where);
    s.v = number(f[col["v"]], where);
    s.force = number(f[col["force"]], where);
    if (!(s.beta >= 0.0 && s.beta < 1.0) || s.n_spheres < 1 || !(s.d > 0.0) || !(s.mu > 0.0))
      throw std::runtime_error(where + ": need 0 <= beta < 1, n_spheres >= 1, d > 0, mu > 0");
    if (s.body == FitBody::Sphere && s.n_spheres != 1)
      throw std::runtime_error(where + ": a sphere sample has n_spheres 1");
    out.push_back(s);
  }
  if (header.empty()) throw std::runtime_error(origin + ": empty (no header)");
  return out;
}

std::vector<ForceSample> read_force_samples(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read force samples '" + path + "'");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_force_samples(ss.str(), path);
}

LinearFit fit_linear(const std::vector<ForceSample>& samples) {
  const int n = static_cast<int>(samples.size());
  Eigen::MatrixXd A(n, 2);
  Eigen::VectorXd f(n);
  for (int k = 0; k < n; ++k) {
    A(k, 0) = samples[k].u_mean;
    A(k, 1) = -samples[k].v;
    f(k) = samples[k].force / samples[k].n_spheres;
  }
  // scale the columns so that the rank test does not depend on units
  const Eigen::Vector2d scale(A.col(0).norm(), A.col(1).norm());
  if (!(scale(0) > 0.0) || !(scale(1) > 0.0))
    throw std::invalid_argument("fit needs runs with a flow (u_mean != 0) and runs with a moving body (v != 0)");
  const Eigen::MatrixXd As = A * scale.cwiseInverse().asDiagonal();
  const auto qr = As.colPivHouseholderQr();
  if (qr.rank() < 2) throw std::invalid_argument("fit: flow and body velocity vary together; a and b not separable");
  const Eigen::Vector2d x = qr.solve(f).cwiseQuotient(scale);
  LinearFit out;
  out.a = x(0);
  out.b = x(1);
  out.n = n;
  const double fr = f.norm();
  out.rms_residual = fr > 0.0 ? (A * x - f).norm() / fr : 0.0;
  return out;
}

ConfinementTable fit_table(const std::vector<ForceSample>& samples, const std::string& source) {
  if (samples.empty()) throw std::invalid_argument("fit_table: no samples");
  const ConfinementTable defaults = ConfinementTable::default_table();
  std::map<double, std::map<FitBody, std::vector<ForceSample>>> groups;
  for (const auto& s : samples) groups[s.beta][s.body].push_back(s);
  if (groups.size() < 2)
    throw std::invalid_argument("fit_table: runs at two or more beta values are needed (the table interpolates in beta)");
  std::vector<ConfinementTable::Row> rows;
  std::set<std::string> fitted;
  for (auto& [beta, bodies] : groups) {
    ConfinementCoefficients c = defaults.at(beta);
    if (bodies.count(FitBody::Sphere)) {
      const auto& g = bodies[FitBody::Sphere];
      const LinearFit fit = fit_linear(g);
      const double zeta0 = 3.0 * kPi * g.front().mu * g.front().d;
      c.sphere_friction = fit.b / zeta0;
      c.sphere_driving = fit.a / fit.b;
      fitted.insert("sphere");
    }
    for (FitBody body : {FitBody::RodParallel, FitBody::RodPerpendicular}) {
      if (!bodies.count(body)) continue;
      const auto& g = bodies[body];
      const LinearFit fit = fit_linear(g);
      const double zeta_sphere = c.sphere_friction * 3.0 * kPi * g.front().mu * g.front().d;
      if (body == FitBody::RodParallel) {
        c.parallel_friction = fit.b / zeta_sphere;
        c.parallel_driving = fit.a / fit.b;
        fitted.insert("rod_parallel");
      } else {
        c.perpendicular_friction = fit.b / zeta_sphere;
        c.perpendicular_driving = fit.a / fit.b;
        fitted.insert("rod_perpendicular");
      }
    }
    rows.push_back({beta, c});
  }
  std::string which;
  for (const auto& f : fitted) which += (which.empty() ? "" : " ") + f;
  return ConfinementTable(rows, source + "; fitted columns: " + which + "; other columns from the defaults");
}

// ---------------------------------------------------------------- curve fits
namespace {

using namespace hsrod::confinement_form;

struct Given {
  std::function<double(double)> lone, c_inf, growth, shielding;
  std::function<double(double, int)> divisor;
  RodLayout layout;
};

// Sizes of the blocks of a rod form's parameters (RodLayout): the leading
// polynomial, the growth k(beta), the shielding e(beta), the held growth.
struct Blocks {
  int poly = 0, growth = 0, shielding = 0, held = 0;
};
Blocks blocks(CurveForm form, int np, const RodLayout& l) {
  Blocks b;
  switch (form) {
    case CurveForm::RodColumn: b.shielding = l.shielding_terms; break;
    case CurveForm::RodColumnGrowth: b.growth = l.growth_terms, b.shielding = l.shielding_terms; break;
    case CurveForm::RodVelocityRatio: b.held = l.held_growth_terms; break;
    default: break;
  }
  b.poly = np - b.growth - b.shielding - b.held;
  return b;
}

double given_shielding(const Given& g, double beta) { return g.shielding ? g.shielding(beta) : 0.0; }

double curve_value(CurveForm form, const double* p, int np, double beta, int n, const Given& g) {
  const Blocks k = blocks(form, np, g.layout);
  switch (form) {
    case CurveForm::SphereFriction:
      return np > 2 ? sphere_friction(beta, p[0], p[1], p[2])
             : np > 1 ? sphere_friction(beta, p[0], p[1])
                      : sphere_friction(beta, p[0]);
    case CurveForm::SphereDriving:
      return np > 1 ? sphere_driving(beta, p[0], p[1]) : sphere_driving(beta, p[0]);
    case CurveForm::RodColumn:
      return rod_n_law(polynomial(p, k.poly, beta), 1.0, 0.0, n, polynomial(p + k.poly, k.shielding, beta));
    case CurveForm::RodColumnGrowth:
      return rod_n_law(polynomial(p, k.poly, beta), 1.0, rod_growth(beta, p + k.poly, k.growth), n,
                       polynomial(p + k.poly + k.growth, k.shielding, beta));
    case CurveForm::RodHeld: {
      const double ls = g.lone(beta);
      return rod_n_law(g.c_inf(beta) * rod_driving_inf(beta, p, np), ls, g.growth(beta) * ls, n,
                       given_shielding(g, beta) * ls);
    }
    case CurveForm::RodVelocity:
      return rod_velocity(g.c_inf(beta), rod_driving_inf(beta, p, np), g.lone(beta), g.growth(beta), g.growth(beta), n,
                          given_shielding(g, beta));
    case CurveForm::RodVelocityRatio:
      return rod_velocity(g.c_inf(beta), rod_driving_inf(beta, p, k.poly), g.lone(beta), g.growth(beta),
                          rod_growth(beta, p + k.poly, k.held), n, given_shielding(g, beta)) /
             g.divisor(beta, n);
  }
  return 0.0;
}

// Weighted residuals (model - value) / sigma for Eigen's LM.
struct CurveResiduals {
  typedef double Scalar;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  typedef Eigen::VectorXd InputType;
  typedef Eigen::VectorXd ValueType;
  typedef Eigen::MatrixXd JacobianType;

  CurveForm form;
  const std::vector<CurvePoint>* points;
  Given given;
  int np;
  int inputs() const { return np; }
  int values() const { return static_cast<int>(points->size()); }
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
    for (int i = 0; i < values(); ++i) {
      const CurvePoint& q = (*points)[i];
      f(i) = (curve_value(form, x.data(), np, q.beta, q.n, given) - q.value) / q.sigma;
    }
    return 0;
  }
};

}  // namespace

double CurveFit::operator()(double beta, int n) const {
  return curve_value(form, params.data(), static_cast<int>(params.size()), beta, n,
                     {lone, rod_friction_inf, growth, shielding, divisor, layout});
}

double CurveFit::velocity(double beta, int n) const {
  if (form == CurveForm::RodVelocityRatio) return (*this)(beta, n) * divisor(beta, n);
  return (*this)(beta, n);
}

double CurveFit::held_growth_at(double beta) const {
  if (form == CurveForm::RodVelocityRatio) {
    const Blocks k = blocks(form, static_cast<int>(params.size()), layout);
    return confinement_form::rod_growth(beta, params.data() + k.poly, k.held);
  }
  return growth ? growth(beta) : 0.0;
}

double CurveFit::asymptote(double beta) const {
  const int np = static_cast<int>(params.size());
  const Blocks k = blocks(form, np, layout);
  if (form == CurveForm::RodColumn || form == CurveForm::RodColumnGrowth)
    return confinement_form::polynomial(params.data(), k.poly, beta);
  if (form == CurveForm::RodHeld || form == CurveForm::RodVelocity || form == CurveForm::RodVelocityRatio)
    return confinement_form::rod_driving_inf(beta, params.data(), k.poly);
  return (*this)(beta, 1);
}

double CurveFit::growth_at(double beta) const {
  if (form != CurveForm::RodColumnGrowth) return 0.0;
  const Blocks k = blocks(form, static_cast<int>(params.size()), layout);
  return confinement_form::rod_growth(beta, params.data() + k.poly, k.growth);
}

double CurveFit::shielding_at(double beta) const {
  if (form == CurveForm::RodColumn || form == CurveForm::RodColumnGrowth) {
    const Blocks k = blocks(form, static_cast<int>(params.size()), layout);
    return confinement_form::polynomial(params.data() + k.poly + k.growth, k.shielding, beta);
  }
  return shielding ? shielding(beta) : 0.0;
}

CurveFit fit_curve(CurveForm form, const std::vector<CurvePoint>& points, std::vector<double> start,
                   std::function<double(double)> lone, std::function<double(double)> rod_friction_inf,
                   std::function<double(double)> growth, std::function<double(double, int)> divisor,
                   const RodLayout& layout, std::function<double(double)> shielding) {
  const int np = static_cast<int>(start.size()), m = static_cast<int>(points.size());
  if (np < 1 || m < np) throw std::invalid_argument("fit_curve: need at least as many points as parameters");
  for (const auto& q : points)
    if (!(q.sigma > 0.0) || q.n < 1 || !std::isfinite(q.value))
      throw std::invalid_argument("fit_curve: every point needs sigma > 0, n >= 1 and a finite value");
  const bool rod_given = form == CurveForm::RodHeld || form == CurveForm::RodVelocity || form == CurveForm::RodVelocityRatio;
  if (rod_given && !(lone && rod_friction_inf && growth))
    throw std::invalid_argument("fit_curve: RodHeld / RodVelocity need lambda_s, c_inf and g as functions of beta");
  if (form == CurveForm::RodVelocityRatio && (!divisor || np < 2))
    throw std::invalid_argument("fit_curve: RodVelocityRatio needs the parallel velocity lambda_par(beta, n) and "
                                "a polynomial term and k_held");
  if ((form == CurveForm::SphereFriction && np > 3) || (form == CurveForm::SphereDriving && np > 2))
    throw std::invalid_argument("fit_curve: the sphere friction has one to three parameters, the sphere driving one or two");
  if (form == CurveForm::RodColumnGrowth && np < 2)
    throw std::invalid_argument("fit_curve: RodColumnGrowth needs a polynomial term and k");
  if (layout.growth_terms < 1 || layout.held_growth_terms < 1 || layout.shielding_terms < 0)
    throw std::invalid_argument("fit_curve: the growth and held growth have at least one term, the shielding none or more");
  if (blocks(form, np, layout).poly < 1)
    throw std::invalid_argument("fit_curve: the start values leave no polynomial term after the layout's blocks");
  CurveResiduals res{form, &points, {lone, rod_friction_inf, growth, shielding, divisor, layout}, np};
  Eigen::NumericalDiff<CurveResiduals> num(res);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<CurveResiduals>> lm(num);
  Eigen::VectorXd x = Eigen::Map<Eigen::VectorXd>(start.data(), np);
  const auto status = lm.minimize(x);
  if (status <= 0 || !x.allFinite())
    throw std::runtime_error("fit_curve: Levenberg-Marquardt failed (status " + std::to_string(int(status)) + ")");
  CurveFit out;
  out.form = form;
  out.lone = lone;
  out.rod_friction_inf = rod_friction_inf;
  out.growth = growth;
  out.shielding = shielding;
  out.divisor = divisor;
  out.layout = layout;
  out.params.assign(x.data(), x.data() + np);
  Eigen::VectorXd f(m);
  res(x, f);
  Eigen::MatrixXd J(m, np);
  num.df(x, J);
  const double chi2 = f.squaredNorm();
  out.chi2_per_dof = m > np ? chi2 / (m - np) : 0.0;
  // covariance of the parameters: s^2 (J^T J)^-1 (J already weighted by 1/sigma);
  // s^2 = chi2/dof rescales to the observed scatter (1 if the sigmas are right)
  const Eigen::MatrixXd cov = (J.transpose() * J).inverse() * (m > np ? std::max(1.0, out.chi2_per_dof) : 1.0);
  for (int k = 0; k < np; ++k) out.std_errors.push_back(std::sqrt(std::max(0.0, cov(k, k))));
  double s2 = 0.0;
  for (int i = 0; i < m; ++i) {
    const double rel = (out(points[i].beta, points[i].n) - points[i].value) / points[i].value;
    out.relative_residuals.push_back(rel);
    s2 += rel * rel;
    out.max_relative = std::max(out.max_relative, std::abs(rel));
  }
  out.rms_relative = std::sqrt(s2 / m);
  return out;
}

}  // namespace hsrod::calib

// hsrod_fit_wall_proximity: fits the near-wall correction of the reduced
// levels (drag-models/hydro/wall_proximity.h) to the resolved rows near a
// side wall and beside a pore cylinder (campaign "geometry").
//
//   hsrod_fit_wall_proximity CASES.csv --json OUT.json --cpp OUT.cpp
//                            [--hold-out CASE,CASE,...] [--levels twoway,nonlocal,local]
//
// CASES.csv: calibration/data/resolved_geometry_per_sphere.csv (finest mesh).
// For each level family (levels 1-2: fitted on level 2, `local`; level 3;
// level 4) the level is evaluated once per case without the correction (the
// correction is additive to its load), then the nine parameters are fitted by
// Eigen's Levenberg-Marquardt to every sphere's in-plane force, residual
// (model + correction - resolved) / mean |F_resolved| / sqrt(n) (each case
// weighs the same whatever its number of spheres); the screening length is
// fitted as its logarithm (it must stay > 0). Parameter uncertainties:
// s^2 (J^T J)^-1 with s^2 = SSR / (m - p). The held-out cases are not in the
// fit; their errors are reported beside the fitted ones. OUT.json: parameters,
// standard errors, residual RMS (fit / held out), per-case errors of the
// totals and profiles before and after; OUT.cpp: the built-in law
// (drag-models/hydro/wall_proximity_fit.cpp).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "scene_crosscheck.h"

using namespace hsrod::calib;
using hsrod::WallProximityLaw;

namespace {

const char* kNames[WallProximityLaw::kParameters] = {"normal",    "along",       "ln_screening", "normal_row_gain",
                                                     "along_row_gain", "normal_held", "along_held", "squeeze",
                                                     "squeeze_held"};

WallProximityLaw law_of(const Eigen::VectorXd& x) {
  WallProximityLaw w;
  w.active = true;
  w.normal = x[0];
  w.along = x[1];
  w.screening = std::exp(x[2]);
  w.normal_row_gain = x[3];
  w.along_row_gain = x[4];
  w.normal_held = x[5];
  w.along_held = x[6];
  w.squeeze = x[7];
  w.squeeze_held = x[8];
  return w;
}

struct Prepared {
  const SceneCase* c;
  SceneLoad load;
  std::vector<Eigen::Vector2d> base;  // the level without the correction
  double mean = 0.0;                  // mean |F_i,resolved|
};

std::vector<Eigen::Vector2d> corrected(const Prepared& p, const WallProximityLaw& w) {
  std::vector<Eigen::Vector2d> f = p.base;
  const auto dw = wall_proximity_forces(w, *p.c, p.load);
  for (std::size_t i = 0; i < f.size(); ++i) f[i] += dw[i];
  return f;
}

struct Residuals {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  const std::vector<const Prepared*>* cases;
  int m = 0;
  double fixed_ln_screening = NAN;  // NaN: fitted
  bool friction_only = false;       // held-load parameters fixed at 0
  int inputs() const { return WallProximityLaw::kParameters; }
  int values() const { return m; }
  int operator()(const Eigen::VectorXd& x_in, Eigen::VectorXd& r) const {
    Eigen::VectorXd x = x_in;
    if (!std::isnan(fixed_ln_screening)) x[2] = fixed_ln_screening;
    if (friction_only) x[5] = x[6] = x[8] = 0.0;
    const WallProximityLaw w = law_of(x);
    int k = 0;
    for (const Prepared* p : *cases) {
      const auto f = corrected(*p, w);
      const double weight = 1.0 / (p->mean * std::sqrt(static_cast<double>(f.size())));
      for (std::size_t i = 0; i < f.size(); ++i)
        for (int c = 0; c < 2; ++c) r[k++] = (f[i][c] - p->c->resolved[i][c]) * weight;
    }
    return 0;
  }
};

struct CaseError {
  double fx = NAN, fy = NAN, rms = 0.0;  // totals (NaN: component < 20 % of |F|), profile RMS
};

CaseError errors(const Prepared& p, const std::vector<Eigen::Vector2d>& f) {
  Eigen::Vector2d tm = Eigen::Vector2d::Zero(), tr = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < f.size(); ++i) {
    tm += f[i];
    tr += p.c->resolved[i];
  }
  CaseError e;
  if (std::abs(tr.x()) >= 0.2 * tr.norm()) e.fx = tm.x() / tr.x() - 1.0;
  if (std::abs(tr.y()) >= 0.2 * tr.norm()) e.fy = tm.y() / tr.y() - 1.0;
  e.rms = profile_rms(f, p.c->resolved);
  return e;
}

std::string number(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

struct Options {
  std::string cases_path, json_path, cpp_path,
      hold_out = "wall_a45_g1.5_b0.300_n5,wall_a0_g0.5_b0.300_n10,pore_a90_g1.5_b0.300_n5";
  std::string levels = "twoway,nonlocal,local";
  bool friction_only = false;
};

void add_options(CLI::App& app, Options& o) {
  app.add_option("cases", o.cases_path)->required()->check(CLI::ExistingFile);
  app.add_option("--json", o.json_path, "fit report (parameters, uncertainties, residuals)")->required();
  app.add_option("--cpp", o.cpp_path, "built-in law (drag-models/hydro/wall_proximity_fit.cpp)")->required();
  app.add_option("--hold-out", o.hold_out, "cases (both loads) left out of the fit");
  app.add_option("--levels", o.levels,
                 "levels to fit, twoway first (its screening is the others'); nonlocal+images: level 3 with the "
                 "walls' images, fitted into the nonlocal slot");
  app.add_flag("--friction-only", o.friction_only, "held-load parameters b_n, b_t, b_q fixed at 0");
}

// every case with the level's loads without the correction and its mean |F_i,resolved|
std::vector<Prepared> prepare(const std::string& level, const std::vector<SceneCase>& cases,
                              const hsrod::ConfinementTable& table, const hsrod::WallProximityCalibration& off) {
  std::vector<Prepared> prepared;
  for (const SceneCase& c : cases) {
    Prepared p{&c, scene_load(c), scene_forces(level, c, table, hsrod::NearFieldCalibration::built_in(), off)};
    for (const auto& f : c.resolved) p.mean += f.norm() / c.resolved.size();
    prepared.push_back(std::move(p));
  }
  return prepared;
}

// one level's least-squares fit over the cases not held out
struct LevelFit {
  Eigen::VectorXd x;    // parameters (index 2: ln screening), fixed ones at their values
  Eigen::VectorXd r;    // residuals at x
  Eigen::MatrixXd cov;  // s^2 (J^T J)^-1; 0 on the diagonal of fixed parameters
  int status = 0;       // Levenberg-Marquardt status
  int m = 0;            // residuals (two per sphere)
  std::size_t fit_cases = 0;
};

// fixed_ln_screening: NaN to fit the screening length
LevelFit fit_level(const std::vector<Prepared>& prepared, const std::set<std::string>& held,
                   double fixed_ln_screening, bool friction_only) {
  std::vector<const Prepared*> fit_cases;
  int m = 0;
  for (const Prepared& p : prepared) {
    if (!held.count(p.c->name)) {
      fit_cases.push_back(&p);
      m += 2 * static_cast<int>(p.c->resolved.size());
    }
  }
  Residuals res;
  res.cases = &fit_cases;
  res.m = m;
  res.fixed_ln_screening = fixed_ln_screening;
  res.friction_only = friction_only;
  Eigen::VectorXd x(WallProximityLaw::kParameters);
  x << 0.5, 0.3, std::log(1.0), 0.5, 0.3, 0.0, 0.0, 0.0, 0.0;
  Eigen::NumericalDiff<Residuals> num(res);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Residuals>> lm(num);
  lm.parameters.maxfev = 4000;
  lm.parameters.xtol = 1e-10;
  lm.parameters.ftol = 1e-10;
  const auto status = lm.minimize(x);
  if (!std::isnan(res.fixed_ln_screening)) x[2] = res.fixed_ln_screening;
  if (friction_only) x[5] = x[6] = x[8] = 0.0;
  Eigen::VectorXd r(m);
  res(x, r);
  Eigen::MatrixXd J(m, WallProximityLaw::kParameters);
  num.df(x, J);
  const int dof = std::max(1, m - WallProximityLaw::kParameters);
  const double s2 = r.squaredNorm() / dof;
  std::vector<int> fixed;
  if (!std::isnan(res.fixed_ln_screening)) fixed.push_back(2);
  if (friction_only) fixed.insert(fixed.end(), {5, 6, 8});
  for (int k : fixed) J.col(k).setZero();
  Eigen::MatrixXd JtJ = J.transpose() * J;
  for (int k : fixed) JtJ(k, k) = 1.0;  // not fitted: no uncertainty of its own
  Eigen::MatrixXd cov = s2 * JtJ.inverse();
  for (int k : fixed) cov(k, k) = 0.0;
  LevelFit f;
  f.x = x;
  f.r = r;
  f.cov = cov;
  f.status = static_cast<int>(status);
  f.m = m;
  f.fit_cases = fit_cases.size();
  return f;
}

// one level's report: parameters, per-case errors before and after the
// correction (fitted and held out), printed and as the report's JSON entry
nlohmann::json report_level(const std::string& level, const std::vector<Prepared>& prepared,
                            const std::set<std::string>& held, const LevelFit& fit, const WallProximityLaw& w,
                            bool friction_only) {
  const Eigen::VectorXd& x = fit.x;
  const int m = fit.m;
  nlohmann::json lj;
  lj["lm_status"] = fit.status;
  lj["fit_points"] = m;
  lj["fit_cases"] = fit.fit_cases;
  lj["residual_rms"] = std::sqrt(fit.r.squaredNorm() / m);
  for (int k = 0; k < WallProximityLaw::kParameters; ++k) {
    lj["parameters"][kNames[k]] = x[k];
    lj["standard_errors"][kNames[k]] = std::sqrt(std::max(0.0, fit.cov(k, k)));
  }
  lj["parameters"]["screening"] = w.screening;
  lj["screening_from_level_4"] = level != "twoway";
  lj["friction_only"] = friction_only;
  double held_se = 0.0;
  int held_m = 0;
  std::printf("%s: LM status %d, %d points, residual RMS %.4f\n", level.c_str(), fit.status, m,
              std::sqrt(fit.r.squaredNorm() / m));
  for (int k = 0; k < WallProximityLaw::kParameters; ++k)
    std::printf("  %-16s %+.4f +- %.4f\n", kNames[k], x[k], std::sqrt(std::max(0.0, fit.cov(k, k))));
  double worst_before = 0.0, worst_after = 0.0, rms_before = 0.0, rms_after = 0.0;
  for (const Prepared& p : prepared) {
    const bool out = held.count(p.c->name) > 0;
    const auto f = corrected(p, w);
    const CaseError b = errors(p, p.base), a = errors(p, f);
    if (out)
      for (std::size_t i = 0; i < f.size(); ++i) {
        held_se += (f[i] - p.c->resolved[i]).squaredNorm() / (p.mean * p.mean * f.size());
        held_m += 2;
      }
    nlohmann::json cj;
    cj["case"] = p.c->name;
    cj["load"] = p.c->load;
    cj["held_out"] = out;
    cj["before"] = {{"F_x", b.fx}, {"F_y", b.fy}, {"profile_rms", b.rms}};
    cj["after"] = {{"F_x", a.fx}, {"F_y", a.fy}, {"profile_rms", a.rms}};
    lj["cases"].push_back(cj);
    const auto worst = [](const CaseError& e) {
      return std::max(std::isnan(e.fx) ? 0.0 : std::abs(e.fx), std::isnan(e.fy) ? 0.0 : std::abs(e.fy));
    };
    worst_before = std::max(worst_before, worst(b));
    worst_after = std::max(worst_after, worst(a));
    rms_before = std::max(rms_before, b.rms);
    rms_after = std::max(rms_after, a.rms);
    std::printf("  %s %-26s %-8s F_x %+6.1f -> %+6.1f %%  F_y %+6.1f -> %+6.1f %%  profile %5.1f -> %5.1f %%\n",
                out ? "H" : " ", p.c->name.c_str(), p.c->load.c_str(), 100 * b.fx, 100 * a.fx, 100 * b.fy,
                100 * a.fy, 100 * b.rms, 100 * a.rms);
  }
  lj["held_out_residual_rms"] = held_m ? std::sqrt(held_se / held_m) : 0.0;
  lj["worst_total_error"] = {{"before", worst_before}, {"after", worst_after}};
  lj["worst_profile_rms"] = {{"before", rms_before}, {"after", rms_after}};
  std::printf("  worst totals %.1f -> %.1f %%, worst profile RMS %.1f -> %.1f %%; held-out residual RMS %.4f\n",
              100 * worst_before, 100 * worst_after, 100 * rms_before, 100 * rms_after,
              held_m ? std::sqrt(held_se / held_m) : 0.0);
  return lj;
}

// the built-in law (drag-models/hydro/wall_proximity_fit.cpp)
void write_cpp(const Options& o, const hsrod::WallProximityCalibration& fitted, double beta_min, double beta_max) {
  std::ofstream cpp(o.cpp_path);
  cpp << "// The shipped near-wall fit (hydro/wall_proximity.h), written by\n"
         "//   build/hsrod_fit_wall_proximity (calibration/tools/fit_wall_proximity.cpp)\n"
         "// Do not edit: equals calibration/data/wall_proximity_fit.json's parameters\n"
         "// (test calibration_WallProximity.BuiltInLawIsTheShippedFit).\n"
         "#include \"hydro/wall_proximity.h\"\n\nnamespace hsrod {\n\n"
         "namespace {\nWallProximityLaw law(double normal, double along, double screening, double normal_row_gain,\n"
         "                     double along_row_gain, double normal_held, double along_held, double squeeze,\n"
         "                     double squeeze_held) {\n"
         "  WallProximityLaw w;\n  w.active = true;\n  w.normal = normal;\n  w.along = along;\n"
         "  w.screening = screening;\n  w.normal_row_gain = normal_row_gain;\n  w.along_row_gain = along_row_gain;\n"
         "  w.normal_held = normal_held;\n  w.along_held = along_held;\n  w.squeeze = squeeze;\n"
         "  w.squeeze_held = squeeze_held;\n"
         "  w.beta_min = "
      << number(beta_min) << ";\n  w.beta_max = " << number(beta_max)
      << ";\n  return w;\n}\n}  // namespace\n\n"
         "const WallProximityCalibration& WallProximityCalibration::built_in() {\n"
         "  static const WallProximityCalibration fitted = [] {\n    WallProximityCalibration c;\n";
  for (const auto& [name, w] : {std::make_pair("local", fitted.local), std::make_pair("nonlocal", fitted.nonlocal),
                                std::make_pair("twoway", fitted.twoway)})
    cpp << "    c." << name << " = law(" << number(w.normal) << ", " << number(w.along) << ", " << number(w.screening)
        << ", " << number(w.normal_row_gain) << ", " << number(w.along_row_gain) << ", " << number(w.normal_held)
        << ", " << number(w.along_held) << ", " << number(w.squeeze) << ", " << number(w.squeeze_held) << ");\n";
  // Shipped for level 4 only: levels 1-3's fits (in the report) stay 22-23 %
  // off near walls and pores and, in the dynamic pore passages, push the
  // rod the wrong way (calibration/validation/pore_passage/README.md; the
  // paper's 45-degree example's drift flips sign): kept, not applied.
  cpp << "    // levels 1-3: fitted (calibration/data/wall_proximity_fit.json) but not applied: they stay 22-23 %\n"
         "    // off near walls and pores and push the dynamic pore passages the wrong way (pore_passage/README.md)\n"
         "    c.local.active = false;\n    c.nonlocal.active = false;\n";
  cpp << "    c.source = \"hsrod_fit_wall_proximity on " << o.cases_path << " (held out: " << o.hold_out
      << ")\";\n    return c;\n  }();\n  return fitted;\n}\n\n}  // namespace hsrod\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fit the near-wall correction of hsrod's reduced levels to the resolved wall and pore rows"};
  Options o;
  add_options(app, o);
  CLI11_PARSE(app, argc, argv);
  try {
    std::set<std::string> held;
    {
      std::stringstream in(o.hold_out);
      std::string name;
      while (std::getline(in, name, ',')) held.insert(name);
    }
    std::vector<SceneCase> cases;
    for (SceneCase& c : read_scene_cases(o.cases_path))
      if (c.geometry != "bent") cases.push_back(std::move(c));
    const auto table = hsrod::ConfinementTable::default_table();
    const auto off = hsrod::WallProximityCalibration::off();
    nlohmann::json report;
    report["cases"] = o.cases_path;
    report["held_out"] = std::vector<std::string>(held.begin(), held.end());
    report["form"] = "drag-models/hydro/wall_proximity.h";
    hsrod::WallProximityCalibration fitted;
    double beta_min = 1.0, beta_max = 0.0;
    for (const SceneCase& c : cases) {
      beta_min = std::min(beta_min, c.beta);
      beta_max = std::max(beta_max, c.beta);
    }
    // Level 4 first: its screening length (the range over which the side
    // wall's 3-D disturbance survives the gap walls) is taken by levels 1-3
    // too, so that every level corrects the same near-wall physics; a free
    // screening lets levels 1-3 stretch the correction over ~3-9 H to mimic
    // the depth-averaged reflection off the walls they lack (a channel-wide
    // effect, not a near-wall one), which slowed the dynamic pore passage of
    // level 2 by 6 % (calibration/validation/pore_passage).
    double ln_screening_level4 = NAN;
    std::vector<std::string> levels;
    {
      std::stringstream in(o.levels);
      for (std::string l; std::getline(in, l, ',');) levels.push_back(l);
    }
    for (const std::string& level : levels) {
      const std::vector<Prepared> prepared = prepare(level, cases, table, off);
      const LevelFit fit = fit_level(prepared, held, level != "twoway" ? ln_screening_level4 : NAN, o.friction_only);
      if (level == "twoway") ln_screening_level4 = fit.x[2];
      const WallProximityLaw w = law_of(fit.x);
      report["levels"][level] = report_level(level, prepared, held, fit, w, o.friction_only);
      WallProximityLaw& slot = level == "local" ? fitted.local : level == "twoway" ? fitted.twoway : fitted.nonlocal;
      slot = w;
      slot.beta_min = beta_min;
      slot.beta_max = beta_max;
    }
    std::ofstream(o.json_path) << report.dump(1) << '\n';
    write_cpp(o, fitted, beta_min, beta_max);
    std::printf("wrote %s and %s\n", o.json_path.c_str(), o.cpp_path.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hsrod_fit_wall_proximity: %s\n", e.what());
    return 1;
  }
  return 0;
}

// hsrod_fit_campaign: levels 1 and 2 of the confinement table fitted to the
// resolved campaign (calibration/tools/hsrod_campaign.py).
//
//   hsrod_fit_campaign POINTS.csv OUT_TABLE.txt [--report FIT.json] [--source TEXT] [--cpp HEADER]
//
// POINTS.csv (calibration/tools/campaign_analysis.py --points): columns
// quantity,beta,n,value,sigma,role; quantity one of
//   sphere_friction   lone sphere's friction over 3 pi mu d            (n = 1)
//   sphere_driving    lone sphere's force-free velocity over the gap mean (n = 1)
//   par_friction, perp_friction   rod's friction per sphere over the lone
//                     sphere's, along / across its axis
//   par_held, perp_held           rod's held-in-flow load per sphere over
//                     (lone sphere friction x gap-mean velocity) (reported)
//   par_velocity, perp_velocity   rod's force-free velocity over the gap mean
//   velocity_ratio    r = lambda_perp / lambda_par
// role "fit" points are fitted, others ("heldout", ...) only predicted.
// Fits (calibration/core/confinement_fit.h, Eigen Levenberg-Marquardt):
// sphere columns with the Faxen-type forms (Faxen's published coefficients
// kept where the fit does not reject them), rod friction with the n-law
// c(beta, n) = c_inf + (1 - c_inf - g)/n + g n + e ln(n)/n, c_inf polynomial
// in beta; along the axis g = 0 and the 3-D shielding e (polynomial,
// --shielding-terms), across it e = 0 and g = beta^2 k(beta) (polynomial,
// --growth-terms); the rod's force-free velocity
// along the axis fitted to the resolved velocities (RodVelocity), across it
// to the resolved r (RodVelocityRatio, with its own held growth
// g_held = beta^2 k_held(beta), polynomial, --held-growth-terms):
// r - 1 is a few 1e-3 and both velocities share one mesh, so r is measured
// far better than either velocity and is fitted directly. The table (format
// "hsrod-confinement-coefficients 1") holds the rows beta = 0, 0.05, .., 0.85
// of a rod of n = 10 (the table's definition of the rod columns):
// *_friction = c(beta, 10), *_driving = lambda(beta, 10). --cpp writes the
// parameters as drag-models/hydro/default_coefficients_fit.h (the built-in
// table). One command for collect, fit and error record:
// calibration/campaign/refit.sh.
#include <CLI/CLI.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "confinement_fit.h"

using namespace hsrod::calib;

namespace {

// Published lone-sphere coefficients (hydro/confinement_forms.h): Faxen's
// mid-plane friction series (Happel & Brenner 1965, eq. 7-4.28) and Faxen's
// law in the parabolic gap profile.
constexpr double kFaxenFriction = 1.004, kFaxenCubic = 0.418, kFaxenQuintic = 0.169, kFaxenDriving = 1.0 / 3.0;
// Default terms of the polynomials in beta: the infinite rod's friction per
// sphere c_inf(beta) and its velocity's correction q(beta)
// (confinement_forms.h); --friction-terms, --velocity-terms.
constexpr int kFrictionTerms = 3, kVelocityTerms = 3;

struct Point {
  std::string quantity, role;
  CurvePoint p;
};

std::vector<Point> read_points(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string line;
  std::vector<Point> out;
  bool header = false;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      if (line.rfind("quantity,beta,n,value,sigma,role", 0) != 0)
        throw std::runtime_error(path + ": header must be quantity,beta,n,value,sigma,role");
      header = true;
      continue;
    }
    std::stringstream ss(line);
    std::string f[6];
    for (auto& x : f) std::getline(ss, x, ',');
    Point pt;
    pt.quantity = f[0];
    pt.role = f[5];
    try {
      pt.p.beta = std::stod(f[1]);
      pt.p.n = std::stoi(f[2]);
      pt.p.value = std::stod(f[3]);
      pt.p.sigma = std::stod(f[4]);
    } catch (const std::exception&) {
      throw std::runtime_error(path + " line " + std::to_string(lineno) + ": bad number");
    }
    out.push_back(pt);
  }
  return out;
}

std::vector<CurvePoint> select(const std::vector<Point>& pts, const std::string& q, bool fit) {
  std::vector<CurvePoint> out;
  for (const auto& p : pts)
    if (p.quantity == q && ((p.role == "fit") == fit)) out.push_back(p.p);
  return out;
}

std::string json_fit(const std::string& name, const CurveFit& f, const std::vector<CurvePoint>& pts,
                     const std::vector<CurvePoint>& held) {
  std::ostringstream os;
  os.precision(10);
  os << "  \"" << name << "\": {\"params\": [";
  for (std::size_t k = 0; k < f.params.size(); ++k) os << (k ? ", " : "") << f.params[k];
  os << "], \"std_errors\": [";
  for (std::size_t k = 0; k < f.std_errors.size(); ++k) os << (k ? ", " : "") << f.std_errors[k];
  os << "], \"chi2_per_dof\": " << f.chi2_per_dof << ", \"rms_relative\": " << f.rms_relative
     << ", \"max_relative\": " << f.max_relative << ",\n    \"points\": [";
  for (std::size_t i = 0; i < pts.size(); ++i)
    os << (i ? ", " : "") << "{\"beta\": " << pts[i].beta << ", \"n\": " << pts[i].n << ", \"value\": " << pts[i].value
       << ", \"sigma\": " << pts[i].sigma << ", \"fit\": " << f(pts[i].beta, pts[i].n) << "}";
  os << "],\n    \"heldout\": [";
  for (std::size_t i = 0; i < held.size(); ++i)
    os << (i ? ", " : "") << "{\"beta\": " << held[i].beta << ", \"n\": " << held[i].n << ", \"value\": " << held[i].value
       << ", \"sigma\": " << held[i].sigma << ", \"predicted\": " << f(held[i].beta, held[i].n) << "}";
  os << "]}";
  return os.str();
}

void print_fit(const char* name, const CurveFit& f, const std::vector<CurvePoint>& held) {
  std::printf("%-16s params", name);
  for (std::size_t k = 0; k < f.params.size(); ++k) std::printf(" %.6f +- %.6f", f.params[k], f.std_errors[k]);
  std::printf("; %zu points, rms %.3f %%, max %.3f %%, chi2/dof %.2f\n", f.relative_residuals.size(),
              100 * f.rms_relative, 100 * f.max_relative, f.chi2_per_dof);
  for (const auto& h : held)
    std::printf("%-16s   held out beta %.3f n %d: resolved %.5f, fit %.5f (%+.2f %%)\n", "", h.beta, h.n, h.value,
                f(h.beta, h.n), 100 * (f(h.beta, h.n) / h.value - 1));
}

struct Options {
  std::string points_path, out_path, report_path, source = "hsrod_fit_campaign";
  std::string cpp_path;
  int friction_terms = kFrictionTerms, velocity_terms = kVelocityTerms;
  // Across the axis k(beta) has 2 terms and k_held(beta) 4: with constant k
  // and k_held level 2's r at beta 0.75 was 1.4 / 2.8 % low (N = 5 / 10; r
  // fit chi2/dof 57) and r - 1 at beta 0.1-0.2 up to 7e-4 off (N = 2 with the
  // wrong sign); 2 and 4 terms put every resolved r within 0.09 % and r - 1
  // within 1e-4 at beta <= 0.45 (chi2/dof 1.6, confinement_campaign_fit.json);
  // with 3 terms of k_held r was within 0.6 %, r - 1 off by up to 7e-4.
  RodLayout perp_layout{2, 0, 4};
  int shielding_terms = 1;
};

void add_options(CLI::App& app, Options& o) {
  app.add_option("points", o.points_path, "campaign points CSV (campaign_analysis.py)")->required()->check(CLI::ExistingFile);
  app.add_option("output", o.out_path, "coefficient table to write")->required();
  app.add_option("--report", o.report_path, "fit report (JSON)");
  app.add_option("--source", o.source, "text for the table's source line");
  app.add_option("--friction-terms", o.friction_terms, "terms of c_inf(beta) (polynomial)")->check(CLI::Range(1, 5));
  app.add_option("--velocity-terms", o.velocity_terms, "terms of q(beta) in lambda_inf (polynomial)")->check(CLI::Range(1, 5));
  app.add_option("--growth-terms", o.perp_layout.growth_terms, "terms of k(beta) in the growth across, g = beta^2 k(beta)")
      ->check(CLI::Range(1, 4));
  app.add_option("--held-growth-terms", o.perp_layout.held_growth_terms,
                 "terms of k_held(beta) in the held load's growth across")->check(CLI::Range(1, 4));
  app.add_option("--shielding-terms", o.shielding_terms, "terms of e(beta), the 3-D shielding along the axis (0: none)")
      ->check(CLI::Range(0, 3));
  app.add_option("--cpp", o.cpp_path, "write the parameters as the built-in table's header "
                                      "(drag-models/hydro/default_coefficients_fit.h)");
}

// A lone-sphere column: the free fit and what the table uses (the published
// law where the resolved runs do not reject it, else the fit).
struct SphereChoice {
  CurveFit free, table;
  bool published = false;
};

// The lone sphere's published law (Faxen: friction series p0 = 1.004,
// p3 = 0.418; velocity p0 = 1/3, p2 = 0) is kept where the resolved runs
// do not reject it: if every resolved lone sphere lies within two of its
// standard uncertainties (mesh change and floor, campaign_analysis.py)
// of the published curve. Otherwise the table uses the fit: every
// coefficient (friction: p0, p3, p5 with points at five or more beta;
// p0, p3 at three or four) with points at three or more beta, else p0 alone.
SphereChoice sphere_fit(const std::vector<Point>& pts, const char* q, CurveForm form, std::vector<double> published) {
  const auto p = select(pts, q, true);
  SphereChoice c;
  if (p.size() < 3) published.resize(1);
  else if (p.size() < 5) published.resize(std::min<std::size_t>(published.size(), 2));  // p5 needs five beta
  c.free = fit_curve(form, p, published);
  CurveFit pub = c.free;
  pub.params = published;
  double worst = 0.0;  // largest |published - resolved| / sigma
  for (const auto& x : p) worst = std::max(worst, std::abs(pub(x.beta) - x.value) / x.sigma);
  c.published = worst <= 2.0;
  c.table = c.published ? pub : c.free;
  std::printf("%s: fitted", q);
  for (std::size_t k = 0; k < published.size(); ++k)
    std::printf(" %.5f +- %.5f (published %.5f)", c.free.params[k], c.free.std_errors[k], published[k]);
  std::printf("; published curve at most %.2f sigma from the runs: table uses %s\n", worst,
              c.published ? "the published values" : "the fit");
  return c;
}

// every fitted column: lone sphere (table and free fit), rod friction and
// force-free velocity along (par) and across (perp, through r) the axis
struct Fits {
  SphereChoice sphere_friction, sphere_driving;
  CurveFit pf, qf, pv, qv;
  const CurveFit& sf() const { return sphere_friction.table; }
  const CurveFit& sd() const { return sphere_driving.table; }
  // the six fits of the report, by quantity
  std::array<std::pair<const char*, const CurveFit*>, 6> named() const {
    return {{{"sphere_friction", &sf()}, {"sphere_driving", &sd()}, {"par_friction", &pf},
             {"perp_friction", &qf},     {"par_velocity", &pv},     {"velocity_ratio", &qv}}};
  }
};

Fits fit_columns(const std::vector<Point>& pts, const Options& o) {
  const RodLayout& perp_layout = o.perp_layout;
  Fits r;
  r.sphere_friction = sphere_fit(pts, "sphere_friction", CurveForm::SphereFriction,
                                 {kFaxenFriction, kFaxenCubic, kFaxenQuintic});
  r.sphere_driving = sphere_fit(pts, "sphere_driving", CurveForm::SphereDriving, {kFaxenDriving, 0.0});
  const CurveFit& sd = r.sd();
  RodLayout par_layout;
  par_layout.shielding_terms = o.shielding_terms;
  r.pf = fit_curve(CurveForm::RodColumn, select(pts, "par_friction", true),
                   std::vector<double>(o.friction_terms + o.shielding_terms, 0.0), {}, {}, {}, {}, par_layout);
  std::vector<double> q_start(o.friction_terms, 0.0);
  q_start.push_back(0.3);
  q_start.resize(o.friction_terms + perp_layout.growth_terms, 0.0);
  r.qf = fit_curve(CurveForm::RodColumnGrowth, select(pts, "perp_friction", true), q_start, {}, {}, {}, {},
                   perp_layout);
  const CurveFit &pf = r.pf, &qf = r.qf;
  // Force-free velocities: lambda_par of the rods fitted directly, lambda_perp
  // through the measured r = lambda_perp / lambda_par (rods only: the lone
  // sphere's lambda_s is the n = 1 limit of both).
  const auto lone_velocity = [sd](double b) { return sd(b); };
  r.pv = fit_curve(CurveForm::RodVelocity, select(pts, "par_velocity", true),
                   std::vector<double>(o.velocity_terms, 0.0), lone_velocity,
                   [pf](double b) { return pf.asymptote(b); }, [pf](double b) { return pf.growth_at(b); },
                   {}, {}, [pf](double b) { return pf.shielding_at(b); });
  const CurveFit& pv = r.pv;
  std::vector<double> r_start(o.velocity_terms, 0.0);
  r_start.push_back(qf.params[o.friction_terms]);  // k_held from the friction's k
  r_start.resize(o.velocity_terms + perp_layout.held_growth_terms, 0.0);
  r.qv = fit_curve(CurveForm::RodVelocityRatio, select(pts, "velocity_ratio", true), r_start, lone_velocity,
                   [qf](double b) { return qf.asymptote(b); }, [qf](double b) { return qf.growth_at(b); },
                   [pv](double b, int n) { return pv(b, n); }, perp_layout,
                   [qf](double b) { return qf.shielding_at(b); });
  return r;
}

// what the fits give for the quantities not fitted directly: printed, and
// the report's "derived" entries (JSON members)
std::string report_derived(const std::vector<Point>& pts, const Fits& fits) {
  const CurveFit &pf = fits.pf, &qf = fits.qf, &pv = fits.pv, &qv = fits.qv;
  std::string derived_json;
  for (const auto& [name, fn] :
       {std::pair<const char*, std::function<double(double, int)>>{"perp_velocity", [&](double b, int n) { return qv.velocity(b, n); }},
        {"par_held", [&](double b, int n) { return pf(b, n) * pv(b, n); }},
        {"perp_held", [&](double b, int n) { return qf(b, n) * qv.velocity(b, n); }}}) {
    for (const char* role : {"fit", "heldout"}) {
      double worst = 0.0;
      int count = 0;
      for (const auto& p : pts)
        if (p.quantity == name && (p.role == "fit") == (std::string(role) == "fit")) {
          worst = std::max(worst, std::abs(fn(p.p.beta, p.p.n) / p.p.value - 1.0));
          ++count;
        }
      if (!count) continue;
      std::printf("%-16s from the fits, %s points: largest error %.3f %% (%d points)\n", name, role, 100 * worst, count);
      char buf[160];
      std::snprintf(buf, sizeof buf, "%s\"%s %s largest_relative\": %.6g", derived_json.empty() ? "" : ", ", name, role,
                    worst);
      derived_json += buf;
    }
  }
  return derived_json;
}

// the table's source suffix: the beta range of the fitted rod columns
std::string fitted_range(const std::vector<Point>& pts) {
  double bmin = 1, bmax = 0;
  for (const auto& p : pts)
    if (p.role == "fit" && p.quantity == "par_friction") bmin = std::min(bmin, p.p.beta), bmax = std::max(bmax, p.p.beta);
  char range[160];
  std::snprintf(range, sizeof range, "; rod columns (n = 10) fitted over beta %.2f-%.2f, extrapolated outside", bmin,
                bmax);
  return range;
}

// the table: rows beta = 0, 0.05, .., 0.85 of a rod of n = 10
void write_table(const Fits& fits, const std::string& source, const std::string& path) {
  std::vector<hsrod::ConfinementTable::Row> rows;
  for (int k = 0; k <= 17; ++k) {
    const double beta = 0.05 * k;
    hsrod::ConfinementCoefficients c;
    c.sphere_friction = fits.sf()(beta);
    c.sphere_driving = fits.sd()(beta);
    c.parallel_friction = fits.pf(beta, 10);
    c.perpendicular_friction = fits.qf(beta, 10);
    c.parallel_driving = fits.pv(beta, 10);
    c.perpendicular_driving = fits.qv.velocity(beta, 10);
    rows.push_back({beta, c});
  }
  const hsrod::ConfinementTable table(rows, source);
  table.write(path);
  std::printf("wrote %s\n", path.c_str());
}

// parameters of the built-in table (drag-models/hydro/default_coefficients_fit.h)
void write_cpp_header(const Options& o, const Fits& fits, const std::string& range) {
  std::ofstream h(o.cpp_path);
  h << "// The fitted parameters of the built-in confinement table (default_coefficients.cpp), written by\n"
       "//   hsrod_fit_campaign " << o.points_path << " OUT_TABLE --cpp " << o.cpp_path << "\n"
       "// Do not edit: regenerate when the campaign or the forms change (test\n"
       "// calibration_CalibratedLevels.BuiltInTableIsTheShippedFit). Forms: hydro/confinement_forms.h;\n"
       "// standard errors after //.\n#pragma once\n\nnamespace hsrod::default_fit {\n\n";
  char buf[256];
  // one array per block of each fit's parameters (RodLayout), named for
  // what it is; a block without terms is written as one zero term
  const auto array = [&](const std::string& name, const CurveFit& f, int first, int count) {
    h << "constexpr double k_" << name << "[" << std::max(count, 1) << "] = {";
    for (int k = 0; k < count; ++k) {
      std::snprintf(buf, sizeof buf, "%s%.10g", k ? ", " : "", f.params[first + k]);
      h << buf;
    }
    h << (count ? "};  // +-" : "0.0};  // (no terms)");
    for (int k = 0; k < count; ++k) {
      std::snprintf(buf, sizeof buf, " %.2g", f.std_errors[first + k]);
      h << buf;
    }
    h << "\n";
  };
  const auto whole = [&](const char* name, const CurveFit& f) { array(name, f, 0, int(f.params.size())); };
  whole("sphere_friction", fits.sf());
  whole("sphere_driving", fits.sd());
  array("par_friction", fits.pf, 0, o.friction_terms);
  array("par_shielding", fits.pf, o.friction_terms, o.shielding_terms);
  array("perp_friction", fits.qf, 0, o.friction_terms);
  array("perp_growth", fits.qf, o.friction_terms, o.perp_layout.growth_terms);
  whole("par_velocity", fits.pv);
  array("perp_velocity", fits.qv, 0, o.velocity_terms);
  array("perp_held_growth", fits.qv, o.velocity_terms, o.perp_layout.held_growth_terms);
  h << "constexpr const char* k_source =\n    \"built-in: " << o.source << range << "\";\n\n}  // namespace hsrod::default_fit\n";
  std::printf("wrote %s\n", o.cpp_path.c_str());
}

// the fit report (JSON): sphere table choice, derived errors, layout, every fit
void write_report(const Options& o, const std::vector<Point>& pts, const Fits& fits, const std::string& derived_json) {
  const CurveFit &sf = fits.sf(), &sd = fits.sd(), &sf_free = fits.sphere_friction.free,
                 &sd_free = fits.sphere_driving.free;
  std::ofstream r(o.report_path);
  r.precision(10);
  r << "{\"schema\": \"hsrod-campaign-fit 1\", \"points\": \"" << o.points_path << "\",\n";
  const auto arr = [](const std::vector<double>& v) {
    std::ostringstream os;
    os.precision(10);
    os << "[";
    for (std::size_t k = 0; k < v.size(); ++k) os << (k ? ", " : "") << v[k];
    return os.str() + "]";
  };
  r << "  \"sphere_table\": {\"sphere_friction\": {\"fitted\": " << arr(sf_free.params) << ", \"std_errors\": "
    << arr(sf_free.std_errors) << ", \"published\": " << arr({kFaxenFriction, kFaxenCubic, kFaxenQuintic}) << ", \"table\": "
    << arr(sf.params) << "}, \"sphere_driving\": {\"fitted\": " << arr(sd_free.params) << ", \"std_errors\": "
    << arr(sd_free.std_errors) << ", \"published\": " << arr({kFaxenDriving, 0.0}) << ", \"table\": "
    << arr(sd.params) << "}, \"rule\": \"published values kept if every resolved lone sphere is within 2 sigma of the "
       "published curve\"},\n";
  r << "  \"derived\": {" << derived_json << "},\n";
  r << "  \"layout\": {\"friction_terms\": " << o.friction_terms << ", \"par_shielding_terms\": " << o.shielding_terms
    << ", \"perp_growth_terms\": " << o.perp_layout.growth_terms << ", \"velocity_terms\": " << o.velocity_terms
    << ", \"perp_held_growth_terms\": " << o.perp_layout.held_growth_terms
    << ", \"note\": \"params of par_friction: c_inf polynomial then e(beta); perp_friction: c_inf polynomial then "
       "k(beta) (g = beta^2 k); velocity_ratio: lambda_inf's q polynomial then k_held(beta)\"},\n";
  const auto named = fits.named();
  for (std::size_t i = 0; i < 6; ++i)
    r << json_fit(named[i].first, *named[i].second, select(pts, named[i].first, true),
                  select(pts, named[i].first, false))
      << (i < 5 ? ",\n" : "\n");
  r << "}\n";
  std::printf("wrote %s\n", o.report_path.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fit hsrod's confinement table (levels 1-2) to the resolved campaign"};
  Options o;
  add_options(app, o);
  CLI11_PARSE(app, argc, argv);
  try {
    const auto pts = read_points(o.points_path);
    const Fits fits = fit_columns(pts, o);
    for (const auto& [name, f] : fits.named()) print_fit(name, *f, select(pts, name, false));
    const std::string derived_json = report_derived(pts, fits);
    const std::string range = fitted_range(pts);
    write_table(fits, o.source + range, o.out_path);
    if (!o.cpp_path.empty()) write_cpp_header(o, fits, range);
    if (!o.report_path.empty()) write_report(o, pts, fits, derived_json);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hsrod_fit_campaign: %s\n", e.what());
    return 1;
  }
  return 0;
}

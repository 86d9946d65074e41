// hsrod_fit_near_field: the near-field coupling of levels 3 and 4
// (drag-models/hydro/near_field_coupling.h) fitted to the resolved per-sphere
// loads of rigid rods (calibration/core/near_field_fit.h). One command
// regenerates the shipped fit and its compiled-in copy:
//
//   build/hsrod_fit_near_field calibration/data/resolved_campaign_series.csv
//     calibration/data/resolved_campaign_profiles.csv calibration/data/near_field_coupling.txt
//     --write-cpp drag-models/hydro/near_field_coupling_fit.cpp
// (one line)
//
// With the built-in confinement table (the fit of levels 1-2, whose sphere
// columns levels 3-4 use). Fits, per level, the near-field law of
// hydro/near_field_coupling.h (friction and held load each with its own
// blend length and reflections, polynomials of degree --degree in beta;
// calibration/core/near_field_fit.h) to the per-sphere profiles and the
// free velocities and r of every fitted row. Prints, per level and resolved
// row, the errors of the totals, the per-sphere profile RMS, the free
// velocities and r without and with the near field; rows with role
// "heldout" are only predicted. The output file records the rows fitted,
// the residual, the parameters with their standard errors and the held-out
// prediction as comments.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "near_field_fit.h"

using namespace hsrod::calib;

namespace {

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0, double e = 0, double g = 0) {
  char buf[512];
  std::snprintf(buf, sizeof buf, f, a, b, c, d, e, g);
  return buf;
}

// Per-row lines (before -> after) and the worst held-out errors.
std::string report(const std::string& level, const std::vector<NearFieldCase>& cases,
                   const hsrod::NearFieldLaw& fit, double& worst_heldout_total, double& worst_heldout_rms) {
  std::ostringstream out;
  worst_heldout_total = worst_heldout_rms = 0.0;
  for (const NearFieldCase& c : cases) {
    const CaseErrors before = case_errors(c, near_field_response(c, hsrod::NearFieldAtBeta{}));
    const CaseErrors after = case_errors(c, near_field_response(c, fit));
    out << level << " beta " << fmt("%.2f", c.resolved.beta) << " n " << c.resolved.n << " (" << c.resolved.role
        << "): totals R_par/R_perp/D_par/D_perp "
        << fmt("%+.1f/%+.1f/%+.1f/%+.1f %%", 100 * after.total[0], 100 * after.total[1], 100 * after.total[2],
               100 * after.total[3])
        << fmt(" (before worst %.1f %%), profile RMS worst %.1f %% (before %.1f %%), free velocity %+.2f/%+.2f %%",
               100 * before.worst_total(), 100 * after.worst_profile(), 100 * before.worst_profile(),
               100 * after.lambda[0], 100 * after.lambda[1])
        << fmt(", r %+.2f %% (r - 1 %.4f, resolved %.4f)", 100 * after.ratio, after.r - 1.0, c.resolved.at("r") - 1.0)
        << "\n";
    if (std::getenv("HSROD_NEAR_FIELD_VERBOSE")) {  // per-sphere profiles, resolved | model
      const RowResponse m = near_field_response(c, fit);
      const char* names[4] = {"friction_par", "friction_perp", "driving_par", "driving_perp"};
      const std::vector<double>* model[4] = {&m.friction_par, &m.friction_perp, &m.driving_par, &m.driving_perp};
      for (int q = 0; q < 4; ++q) {
        out << "    " << names[q] << fmt(" RMS %.1f %%:", 100 * after.profile_rms[q]);
        for (std::size_t i = 0; i < model[q]->size(); ++i)
          out << fmt(" %.3f|%.3f", c.profiles.at(names[q])[i], (*model[q])[i]);
        out << "\n";
      }
    }
    if (c.resolved.role != "fit") {
      worst_heldout_total = std::max(worst_heldout_total, after.worst_total());
      worst_heldout_rms = std::max(worst_heldout_rms, after.worst_profile());
    }
  }
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fit the near-field coupling of levels 3-4 to the resolved per-sphere loads"};
  std::string series_path, profiles_path, out_path, cpp_path;
  app.add_option("series", series_path, "resolved_campaign_series.csv")->required()->check(CLI::ExistingFile);
  app.add_option("profiles", profiles_path, "resolved_campaign_profiles.csv")->required()->check(CLI::ExistingFile);
  app.add_option("output", out_path, "near-field coupling file to write")->required();
  app.add_option("--write-cpp", cpp_path, "also write the compiled-in copy (near_field_coupling_fit.cpp)");
  int degree = 2;  // the shipped fit (calibration/README.md: degree 1 leaves 1.5 % in the free velocities)
  app.add_option("--degree", degree, "degree of each parameter's polynomial in beta (0: constant)")->check(CLI::Range(0, 4));
  CLI11_PARSE(app, argc, argv);
  try {
    const auto series = read_resolved_series(series_path);
    const auto profiles = read_resolved_profiles(profiles_path);
    const hsrod::ConfinementTable table = hsrod::ConfinementTable::default_table();
    const std::string series_name = series_path.substr(series_path.rfind('/') + 1);
    hsrod::NearFieldCalibration result;
    result.source = "hsrod_fit_near_field on " + series_name +
                    " (resolved rodIbFoam rigid rows, per-sphere profiles and free velocities, finest mesh), degree " +
                    std::to_string(degree) + " in beta, table: " + table.source();
    std::ostringstream provenance, law_lines;
    const char* const loads[2] = {"friction", "driving"};
    const char* const parameters[4] = {"ln_blend_length", "reflection", "reflection_along", "ln_blend_length_along"};
    double beta_min = 1.0, beta_max = 0.0;
    for (const std::string level : {"nonlocal", "twoway"}) {
      const auto cases = near_field_cases(level, series, profiles, table);
      const NearFieldFit fit = fit_near_field(cases, {0.33, 0.15, 0.0}, degree);
      (level == "nonlocal" ? result.nonlocal : result.twoway) = fit.law;
      beta_min = fit.beta_min;
      beta_max = fit.beta_max;
      double ho_total = 0, ho_rms = 0;
      const std::string rows = report(level, cases, fit.law, ho_total, ho_rms);
      std::printf("%s", rows.c_str());
      provenance << "# " << level
                 << fmt(": %.0f fitted rows (beta %.2f-%.2f), %.0f residuals, %.0f parameters; RMS profile error %.4f of the "
                        "profile mean; ",
                        fit.rows, fit.beta_min, fit.beta_max, fit.points, fit.parameters.size(), fit.rms_profile_residual)
                 << fmt("fitted rows: worst free velocity %.2f %%, worst r %.2f %%; held out: worst total %.1f %%, worst "
                        "profile RMS %.1f %%\n",
                        100 * fit.worst_fitted_velocity, 100 * fit.worst_fitted_ratio, 100 * ho_total, 100 * ho_rms);
      int k = 0;
      for (int l = 0; l < 2; ++l)
        for (int q = 0; q < 4; ++q) {
          provenance << "#   " << level << " " << loads[l] << " " << parameters[q] << ":";
          law_lines << level << " " << loads[l] << " " << parameters[q];
          for (int j = 0; j <= degree; ++j, ++k) {
            provenance << fmt(" %.4f +- %.4f", fit.parameters[k], fit.std_error[k]);
            char buf[64];
            std::snprintf(buf, sizeof buf, " %.10g", fit.parameters[k]);
            law_lines << buf;
          }
          provenance << "\n";
          law_lines << "\n";
        }
      std::istringstream lines(rows);
      for (std::string l; std::getline(lines, l);) provenance << "#   " << l << "\n";
    }
    std::printf("%s", provenance.str().c_str());
    std::ofstream f(out_path);
    f << "hsrod-near-field-coupling 2\nsource " << result.source << "\n"
      << "# Near-field coupling of levels 3-4 (drag-models/hydro/near_field_coupling.h), written by\n"
      << "#   build/hsrod_fit_near_field " << series_name << " " << profiles_path.substr(profiles_path.rfind('/') + 1)
      << " near_field_coupling.txt --degree " << degree << " --write-cpp drag-models/hydro/near_field_coupling_fit.cpp\n"
      << "# Fitted: rows with role fit (n > 1): per-sphere residual (model - resolved) / (profile mean sqrt(n)),\n"
      << "# free velocities along/across and r (relative error x " << kProfileScale / kVelocityScale << " and x "
      << kProfileScale / kRatioScale << ");\n"
      << "# standard errors from s^2 (J^T J)^-1. Per row: errors with the fit (before: near field off).\n"
      << provenance.str() << fmt("beta_range %.4g %.4g\n", beta_min, beta_max)
      << "# model load parameter c0 c1 ...: polynomial in (beta - 0.3); blend length kappa = exp(...) over H,\n"
      << "# reflections over Faxen's 1.004/(3 pi mu H)\n"
      << law_lines.str();
    std::printf("wrote %s\n", out_path.c_str());
    if (!cpp_path.empty()) {
      std::ofstream c(cpp_path);
      c << "// The shipped near-field fit (hydro/near_field_coupling.h), written by\n"
           "//   build/hsrod_fit_near_field (calibration/tools/fit_near_field.cpp)\n"
           "// Do not edit: equals calibration/data/near_field_coupling.txt (test\n"
           "// calibration_NearFieldLevels.BuiltInNearFieldIsTheShippedFit).\n"
           "#include \"hydro/near_field_coupling.h\"\n\nnamespace hsrod {\n\n"
           "NearFieldCalibration NearFieldCalibration::built_in() {\n  NearFieldCalibration c;\n";
      for (const std::string level : {"nonlocal", "twoway"}) {
        const hsrod::NearFieldLaw& law = level == "nonlocal" ? result.nonlocal : result.twoway;
        c << "  c." << level << ".active = true;\n";
        char buf[128];
        std::snprintf(buf, sizeof buf, "  c.%s.beta_min = %.4g;\n  c.%s.beta_max = %.4g;\n", level.c_str(), law.beta_min,
                      level.c_str(), law.beta_max);
        c << buf;
        for (int l = 0; l < 2; ++l)
          for (int q = 0; q < 4; ++q) {
            c << "  c." << level << ".coefficients[" << l << "][" << q << "] = {";
            for (std::size_t j = 0; j < law.coefficients[l][q].size(); ++j) {
              std::snprintf(buf, sizeof buf, "%s%.10g", j ? ", " : "", law.coefficients[l][q][j]);
              c << buf;
            }
            c << "};  // " << loads[l] << " " << parameters[q] << "\n";
          }
      }
      c << "  c.source = \"" << result.source << "\";\n  return c;\n}\n\n}  // namespace hsrod\n";
      std::printf("wrote %s\n", cpp_path.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hsrod_fit_near_field: %s\n", e.what());
    return 1;
  }
  return 0;
}

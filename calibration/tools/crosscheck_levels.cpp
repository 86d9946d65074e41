// hsrod_crosscheck_levels: levels 1-4 against the resolved campaign.
//
//   hsrod_crosscheck_levels SERIES.csv PROFILES.csv OUT.csv [--table FILE] [--label TEXT]
//                           [--levels isotropic,local,nonlocal,twoway] [--write-table FILE]
//                           [--error-record CSV] [--error-record-cpp CPP] [--near-field FILE|off]
//
// SERIES.csv / PROFILES.csv: calibration/data/resolved_campaign_{series,profiles}.csv
// (campaign_analysis.py). For every resolved row of spheres and every level,
// the model's response (calibration/core/level_crosscheck.h) with the given
// coefficient table (default: the built-in ConfinementTable::default_table())
// is compared with the resolved one: totals R_par, R_perp, D_par, D_perp,
// force-free velocities lambda_par/perp, r, and the RMS of the per-sphere
// profile error over the profile's mean magnitude. --near-field: the
// near-field coupling of levels 3-4 (hydro/near_field_coupling.h; default
// the built-in fit, "off" for the depth-averaged coupling alone). OUT.csv: one row per
// (label, level, beta, n, spacing, quantity). Prints a summary per level.
// --error-record / --error-record-cpp: the error model of `auto`
// (hydro/auto_model_choice.h) from the fitted rods (role "fit", spacing 1):
// per level, beta and n the largest |error| of the totals, of the free
// velocities and of r, as CSV (calibration/data/level_error_record.csv) and
// as the built-in record (drag-models/hydro/auto_model_choice_record.cpp).
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "hydro/model_registry.h"
#include "level_crosscheck.h"
#include "resolved_campaign.h"

using namespace hsrod::calib;

namespace {

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string x;
  while (std::getline(ss, x, ',')) out.push_back(x);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Cross-check hsrod's reduced models against the resolved campaign"};
  std::string series_path, profiles_path, out_path, table_path, label = "built-in", levels = "isotropic,local,nonlocal,twoway";
  app.add_option("series", series_path)->required()->check(CLI::ExistingFile);
  app.add_option("profiles", profiles_path)->required()->check(CLI::ExistingFile);
  app.add_option("output", out_path)->required();
  app.add_option("--table", table_path, "coefficient file (default: the built-in table)");
  app.add_option("--label", label, "label of this table in the output");
  app.add_option("--levels", levels, "models to check");
  std::string write_table, record_csv, record_cpp, near_field_path;
  app.add_option("--near-field", near_field_path, "near-field coupling file of levels 3-4, or off (default: built-in)");
  app.add_option("--write-table", write_table, "also write the table in use to this file");
  app.add_option("--error-record", record_csv, "write the error record of auto (CSV)");
  app.add_option("--error-record-cpp", record_cpp, "write the error record of auto (C++ source)");
  CLI11_PARSE(app, argc, argv);
  try {
    const hsrod::ConfinementTable table =
        table_path.empty() ? hsrod::ConfinementTable::default_table() : hsrod::ConfinementTable::read(table_path);
    if (!write_table.empty()) table.write(write_table);
    const hsrod::NearFieldCalibration near_field =
        near_field_path.empty()   ? hsrod::NearFieldCalibration::built_in()
        : near_field_path == "off" ? hsrod::NearFieldCalibration::off()
                                   : hsrod::NearFieldCalibration::read(near_field_path);
    const auto series = read_csv_rows(series_path);
    // profiles: (beta, n, spacing, load_component) -> values by sphere
    const auto prof = read_resolved_profiles(profiles_path);
    std::ofstream out(out_path);
    out << "label,level,beta,n,spacing,role,quantity,resolved,model,rel_error\n";
    out.precision(8);
    struct RecordRow {
      int level;
      std::string beta;
      int n;
      double force, velocity, r;
    };
    std::vector<RecordRow> record;
    for (const auto& level : split(levels)) {
      double worst_tot = 0, worst_lambda = 0, worst_r = 0, worst_prof = 0;
      for (const auto& s : series) {
        const double beta = std::stod(s.at("beta")), spacing = std::stod(s.at("spacing"));
        const int n = std::stoi(s.at("n"));
        RowResponse m;
        try {
          m = row_response(level, beta, n, spacing, table, near_field);
        } catch (const std::exception& e) {
          // a level that refuses this configuration has no error to record
          // (auto interpolates between the betas where it runs)
          std::printf("%-10s %-9s beta %s n %d: not evaluated: %s\n", label.c_str(), level.c_str(),
                      s.at("beta").c_str(), n, e.what());
          continue;
        }
        const std::pair<const char*, double> q[] = {{"R_par", m.R_par()},         {"R_perp", m.R_perp()},
                                                    {"D_par", m.D_par()},         {"D_perp", m.D_perp()},
                                                    {"lambda_par", m.lambda_par()}, {"lambda_perp", m.lambda_perp()},
                                                    {"r", m.r()}};
        RecordRow rec{hsrod::find_model(level) ? hsrod::find_model(level)->level : 0, s.at("beta"), n, 0, 0, 0};
        for (const auto& [name, val] : q) {
          const double res = std::stod(s.at(name));
          const double err = val / res - 1.0;
          out << label << ',' << level << ',' << s.at("beta") << ',' << n << ',' << s.at("spacing") << ','
              << s.at("role") << ',' << name << ',' << res << ',' << val << ',' << err << '\n';
          const std::string nm = name;
          if (nm[0] == 'R' || nm[0] == 'D') worst_tot = std::max(worst_tot, std::abs(err));
          else if (nm == "r") worst_r = std::max(worst_r, std::abs(err));
          else worst_lambda = std::max(worst_lambda, std::abs(err));
          double& slot = nm[0] == 'R' || nm[0] == 'D' ? rec.force : nm == "r" ? rec.r : rec.velocity;
          slot = std::max(slot, std::abs(err));
        }
        if (s.at("role") == "fit" && spacing == 1.0 && rec.level > 0) record.push_back(rec);
        const std::pair<const char*, const std::vector<double>*> pr[] = {{"friction_par", &m.friction_par},
                                                                         {"friction_perp", &m.friction_perp},
                                                                         {"driving_par", &m.driving_par},
                                                                         {"driving_perp", &m.driving_perp}};
        for (const auto& [name, vals] : pr) {
          const auto it = prof.find({s.at("beta"), s.at("n"), s.at("spacing"), name});
          if (it == prof.end() || it->second.size() != vals->size()) continue;
          double se = 0, mean = 0;
          for (std::size_t i = 0; i < vals->size(); ++i) {
            se += std::pow((*vals)[i] - it->second[i], 2);
            mean += std::abs(it->second[i]);
          }
          const double rms = std::sqrt(se / vals->size()) / (mean / vals->size());
          out << label << ',' << level << ',' << s.at("beta") << ',' << n << ',' << s.at("spacing") << ','
              << s.at("role") << ",profile_rms_" << name << ",0,0," << rms << '\n';
          if (n > 1) worst_prof = std::max(worst_prof, rms);
          for (std::size_t i = 0; i < vals->size(); ++i)
            out << label << ',' << level << ',' << s.at("beta") << ',' << n << ',' << s.at("spacing") << ','
                << s.at("role") << ',' << name << '_' << (i + 1) << ',' << it->second[i] << ',' << (*vals)[i] << ','
                << (*vals)[i] / it->second[i] - 1.0 << '\n';
        }
      }
      std::printf("%-10s %-9s worst |error|: totals %6.1f %%, force-free velocity %5.2f %%, r %5.2f %%, "
                  "per-sphere profile RMS %5.1f %%\n",
                  label.c_str(), level.c_str(), 100 * worst_tot, 100 * worst_lambda, 100 * worst_r, 100 * worst_prof);
    }
    std::printf("wrote %s\n", out_path.c_str());
    const std::string provenance = "hsrod_crosscheck_levels --error-record: levels against the resolved campaign "
                                   "(" + series_path.substr(series_path.rfind('/') + 1) + ", rigid rods, role fit), "
                                   "table: " + table.source();
    if (!record_csv.empty()) {
      std::ofstream f(record_csv);
      f << "# " << provenance << "\n# largest |model / resolved - 1| of the totals (R, D along and across), of the "
           "force-free velocities and of r\nlevel,beta,n,force_error,velocity_error,r_error\n";
      f.precision(6);
      for (const auto& r : record)
        f << r.level << ',' << r.beta << ',' << r.n << ',' << r.force << ',' << r.velocity << ',' << r.r << '\n';
      std::printf("wrote %s\n", record_csv.c_str());
    }
    if (!record_cpp.empty()) {
      std::ofstream f(record_cpp);
      f << "// The cross-check record of `auto` (hydro/auto_model_choice.h), written by (one command)\n"
           "//   build/hsrod_crosscheck_levels calibration/data/resolved_campaign_series.csv\n"
           "//     calibration/data/resolved_campaign_profiles.csv build/crosscheck/record.csv\n"
           "//     --error-record calibration/data/level_error_record.csv\n"
           "//     --error-record-cpp drag-models/hydro/auto_model_choice_record.cpp\n"
           "// Do not edit: regenerate when a level or the table changes (test\n"
           "// calibration_AutoErrorModel.BuiltInRecordIsTheCurrentCrossCheck fails otherwise).\n"
           "#include \"hydro/auto_model_choice.h\"\n\nnamespace hsrod {\n\n"
           "const char* level_error_record_provenance() {\n  return \"" << provenance << "\";\n}\n\n"
           "const std::vector<LevelErrorRow>& level_error_record() {\n"
           "  // level, beta, n, force_error, velocity_error, r_error\n"
           "  static const std::vector<LevelErrorRow> rows = {\n";
      f.precision(6);
      for (const auto& r : record)
        f << "      {" << r.level << ", " << r.beta << ", " << r.n << ", " << r.force << ", " << r.velocity << ", " << r.r
          << "},\n";
      f << "  };\n  return rows;\n}\n\n}  // namespace hsrod\n";
      std::printf("wrote %s\n", record_cpp.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hsrod_crosscheck_levels: %s\n", e.what());
    return 1;
  }
  return 0;
}

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

struct Options {
  std::string series_path, profiles_path, out_path, table_path, label = "built-in", levels = "isotropic,local,nonlocal,twoway";
  std::string write_table, record_csv, record_cpp, near_field_path;
};

void add_options(CLI::App& app, Options& o) {
  app.add_option("series", o.series_path)->required()->check(CLI::ExistingFile);
  app.add_option("profiles", o.profiles_path)->required()->check(CLI::ExistingFile);
  app.add_option("output", o.out_path)->required();
  app.add_option("--table", o.table_path, "coefficient file (default: the built-in table)");
  app.add_option("--label", o.label, "label of this table in the output");
  app.add_option("--levels", o.levels, "models to check");
  app.add_option("--near-field", o.near_field_path, "near-field coupling file of levels 3-4, or off (default: built-in)");
  app.add_option("--write-table", o.write_table, "also write the table in use to this file");
  app.add_option("--error-record", o.record_csv, "write the error record of auto (CSV)");
  app.add_option("--error-record-cpp", o.record_cpp, "write the error record of auto (C++ source)");
}

// one row of auto's error record: the largest |error| per level, beta and n
struct RecordRow {
  int level;
  std::string beta;
  int n;
  double force, velocity, r;
};

// worst |error| of one level over the resolved rows
struct Worst {
  double tot = 0, lambda = 0, r = 0, prof = 0;
};

// the columns that name a resolved row in OUT.csv
std::ostream& row_columns(std::ostream& out, const std::string& label, const std::string& level, const CsvRow& s,
                          int n) {
  return out << label << ',' << level << ',' << s.at("beta") << ',' << n << ',' << s.at("spacing") << ','
             << s.at("role");
}

// totals and force-free velocities of one row: OUT.csv rows, worst errors, record row
void compare_totals(std::ostream& out, const std::string& label, const std::string& level, const CsvRow& s, int n,
                    const RowResponse& m, Worst& worst, RecordRow& rec) {
  const std::pair<const char*, double> q[] = {{"R_par", m.R_par()},         {"R_perp", m.R_perp()},
                                              {"D_par", m.D_par()},         {"D_perp", m.D_perp()},
                                              {"lambda_par", m.lambda_par()}, {"lambda_perp", m.lambda_perp()},
                                              {"r", m.r()}};
  for (const auto& [name, val] : q) {
    const double res = std::stod(s.at(name));
    const double err = val / res - 1.0;
    row_columns(out, label, level, s, n) << ',' << name << ',' << res << ',' << val << ',' << err << '\n';
    const std::string nm = name;
    if (nm[0] == 'R' || nm[0] == 'D') worst.tot = std::max(worst.tot, std::abs(err));
    else if (nm == "r") worst.r = std::max(worst.r, std::abs(err));
    else worst.lambda = std::max(worst.lambda, std::abs(err));
    double& slot = nm[0] == 'R' || nm[0] == 'D' ? rec.force : nm == "r" ? rec.r : rec.velocity;
    slot = std::max(slot, std::abs(err));
  }
}

// per-sphere load profiles of one row against the resolved ones
void compare_profiles(std::ostream& out, const std::string& label, const std::string& level, const CsvRow& s, int n,
                      const RowResponse& m, const std::map<ProfileKey, std::vector<double>>& prof, Worst& worst) {
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
    row_columns(out, label, level, s, n) << ",profile_rms_" << name << ",0,0," << rms << '\n';
    if (n > 1) worst.prof = std::max(worst.prof, rms);
    for (std::size_t i = 0; i < vals->size(); ++i)
      row_columns(out, label, level, s, n) << ',' << name << '_' << (i + 1) << ',' << it->second[i] << ','
                                           << (*vals)[i] << ',' << (*vals)[i] / it->second[i] - 1.0 << '\n';
  }
}

// one level against every resolved row: OUT.csv rows, the record's rows, summary line
void crosscheck_level(const std::string& level, const std::string& label, const std::vector<CsvRow>& series,
                      const std::map<ProfileKey, std::vector<double>>& prof, const hsrod::ConfinementTable& table,
                      const hsrod::NearFieldCalibration& near_field, std::ostream& out,
                      std::vector<RecordRow>& record) {
  Worst worst;
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
    RecordRow rec{hsrod::find_model(level) ? hsrod::find_model(level)->level : 0, s.at("beta"), n, 0, 0, 0};
    compare_totals(out, label, level, s, n, m, worst, rec);
    if (s.at("role") == "fit" && spacing == 1.0 && rec.level > 0) record.push_back(rec);
    compare_profiles(out, label, level, s, n, m, prof, worst);
  }
  std::printf("%-10s %-9s worst |error|: totals %6.1f %%, force-free velocity %5.2f %%, r %5.2f %%, "
              "per-sphere profile RMS %5.1f %%\n",
              label.c_str(), level.c_str(), 100 * worst.tot, 100 * worst.lambda, 100 * worst.r, 100 * worst.prof);
}

void write_record_csv(const std::string& path, const std::string& provenance, const std::vector<RecordRow>& record) {
  std::ofstream f(path);
  f << "# " << provenance << "\n# largest |model / resolved - 1| of the totals (R, D along and across), of the "
       "force-free velocities and of r\nlevel,beta,n,force_error,velocity_error,r_error\n";
  f.precision(6);
  for (const auto& r : record)
    f << r.level << ',' << r.beta << ',' << r.n << ',' << r.force << ',' << r.velocity << ',' << r.r << '\n';
  std::printf("wrote %s\n", path.c_str());
}

void write_record_cpp(const std::string& path, const std::string& provenance, const std::vector<RecordRow>& record) {
  std::ofstream f(path);
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
  std::printf("wrote %s\n", path.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Cross-check hsrod's reduced models against the resolved campaign"};
  Options o;
  add_options(app, o);
  CLI11_PARSE(app, argc, argv);
  try {
    const hsrod::ConfinementTable table =
        o.table_path.empty() ? hsrod::ConfinementTable::default_table() : hsrod::ConfinementTable::read(o.table_path);
    if (!o.write_table.empty()) table.write(o.write_table);
    const hsrod::NearFieldCalibration near_field =
        o.near_field_path.empty()   ? hsrod::NearFieldCalibration::built_in()
        : o.near_field_path == "off" ? hsrod::NearFieldCalibration::off()
                                     : hsrod::NearFieldCalibration::read(o.near_field_path);
    const auto series = read_csv_rows(o.series_path);
    // profiles: (beta, n, spacing, load_component) -> values by sphere
    const auto prof = read_resolved_profiles(o.profiles_path);
    std::ofstream out(o.out_path);
    out << "label,level,beta,n,spacing,role,quantity,resolved,model,rel_error\n";
    out.precision(8);
    std::vector<RecordRow> record;
    for (const auto& level : split(o.levels)) crosscheck_level(level, o.label, series, prof, table, near_field, out, record);
    std::printf("wrote %s\n", o.out_path.c_str());
    const std::string provenance = "hsrod_crosscheck_levels --error-record: levels against the resolved campaign "
                                   "(" + o.series_path.substr(o.series_path.rfind('/') + 1) + ", rigid rods, role fit), "
                                   "table: " + table.source();
    if (!o.record_csv.empty()) write_record_csv(o.record_csv, provenance, record);
    if (!o.record_cpp.empty()) write_record_cpp(o.record_cpp, provenance, record);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hsrod_crosscheck_levels: %s\n", e.what());
    return 1;
  }
  return 0;
}

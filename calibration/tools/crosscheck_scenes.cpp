// hsrod_crosscheck_scenes: levels 1-4 against the resolved cases beyond
// straight rows in a wide slit: bent (C-shaped) rods, rigid rows near a side
// wall and beside a pore cylinder (campaign "geometry").
//
//   hsrod_crosscheck_scenes CASES.csv OUT.csv [--levels isotropic,local,nonlocal,twoway]
//                           [--table FILE] [--near-field FILE|off] [--label TEXT]
//                           [--wall-record FILE] [--wall-record-cpp FILE] [--case-table FILE]
//                           [--no-wall-law] [--pair-squeeze K]
//
// CASES.csv: calibration/data/resolved_geometry_per_sphere.csv
// (calibration/tools/geometry_cases.py; the finest mesh of every case is
// used). For every case, load and level (calibration/core/scene_crosscheck.h)
// OUT.csv gets one row per quantity (level "nonlocal+images": level 3 with
// the walls' images and the law fitted on top of them, as `fix hele_shaw/drag
// ... wall_reflection images` ships it):
//   F_x, F_y          total force over 3 pi mu d U (x along the wall and the
//                     flow, y towards (-) / away from (+) the wall): resolved,
//                     model, error (model - resolved) / |resolved| and
//                     error_of_magnitude (model - resolved) / |F_total|;
//   T_z               the rod's z torque about the centroid of its sphere
//                     centres (sum of (x_i - c) x F_i + T_i) over
//                     3 pi mu d^2 U, when the table has the per-sphere torques
//                     (column tz): resolved, model, error over |resolved|;
//   profile_rms       RMS over the spheres of |F_i,model - F_i,resolved| over
//                     the mean |F_i,resolved|;
//   f{x,y}_<i>        per sphere, error over the mean |F_i,resolved|;
//   tz_<i>            per sphere, z torque about its centre over 3 pi mu d^2 U,
//                     error over the mean |T_i,resolved| (with the table's torques);
// with the case's geometry, beta, n, gap (d), row angle, bend and load.
// Prints per level the worst errors per geometry and gap. --wall-record: the
// same worst errors as CSV (level, geometry, beta, gap over d and over H,
// totals, profile RMS), the material for an error model of `auto` that uses
// the distance to walls and pores (calibration/data/level_error_near_walls.csv);
// --wall-record-cpp: the same rows (walls and pores) as `auto`'s built-in
// near-wall record (drag-models/hydro/auto_near_wall_record.cpp).
// --no-wall-law: every level without the near-wall law (hydro/wall_proximity.h),
// to see what the law itself does.
// --case-table: one row per level and case (geometry, role, gap, row angle,
// load): errors of the totals F_x, F_y (model / resolved - 1), of the total
// vector (|F_model - F_resolved| / |F_resolved|), the profile RMS, the
// resolved total's change from the next coarser mesh over |F| (its numerical
// uncertainty; nan without a coarser mesh), and the rod torque T_z (resolved,
// model / resolved - 1, its mesh change over |T_z|; nan without torques).
// Loads: friction, driving, rotation and orbit (scene_crosscheck.h).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

#include "hydro/model_registry.h"
#include "scene_crosscheck.h"

using namespace hsrod::calib;

namespace {

struct Options {
  std::string cases_path, out_path, table_path, near_field_path, label = "built-in",
                                                                 levels = "isotropic,local,nonlocal,twoway";
  std::string wall_record, wall_record_cpp, case_table;
  bool no_wall_law = false;
  double pair_squeeze = std::nan("");  // k_p of level 3's law (hydro/wall_proximity.h); NaN: as shipped
};

void add_options(CLI::App& app, Options& o) {
  app.add_option("cases", o.cases_path)->required()->check(CLI::ExistingFile);
  app.add_option("output", o.out_path)->required();
  app.add_option("--levels", o.levels, "models to check");
  app.add_option("--table", o.table_path, "coefficient file (default: the built-in table)");
  app.add_option("--near-field", o.near_field_path, "near-field coupling file of levels 3-4, or off (default: built-in)");
  app.add_option("--label", o.label, "label of this table in the output");
  app.add_option("--wall-record", o.wall_record, "write the worst errors per level, geometry and gap (CSV)");
  app.add_option("--wall-record-cpp", o.wall_record_cpp, "write the near-wall rows as auto's built-in record (C++)");
  app.add_option("--case-table", o.case_table, "write one row of total and profile errors per level and case (CSV)");
  app.add_flag("--no-wall-law", o.no_wall_law, "every level without the near-wall law");
  app.add_option("--pair-squeeze", o.pair_squeeze, "level 3's pair squeeze k_p in place of the shipped one (fitting)");
}

// worst |error| of one level over the cases of a (geometry, beta, gap/d):
// totals (per component where the component carries >= 20 % of |F|), profile RMS
struct Cell {
  double force = 0.0, rms = 0.0;
  int cases = 0;
};
using Cells = std::map<std::tuple<std::string, double, double>, Cell>;  // (geometry, beta, gap/d)
using Worst = std::map<std::string, std::pair<double, double>>;         // printed group -> (totals, RMS)

// one case and level: OUT.csv rows (totals, profile RMS, per sphere), worst errors
void compare_case(std::ostream& out, std::ostream* case_table, const std::string& level, const SceneCase& c,
                  const SceneSphereLoads& model, Worst& worst, Cells& cells, const std::string& label) {
  const std::vector<Eigen::Vector2d>& m = model.forces;
  Eigen::Vector2d tm = Eigen::Vector2d::Zero(), tr = Eigen::Vector2d::Zero(), dr = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < m.size(); ++i) {
    tm += m[i];
    tr += c.resolved[i];
    dr += c.mesh_change[i];
  }
  // the rod torques (NaN when the table has no per-sphere torques)
  const double torque_model = rod_torque(c.positions, c.d, m, model.torques);
  const double torque_resolved = rod_torque(c.positions, c.d, c.resolved, c.resolved_torque);
  std::vector<Eigen::Vector2d> coarse_forces;
  std::vector<double> coarse_torques;
  for (std::size_t i = 0; i < m.size(); ++i) {
    coarse_forces.push_back(c.resolved[i] - c.mesh_change[i]);
    coarse_torques.push_back(c.resolved_torque[i] - c.torque_mesh_change[i]);
  }
  const double torque_change = torque_resolved - rod_torque(c.positions, c.d, coarse_forces, coarse_torques);
  if (case_table)
    *case_table << level << ',' << c.name << ',' << c.geometry << ',' << c.role << ',' << c.beta << ','
                << c.gap_over_d << ',' << c.row_angle_deg << ',' << c.load << ',' << tr[0] << ',' << tr[1] << ','
                << tm[0] / tr[0] - 1.0 << ',' << tm[1] / tr[1] - 1.0 << ',' << (tm - tr).norm() / tr.norm() << ','
                << profile_rms(m, c.resolved) << ',' << dr.norm() / tr.norm() << ',' << torque_resolved << ','
                << torque_model / torque_resolved - 1.0 << ',' << torque_change / std::abs(torque_resolved) << '\n';
  char head[512];
  std::snprintf(head, sizeof head, "%s,%s,%s,%s,%g,%zu,%g,%g,%g,%s", label.c_str(), level.c_str(), c.name.c_str(),
                c.geometry.c_str(), c.beta, m.size(), c.gap_over_d, c.row_angle_deg, c.bend_deg, c.load.c_str());
  char group_name[96];
  if (c.geometry == "bent")
    std::snprintf(group_name, sizeof group_name, "bent b%.2f", c.beta);
  else
    std::snprintf(group_name, sizeof group_name, "%s b%.2f gap %g d", c.geometry.c_str(), c.beta, c.gap_over_d);
  const std::string group = group_name;
  auto& w = worst[group];
  for (int k = 0; k < 2; ++k) {
    const double err = (tm[k] - tr[k]) / std::abs(tr[k]), err_mag = (tm[k] - tr[k]) / tr.norm();
    out << head << ",F_" << "xy"[k] << ',' << tr[k] << ',' << tm[k] << ',' << err << ',' << err_mag << '\n';
    if (std::abs(tr[k]) >= 0.2 * tr.norm()) {
      w.first = std::max(w.first, std::abs(err));
      Cell& cell = cells[{c.geometry, c.beta, c.gap_over_d}];
      cell.force = std::max(cell.force, std::abs(err));
    }
  }
  if (std::isfinite(torque_resolved))
    out << head << ",T_z," << torque_resolved << ',' << torque_model << ','
        << (torque_model - torque_resolved) / std::abs(torque_resolved) << ','
        << (torque_model - torque_resolved) / std::abs(torque_resolved) << '\n';
  const double rms = profile_rms(m, c.resolved);
  Cell& cell = cells[{c.geometry, c.beta, c.gap_over_d}];
  cell.rms = std::max(cell.rms, rms);
  ++cell.cases;
  out << head << ",profile_rms,0,0," << rms << ',' << rms << '\n';
  w.second = std::max(w.second, rms);
  double mean = 0.0;
  for (const auto& f : c.resolved) mean += f.norm() / c.resolved.size();
  for (std::size_t i = 0; i < m.size(); ++i)
    for (int k = 0; k < 2; ++k)
      out << head << ",f" << "xy"[k] << '_' << (i + 1) << ',' << c.resolved[i][k] << ',' << m[i][k] << ','
          << (m[i][k] - c.resolved[i][k]) / mean << ',' << (m[i][k] - c.resolved[i][k]) / mean << '\n';
  if (!std::isfinite(torque_resolved)) return;
  double mean_torque = 0.0;
  for (double t : c.resolved_torque) mean_torque += std::abs(t) / c.resolved_torque.size();
  for (std::size_t i = 0; i < m.size(); ++i)
    out << head << ",tz_" << (i + 1) << ',' << c.resolved_torque[i] << ',' << model.torques[i] << ','
        << (model.torques[i] - c.resolved_torque[i]) / mean_torque << ','
        << (model.torques[i] - c.resolved_torque[i]) / mean_torque << '\n';
}

// one level's worst errors: --wall-record rows, near-wall C++ rows, summary lines
void report_level(const std::string& label, const std::string& level, const Cells& cells, const Worst& worst,
                  std::ofstream& record, std::ostream& cpp_rows) {
  for (const auto& [key, cell] : cells) {
    if (!record.is_open()) break;
    const auto& [geometry, beta, gap] = key;
    record << level << ',' << geometry << ',' << beta << ',';
    if (geometry == "bent")  // the wide slit: no wall within reach
      record << "inf,inf,";
    else
      record << gap << ',' << gap * beta << ',';
    record << cell.cases << ',' << cell.force << ',' << cell.rms << '\n';
  }
  for (const auto& [key, cell] : cells) {
    const auto& [geometry, beta, gap] = key;
    const hsrod::ModelEntry* entry = hsrod::find_model(level);
    if (geometry == "bent" || !entry) continue;
    cpp_rows << "      {" << entry->level << ", " << (geometry == "pore" ? "true" : "false") << ", " << beta << ", "
             << gap << ", " << cell.force << ", " << cell.rms << "},\n";
  }
  for (const auto& [group, w] : worst)
    std::printf("%-10s %-9s %-22s worst |error|: totals %6.1f %%, per-sphere profile RMS %6.1f %%\n", label.c_str(),
                level.c_str(), group.c_str(), 100 * w.first, 100 * w.second);
}

// one level against every case
void crosscheck_level(const std::string& label, const std::string& level, const std::vector<SceneCase>& cases,
                      const hsrod::ConfinementTable& table, const hsrod::NearFieldCalibration& near_field,
                      std::ostream& out, std::ofstream& record, std::ostream& cpp_rows, std::ostream* case_table,
                      bool wall_law, double pair_squeeze) {
  Worst worst;
  Cells cells;
  // Each level as users get it: level 3 with images carries the law fitted on
  // top of them (what `wall_reflection images` ships), the others the built-in fit.
  hsrod::WallProximityCalibration wall = hsrod::WallProximityCalibration::built_in();
  if (level == "nonlocal+images") wall.nonlocal = hsrod::wall_proximity_with_images();
  if (level == "nonlocal+reflections") wall.nonlocal = hsrod::wall_proximity_with_reflections();
  if (!std::isnan(pair_squeeze)) wall.nonlocal.pair_squeeze = pair_squeeze;
  if (!wall_law) wall = hsrod::WallProximityCalibration::off();
  for (const SceneCase& c : cases) {
    SceneSphereLoads m;
    try {
      m = scene_sphere_loads(level, c, table, near_field, wall);
    } catch (const std::exception& e) {
      std::printf("%-9s %-26s %-8s: not evaluated: %s\n", level.c_str(), c.name.c_str(), c.load.c_str(), e.what());
      continue;
    }
    compare_case(out, case_table, level, c, m, worst, cells, label);
  }
  report_level(label, level, cells, worst, record, cpp_rows);
}

void write_wall_record_cpp(const std::string& path, const std::string& cases_path, const hsrod::ConfinementTable& table,
                           const std::string& cpp_rows) {
  std::ofstream f(path);
  f << "// The near-wall record of `auto` (hydro/auto_model_choice.h), written by\n"
       "//   /usr/bin/python3 calibration/validation/crosscheck_report.py build --scenes-only\n"
       "// (hsrod_crosscheck_scenes ... --wall-record calibration/data/level_error_near_walls.csv\n"
       "//  --wall-record-cpp drag-models/hydro/auto_near_wall_record.cpp).\n"
       "// Do not edit: regenerate when a level changes (test\n"
       "// calibration_AutoErrorModel.BuiltInNearWallRecordIsTheRecordedFile fails otherwise).\n"
       "#include \"hydro/auto_model_choice.h\"\n\nnamespace hsrod {\n\n"
       "const char* near_wall_error_record_provenance() {\n  return \"hsrod_crosscheck_scenes --wall-record on "
    << (cases_path.find("calibration/data/") != std::string::npos
            ? cases_path.substr(cases_path.find("calibration/data/"))
            : cases_path)
    << " (levels with their built-in near-wall correction), table: " << table.source()
    << "\";\n}\n\n"
       "const std::vector<NearWallErrorRow>& near_wall_error_record() {\n"
       "  // level, pore, beta, gap_over_d, force_error, profile_rms\n"
       "  static const std::vector<NearWallErrorRow> rows = {\n"
    << cpp_rows << "  };\n  return rows;\n}\n\n}  // namespace hsrod\n";
  std::printf("wrote %s\n", path.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Cross-check hsrod's reduced models against the resolved wall, pore and bent-rod cases"};
  Options o;
  add_options(app, o);
  CLI11_PARSE(app, argc, argv);
  try {
    const hsrod::ConfinementTable table =
        o.table_path.empty() ? hsrod::ConfinementTable::default_table() : hsrod::ConfinementTable::read(o.table_path);
    const hsrod::NearFieldCalibration near_field =
        o.near_field_path.empty()    ? hsrod::NearFieldCalibration::built_in()
        : o.near_field_path == "off" ? hsrod::NearFieldCalibration::off()
                                     : hsrod::NearFieldCalibration::read(o.near_field_path);
    const std::vector<SceneCase> cases = read_scene_cases(o.cases_path);
    std::ofstream out(o.out_path);
    out << "label,level,case,geometry,beta,n,gap_over_d,row_angle_deg,bend_deg,load,quantity,resolved,model,error,"
           "error_of_magnitude\n";
    out.precision(8);
    std::ofstream record;
    if (!o.wall_record.empty()) {
      record.open(o.wall_record);
      record << "# hsrod_crosscheck_scenes --wall-record: largest |model / resolved - 1| of the totals (components "
                "carrying >= 20 % of |F|) and largest per-sphere profile RMS, over the cases (row angles, loads, "
                "rod lengths) of each level, geometry, beta and gap; table: "
             << table.source() << "\nlevel,geometry,beta,gap_over_d,gap_over_H,cases,force_error,profile_rms\n";
      record.precision(4);
    }
    std::ofstream case_table;
    if (!o.case_table.empty()) {
      case_table.open(o.case_table);
      case_table << "# hsrod_crosscheck_scenes --case-table " << o.cases_path << "; table: " << table.source()
                 << "; forces over 3 pi mu d U\nlevel,case,geometry,role,beta,gap_over_d,row_angle_deg,load,"
                    "Fx_resolved,Fy_resolved,Fx_error,Fy_error,total_error,profile_rms,resolved_mesh_change,Tz_resolved,Tz_error,"
                    "Tz_mesh_change\n";
      case_table.precision(4);
    }
    std::ostringstream cpp_rows;
    cpp_rows.precision(6);
    std::stringstream levels_in(o.levels);
    std::string level;
    while (std::getline(levels_in, level, ','))
      crosscheck_level(o.label, level, cases, table, near_field, out, record, cpp_rows,
                       case_table.is_open() ? &case_table : nullptr, !o.no_wall_law, o.pair_squeeze);
    if (!o.wall_record_cpp.empty()) write_wall_record_cpp(o.wall_record_cpp, o.cases_path, table, cpp_rows.str());
    std::printf("wrote %s\n", o.out_path.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hsrod_crosscheck_scenes: %s\n", e.what());
    return 1;
  }
  return 0;
}

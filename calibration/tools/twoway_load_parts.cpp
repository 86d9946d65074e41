// hsrod_twoway_load_parts: the per-sphere loads of one resolved slit case
// (a bent or straight rod in the wide slit, calibration/data/
// resolved_fig3_bent_per_sphere.csv) from levels 3 and 4 taken apart, to see
// which part of a level decides the shape of its load along the rod.
//
//   hsrod_twoway_load_parts CASES.csv OUT.csv --case NAME [--variants LIST]
//   hsrod_twoway_load_parts - OUT.csv --row BETA:N [--variants LIST]
//
// --row: instead of a case of CASES.csv, a straight row of N touching
// spheres along x at BETA in the wide slit (d 3 um, mu 1 mPa s, U 1 mm/s),
// dragged and held at 45 degrees like the slit cases (case name row), or at
// --angle DEG (0: the stream along the row, 90: across it); with a case of
// CASES.csv, --angle replaces its drag angle (the stream then along or
// across the chord directly, without the mirror split of the 45-degree load).
//
// Variants (level 4 with TwoWayWindowOptions changed one at a time, each with
// and without its near field; level 3 with and without its near field; the
// near field with the driving's coupling replaced by the friction's):
//   l3, l3_nf_off, l3_nf_friction_only
//   l4, l4_nf_off, l4_nf_friction_only, l4_nf_driving_only
//   l4_cpd<C>[_rc<R>][_g<G>][_nf_off]  cells_per_diameter C, reflection_cells_per_diameter R
//                                       (R = C: one scale), grading G
//   l3_p<f|d><k><delta>, l4_p<f|d><k><delta>  one near-field parameter changed (make_variant), for
//                                       the sensitivity of the loads to it
// OUT.csv: variant,case,load,quantity,model with quantities fx_<i>, fy_<i>,
// tz_<i> (forces over 3 pi mu d U, torques over 3 pi mu d^2 U, as
// hsrod_crosscheck_scenes writes them) and film_<i> (the film friction
// zeta_f of the variant, over 3 pi mu d; the uncoupled part of the diagonal).
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "flow/uniform_flow.h"
#include "hydro/nonlocal_model.h"
#include "hydro/twoway_near_field.h"
#include "scene_crosscheck.h"

using namespace hsrod;
using namespace hsrod::calib;

namespace {

struct Variant {
  std::string name;
  std::unique_ptr<HydrodynamicModel> model;
  double film = 0.0;  // zeta_f [N s/m]
};

// Level 4 options from a name l4_cpd<C>[_rc<R>][_g<G>][_m<M>] (M: margin in d).
TwoWayWindowOptions options_from(const std::string& name, double d) {
  TwoWayWindowOptions o;
  std::stringstream ss(name);
  std::string part;
  while (std::getline(ss, part, '_')) {
    if (part.rfind("cpd", 0) == 0) o.cells_per_diameter = std::stod(part.substr(3));
    else if (part.rfind("rc", 0) == 0) o.reflection_cells_per_diameter = std::stod(part.substr(2));
    else if (part.rfind("g", 0) == 0 && part.size() > 1 && std::isdigit(static_cast<unsigned char>(part[1])))
      o.grading = std::stod(part.substr(1));
    else if (part.rfind("m", 0) == 0 && part.size() > 1 && std::isdigit(static_cast<unsigned char>(part[1])))
      o.margin = std::stod(part.substr(1)) * d;
  }
  return o;
}

Variant make_variant(const std::string& name, const HydrodynamicParameters& p, const ConfinementTable& table) {
  const double beta = p.beta();
  const NearFieldAtBeta l3 = NearFieldCalibration::built_in().nonlocal.at(beta);
  const NearFieldAtBeta l4 = NearFieldCalibration::built_in().twoway.at(beta);
  const bool off = name.find("_nf_off") != std::string::npos;
  const bool friction_only = name.find("_nf_friction_only") != std::string::npos;
  const bool driving_only = name.find("_nf_driving_only") != std::string::npos;
  // _p<f|d><k><delta>: parameter k (0 blend_length x (1 + delta), 1 reflection + delta, 2 reflection_along
  // + delta, 3 blend_length_along x (1 + delta)) of the friction (f) or driving (d) coupling changed
  const auto at = name.find("_p");
  auto perturbed = [&](NearFieldAtBeta c) {
    if (at == std::string::npos) return c;
    NearFieldCoupling& k = name[at + 2] == 'f' ? c.friction : c.driving;
    if (k.blend_length_along == 0.0) k.blend_length_along = k.blend_length;
    const double delta = std::stod(name.substr(at + 4));
    switch (name[at + 3]) {
      case '0': k.blend_length *= 1.0 + delta; break;
      case '1': k.reflection += delta; break;
      case '2': k.reflection_along += delta; break;
      default: k.blend_length_along *= 1.0 + delta; break;
    }
    return c;
  };
  auto coupling = [&](const NearFieldAtBeta& c) {
    if (off) return NearFieldAtBeta{};
    if (at != std::string::npos) return perturbed(c);
    if (friction_only) return NearFieldAtBeta(c.friction, c.friction);
    if (driving_only) return NearFieldAtBeta(c.driving, c.driving);
    return c;
  };
  Variant v;
  v.name = name;
  if (name.rfind("l3", 0) == 0) {
    v.model = std::make_unique<NonlocalRodModel>(p, table, coupling(l3));
    // zeta_f = zeta - zeta_o from a lone sphere in a uniform stream: R = zeta, driving = c zeta_o u
    RodGeometry lone;
    lone.sphere_diameter = p.sphere_diameter;
    lone.positions.push_back(Eigen::Vector3d::Zero());
    const double big = 1000.0 * p.gap_height;
    const UniformFlow flow(ChannelGeometry(big, big, p.gap_height, -0.5 * big, -0.5 * big), Eigen::Vector2d(1.0, 0.0));
    RodDrag drag;
    v.model->evaluate(lone, flow, drag);
    v.film = drag.coupled_resistance(0, 0) - drag.driving_force[0].x() / 1.5;
  } else if (name.rfind("l4", 0) == 0) {
    auto m = std::make_unique<NearFieldTwoWayModel>(p, table, options_from(name, p.sphere_diameter), coupling(l4));
    v.film = m->film_friction();
    v.model = std::move(m);
  } else {
    throw std::invalid_argument("unknown variant " + name);
  }
  return v;
}

// A straight row of n touching spheres along x in the wide slit, dragged (friction) or held (driving) at 45 deg.
std::vector<SceneCase> row_cases(double beta, int n, double angle_deg) {
  std::vector<SceneCase> out;
  for (const char* load : {"friction", "driving"}) {
    SceneCase c;
    c.name = "row";
    c.geometry = "bent";
    c.load = load;
    c.beta = beta;
    c.drag_angle_deg = angle_deg;
    c.d = 3e-6;
    c.mu = 1e-3;
    c.U = 1e-3;
    for (int i = 0; i < n; ++i) c.positions.emplace_back((i - 0.5 * (n - 1)) * c.d, 0.0, 0.0);
    out.push_back(c);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"levels 3-4 taken apart on one resolved slit case"};
  std::string cases_path, out_path, case_name, variants = "l3,l3_nf_off,l3_nf_friction_only,l4,l4_nf_off,"
                                                            "l4_nf_friction_only,l4_nf_driving_only";
  std::string row;
  double angle_deg = 45.0;
  app.add_option("cases", cases_path)->required();
  app.add_option("output", out_path)->required();
  app.add_option("--case", case_name);
  app.add_option("--row", row, "BETA:N, a straight row in place of a case");
  app.add_option("--angle", angle_deg, "--row: direction of the drag and of the stream [deg] (default 45)");
  app.add_option("--variants", variants);
  CLI11_PARSE(app, argc, argv);
  std::vector<SceneCase> cases;
  if (!row.empty()) {
    const auto colon = row.find(':');
    cases = row_cases(std::stod(row.substr(0, colon)), std::stoi(row.substr(colon + 1)), angle_deg);
    case_name = "row";
  } else {
    cases = read_scene_cases(cases_path);
    if (app.count("--angle"))
      for (SceneCase& c : cases) c.drag_angle_deg = angle_deg;
  }
  const ConfinementTable table = ConfinementTable::default_table();
  std::ofstream out(out_path);
  out << "variant,case,load,quantity,model\n";
  std::stringstream list(variants);
  std::string name;
  while (std::getline(list, name, ',')) {
    for (const SceneCase& c : cases) {
      if (c.name != case_name) continue;
      const HydrodynamicParameters p{c.mu, c.gap_height(), c.d};
      Variant v = make_variant(name, p, table);
      const SceneLoad load = scene_load(c);
      RodDrag drag;
      v.model->evaluate(load.rod, *load.flow, drag);
      const Eigen::VectorXd f = drag.forces(load.velocities);
      for (int i = 0; i < load.rod.size(); ++i) {
        const std::string head = name + "," + c.name + "," + c.load + ",";
        out << head << "fx_" << i + 1 << ',' << f(3 * i) / load.force_scale << '\n';
        out << head << "fy_" << i + 1 << ',' << f(3 * i + 1) / load.force_scale << '\n';
        out << head << "tz_" << i + 1 << ','
            << drag.torque(i, Eigen::Vector3d(0.0, 0.0, load.spins(i))).z() / (load.force_scale * c.d) << '\n';
        out << head << "film_" << i + 1 << ',' << v.film / (3.0 * M_PI * c.mu * c.d) << '\n';
      }
      if (name == "l4" || name == "l3") {
        const NearFieldAtBeta k = name == "l3" ? NearFieldCalibration::built_in().nonlocal.at(c.beta)
                                               : NearFieldCalibration::built_in().twoway.at(c.beta);
        std::printf("%s near field at beta %g: friction kappa %g alpha %g alpha_e %g kappa_e %g; driving kappa %g "
                    "alpha %g alpha_e %g kappa_e %g\n", name.c_str(), c.beta, k.friction.blend_length,
                    k.friction.reflection, k.friction.reflection_along, k.friction.along(), k.driving.blend_length,
                    k.driving.reflection, k.driving.reflection_along, k.driving.along());
      }
    }
    std::printf("%s done\n", name.c_str());
    std::fflush(stdout);
  }
  return 0;
}

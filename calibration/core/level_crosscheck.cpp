#include "common/math_constants.h"
#include "level_crosscheck.h"

#include <numeric>

#include "flow/uniform_flow.h"
#include "hydro/hydrodynamic_model.h"
#include "hydro/nonlocal_model.h"
#include "hydro/twoway_near_field.h"

#include <memory>

namespace hsrod::calib {

namespace {

using hsrod::kPi;

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

}  // namespace

double RowResponse::R_par() const { return sum(friction_par); }
double RowResponse::R_perp() const { return sum(friction_perp); }
double RowResponse::D_par() const { return sum(driving_par); }
double RowResponse::D_perp() const { return sum(driving_perp); }

HydrodynamicParameters row_parameters(double beta) {
  const double d = 3e-6, mu = 1e-3;  // any: the result is dimensionless
  return {mu, d / beta, d};
}

RowLoads row_loads(const HydrodynamicModel& model, const HydrodynamicParameters& p, int n, double spacing) {
  RowLoads out;
  out.parameters = p;
  out.speed = 1e-3;
  const double d = p.sphere_diameter;
  const UniformFlow still = UniformFlow::wide_slit(p.gap_height, Eigen::Vector2d::Zero());
  const UniformFlow stream = UniformFlow::wide_slit(p.gap_height, {out.speed, 0.0});
  for (int across = 0; across < 2; ++across) {
    RodGeometry& rod = out.rod[across];
    rod.sphere_diameter = d;
    for (int i = 0; i < n; ++i) {
      const double s = (i - 0.5 * (n - 1)) * spacing * d;
      rod.positions.push_back(across ? Eigen::Vector3d(0.0, s, 0.0) : Eigen::Vector3d(s, 0.0, 0.0));
    }
    model.evaluate(rod, still, out.still[across]);
    model.evaluate(rod, stream, out.stream[across]);
  }
  return out;
}

RowResponse row_response(const RowLoads& loads) {
  const double U = loads.speed;
  const double scale = 3.0 * kPi * loads.parameters.viscosity * loads.parameters.sphere_diameter * U;
  RowResponse out;
  for (int across = 0; across < 2; ++across) {
    const int n = loads.rod[across].size();
    Eigen::VectorXd v = Eigen::VectorXd::Zero(3 * n);
    for (int i = 0; i < n; ++i) v(3 * i) = -U;  // translating at -U e_x
    const Eigen::VectorXd f_fric = loads.still[across].forces(v);
    const Eigen::VectorXd f_held = loads.stream[across].forces(Eigen::VectorXd::Zero(3 * n));
    auto& fr = across ? out.friction_perp : out.friction_par;
    auto& dr = across ? out.driving_perp : out.driving_par;
    for (int i = 0; i < n; ++i) {
      fr.push_back(f_fric(3 * i) / scale);
      dr.push_back(f_held(3 * i) / scale);
    }
  }
  return out;
}

std::unique_ptr<HydrodynamicModel> make_level_model(const std::string& model_name, const HydrodynamicParameters& p,
                                                    const ConfinementTable& table,
                                                    const NearFieldCalibration& near_field) {
  const double beta = p.beta();  // the near field's parameters are functions of beta
  if (model_name == "nonlocal") return std::make_unique<NonlocalRodModel>(p, table, near_field.nonlocal.at(beta));
  if (model_name == "nonlocal+images" || model_name == "nonlocal+self_images" ||
      model_name == "nonlocal+reflections") {
    // level 3 with the walls' images (hydro/wall_images.h): all, or each sphere's own only
    auto model = std::make_unique<NonlocalRodModel>(p, table, near_field.nonlocal.at(beta));
    model->set_wall_reflection(wall_reflection_from_name(model_name.substr(model_name.find('+') + 1)));
    return model;
  }
  if (model_name == "twoway")
    return std::make_unique<NearFieldTwoWayModel>(p, table, TwoWayWindowOptions{}, near_field.twoway.at(beta));
  return make_hydrodynamic_model(model_name, p, table);
}

RowResponse row_response(const std::string& model_name, double beta, int n, double spacing,
                         const ConfinementTable& table, const NearFieldCalibration& near_field) {
  const HydrodynamicParameters p = row_parameters(beta);
  const std::unique_ptr<HydrodynamicModel> model = make_level_model(model_name, p, table, near_field);
  return row_response(row_loads(*model, p, n, spacing));
}

}  // namespace hsrod::calib

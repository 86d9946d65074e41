// hsrod_throat_loads: levels 1-4 on the rigid throat configurations of the
// dynamic pore passage (calibration/validation/pore_passage, "Throat
// configurations"): the 4-sphere rod (d = 3 um, beta 0.3) at a given centre and
// lab direction in the scene's channel (84 x 36 x 10 um, pore cylinders
// R = 9 um on both side walls at x = 42 um), per sphere, for the same four
// loads as the resolved campaign geometry "throat" (hsrod_campaign.py):
//   driving     held in the channel flow of mean velocity U;
//   friction_x  translating at +U along x through fluid at rest (the channel,
//               its walls and cylinders kept: level 4 reflects off them);
//   friction_y  the same along +y;
//   rotation    turning rigidly at Omega = U / d about +z about the centroid
//               of the sphere centres, every sphere spinning at Omega.
//
//   hsrod_throat_loads OUT.csv --config X,Y,ANGLE [--config ...] [--levels isotropic,local,nonlocal,twoway]
//
// X, Y in um, ANGLE the lab direction of the rod axis from x in degrees
// (sphere 1 at centre - 1.5 d (cos, sin), as hsrod_case.py's channelBody).
// OUT.csv: one row per configuration, level, load and sphere: x, y [m],
// fx, fy over 3 pi mu d U, tz over 3 pi mu d^2 U; the rigid reduction is left
// to the caller (pore_passage/throat.py, the same code for the resolved loads).
// Levels as the reduced passage runs use them (make_hydrodynamic_model with
// the built-in table, near field and near-wall correction). Also prints each
// level's free rigid velocity (hydro/rigid_rod_load.h) as a cross-check.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "hydro/hydrodynamic_model.h"
#include "hydro/rigid_rod_load.h"
#include "scene_crosscheck.h"

int main(int argc, char** argv) {
  CLI::App app{"Levels 1-4 per sphere on rigid throat configurations of the pore passage"};
  std::string out_path, levels = "isotropic,local,nonlocal,twoway";
  std::vector<std::string> configs;
  app.add_option("output", out_path)->required();
  app.add_option("--config", configs, "X,Y,ANGLE: centre [um], lab direction of the axis [deg]")->required();
  app.add_option("--levels", levels, "models");
  CLI11_PARSE(app, argc, argv);
  try {
    const double d = 3e-6, H = 10e-6, U = 1e-3, mu = 1e-3, kPi = 3.14159265358979323846;
    const double fscale = 3.0 * kPi * mu * d * U;
    std::ofstream out(out_path);
    out.precision(9);
    out << "x_um,y_um,row_angle_deg,level,load,sphere,x,y,fx,fy,tz\n";
    std::printf("# free rigid velocity of each level (rigid_rod_load): Vx/U Vy/U Omega d/U\n");
    for (const std::string& cfg : configs) {
      double cx, cy, ang;
      if (std::sscanf(cfg.c_str(), "%lf,%lf,%lf", &cx, &cy, &ang) != 3)
        throw std::invalid_argument("--config wants X,Y,ANGLE (got '" + cfg + "')");
      const double a = ang * kPi / 180.0;
      hsrod::calib::SceneCase c;
      c.name = "throat";
      c.geometry = "pore";  // the channel with both pore cylinders
      c.beta = d / H;
      c.d = d;
      c.mu = mu;
      c.U = U;
      c.channel_length = 84e-6;
      c.channel_width = 36e-6;
      c.pore_radius = 9e-6;
      c.pore_x = 42e-6;
      for (int i = 0; i < 4; ++i)
        c.positions.emplace_back(cx * 1e-6 + (i - 1.5) * d * std::cos(a), cy * 1e-6 + (i - 1.5) * d * std::sin(a),
                                 0.5 * H);
      c.load = "driving";
      const hsrod::calib::SceneLoad held = hsrod::calib::scene_load(c);
      c.load = "friction";
      const hsrod::calib::SceneLoad rest = hsrod::calib::scene_load(c);  // zero flow, the same channel
      const hsrod::HydrodynamicParameters p{mu, H, d};
      const auto table = hsrod::ConfinementTable::default_table();
      const Eigen::Vector2d centre = (c.positions[0] + c.positions[3]).head<2>() * 0.5;
      std::stringstream ls(levels);
      std::string level;
      while (std::getline(ls, level, ',')) {
        const auto model = hsrod::make_hydrodynamic_model(level, p, table);
        hsrod::RodDrag in_flow, at_rest;
        model->evaluate(held.rod, *held.flow, in_flow);
        model->evaluate(rest.rod, *rest.flow, at_rest);
        const double om = U / d;
        const struct {
          const char* name;
          Eigen::Vector3d q;
        } motions[] = {{"driving", {0, 0, 0}}, {"friction_x", {U, 0, 0}}, {"friction_y", {0, U, 0}},
                       {"rotation", {0, 0, om}}};
        for (const auto& m : motions) {
          const bool drive = std::string(m.name) == "driving";
          const hsrod::RodDrag& drag = drive ? in_flow : at_rest;
          const Eigen::VectorXd v = hsrod::rigid_sphere_velocities(held.rod, centre, m.q);
          const Eigen::VectorXd f = drag.forces(v);
          for (int i = 0; i < 4; ++i) {
            const double tz = drag.driving_torque[i].z() - drag.rotational_resistance[i] * m.q.z();
            out << cx << ',' << cy << ',' << ang << ',' << level << ',' << m.name << ',' << i + 1 << ','
                << c.positions[i].x() << ',' << c.positions[i].y() << ',' << f(3 * i) / fscale << ','
                << f(3 * i + 1) / fscale << ',' << tz / (fscale * d) << '\n';
          }
        }
        const hsrod::RigidRodLoad r = hsrod::rigid_rod_load(held.rod, in_flow);
        std::printf("%7.2f %7.2f %8.2f %-10s %+9.5f %+9.5f %+9.5f\n", cx, cy, ang, level.c_str(),
                    r.free_velocity.x() / U, r.free_velocity.y() / U, r.free_velocity.z() * d / U);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hsrod_throat_loads: %s\n", e.what());
    return 1;
  }
  return 0;
}

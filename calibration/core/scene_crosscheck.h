// hsrod calibration: levels 1-4 against the resolved cases beyond straight
// rows in a wide slit (campaign "geometry", calibration/tools/geometry_cases.py):
// bent (C-shaped) rods in the wide slit, rigid rows near a side wall and
// beside a pore cylinder of a channel. Each case is one rigid configuration
// and one load, compared sphere by sphere as force vectors in the plane:
//   friction: every sphere translates at -U e (e = (cos a, sin a, 0),
//             a = drag angle) through fluid at rest (the wide slit, or the
//             channel with its walls and pore);
//   driving:  the spheres held in the flow: the wide slit's uniform stream
//             U e, or the channel flow of mean velocity U along x;
//   rotation: (channel) the row turns rigidly at Omega = U / d about +z about
//             the centroid c of its sphere centres through fluid at rest:
//             sphere i translates at Omega e_z x (x_i - c) and spins at Omega;
//   orbit:    the same translations, the spheres not spinning.
// Forces over 3 pi mu d U, torques over 3 pi mu d^2 U.
#pragma once

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

#include "hydro/confinement_coefficients.h"
#include "flow/background_flow.h"
#include "hydro/hydrodynamic_model.h"
#include "hydro/near_field_coupling.h"
#include "hydro/wall_proximity.h"

#include <memory>

namespace hsrod::calib {

struct SceneCase {
  std::string name;             // configuration (geometry_cases.py "case")
  std::string geometry;         // bent | wall | pore
  std::string load;             // friction | driving | rotation | orbit
  std::string role = "fit";     // the plan's role (fit, or *_heldout: left out of every fit)
  double beta = 0.0;            // d / H [-]
  double gap_over_d = 0.0;      // smallest surface gap to the wall / pore cylinder [d]
  double row_angle_deg = 0.0;   // in-plane angle of the row to the wall (x axis) [deg]
  double bend_deg = 0.0;        // total bend of a bent rod [deg]
  double drag_angle_deg = 0.0;  // a: friction direction e (driving in the slit: the stream's direction) [deg]
  double d = 0.0, mu = 0.0, U = 0.0;                         // [m], [Pa s], [m/s]
  double channel_length = 0.0, channel_width = 0.0;          // wall / pore channel L, W [m]
  double pore_radius = 0.0, pore_x = 0.0;                    // pore cylinders (pore_x, 0) and (pore_x, W) [m]
  std::vector<Eigen::Vector3d> positions;                    // sphere centres [m]
  std::vector<Eigen::Vector2d> resolved;                     // per-sphere force / (3 pi mu d U)
  std::vector<Eigen::Vector2d> mesh_change;                  // change from the next coarser mesh (NaN: none)
  std::vector<double> resolved_torque;                       // per-sphere z torque about its centre / (3 pi mu d^2 U) (NaN: not in the table)
  std::vector<double> torque_mesh_change;                    // its change from the next coarser mesh (NaN: none)
  double gap_height() const { return d / beta; }             // H [m]
};

// The finest-mesh cases of a geometry_cases.py table, one per (case, load),
// spheres in id order. Throws std::runtime_error naming the file on bad input.
std::vector<SceneCase> read_scene_cases(const std::string& path);

// The model's per-sphere in-plane force / (3 pi mu d U) for the case, with
// the near-wall correction `wall` (hydro/wall_proximity.h; default: the
// built-in fit).
std::vector<Eigen::Vector2d> scene_forces(const std::string& model, const SceneCase& c, const ConfinementTable& table,
                                          const NearFieldCalibration& near_field = NearFieldCalibration::built_in(),
                                          const WallProximityCalibration& wall = WallProximityCalibration::built_in());

// Per sphere: in-plane force / (3 pi mu d U) and z torque about the sphere's
// centre / (3 pi mu d^2 U), at the case's sphere velocities and spins.
struct SceneSphereLoads {
  std::vector<Eigen::Vector2d> forces;
  std::vector<double> torques;
};
SceneSphereLoads scene_sphere_loads(const std::string& model, const SceneCase& c, const ConfinementTable& table,
                                    const NearFieldCalibration& near_field = NearFieldCalibration::built_in(),
                                    const WallProximityCalibration& wall = WallProximityCalibration::built_in());

// The rod's z torque about the centroid of its sphere centres, over
// 3 pi mu d^2 U: sum of (x_i - c) x F_i + T_i (forces over 3 pi mu d U, T_i
// over 3 pi mu d^2 U, positions [m], d [m]).
double rod_torque(const std::vector<Eigen::Vector3d>& positions, double d, const std::vector<Eigen::Vector2d>& forces,
                  const std::vector<double>& torques);

// What a case's load is made of: the rod, the flow the levels see (the
// channel at rest or in flow, or the wide slit), the sphere velocities [m/s]
// and spins about z [rad/s].
struct SceneLoad {
  RodGeometry rod;
  std::unique_ptr<BackgroundFlow> flow;
  Eigen::VectorXd velocities;  // 3n
  Eigen::VectorXd spins;       // n
  double force_scale = 1.0;    // 3 pi mu d U [N]
};
SceneLoad scene_load(const SceneCase& c);

// The near-wall correction `law` alone (its change of the per-sphere force,
// over 3 pi mu d U): the correction is additive to every level's load, so a
// fit evaluates the levels once without it and adds this.
std::vector<Eigen::Vector2d> wall_proximity_forces(const WallProximityLaw& law, const SceneCase& c,
                                                   const SceneLoad& load);

// RMS over the spheres of |model - resolved| over the mean |resolved| [-].
double profile_rms(const std::vector<Eigen::Vector2d>& model, const std::vector<Eigen::Vector2d>& resolved);

}  // namespace hsrod::calib

// hsrod calibration: the set of immersed spheres seen by the resolved solver.
//
// Plain C++17 (no OpenFOAM, no LIGGGHTS) so that every driver can fill it:
//   - force-measurement mode: spheres fixed or moved on a prescribed path
//     (constant velocity, or a table of positions versus time),
//   - coupled mode: positions/velocities written by the LIGGGHTS coupling
//     (fix couple/cfd) every coupling interval via set_spheres().
// Forces/torques written back here by the solver are the hydrodynamic loads
// ON the spheres (SI: N, N m).
#pragma once

#include <array>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace hsrod::calib {

using Vec3 = std::array<double, 3>;

struct Sphere {
  long id = 0;          // user / LIGGGHTS atom id
  long mol = 0;         // molecule (rod) id from the DEM side, 0 = none
  Vec3 x{};             // centre [m]
  Vec3 v{};             // translational velocity [m/s]
  Vec3 omega{};         // angular velocity [rad/s]
  double d = 0.0;       // diameter [m]
  Vec3 force{};         // hydrodynamic force on the sphere [N]
  Vec3 torque{};        // hydrodynamic torque about x [N m]
  double radius() const { return 0.5 * d; }
  // Rigid-body velocity at point p [m/s]: v + omega x (p - x).
  Vec3 rigid_velocity(const Vec3& p) const;
};

enum class MotionMode {
  Fixed,             // spheres stay where the CSV puts them (v, omega only set the BC of the body)
  ConstantVelocity,  // x(t) = x0 + v t
  Table,             // x(t) linearly interpolated from a (t,id,x,y,z) CSV; v from the slope
  Coupled            // set externally (LIGGGHTS) through set_spheres()
};

MotionMode parse_motion_mode(const std::string& name);  // throws std::invalid_argument

class SphereSet {
 public:
  // Reads a CSV with a header line; columns by name (any order):
  //   id,x,y,z,d  required; vx,vy,vz,wx,wy,wz optional (default 0). '#' starts a comment.
  // A header without rows is an empty set (flow without bodies).
  static SphereSet read_csv(const std::string& path);
  static SphereSet from_text(const std::string& text, const std::string& origin = "<text>");

  // Prescribed path table: CSV with columns t,id,x,y,z (t ascending per id).
  void read_path_table(const std::string& path);
  void set_path_table_text(const std::string& text, const std::string& origin = "<text>");

  void set_motion(MotionMode m) { mode_ = m; }
  MotionMode motion() const { return mode_; }

  // Positions and velocities at time t [s] for the prescribed modes (no-op for Fixed/Coupled).
  void set_time(double t);

  // Coupled mode: replace all spheres (the DEM side owns the list).
  void set_spheres(std::vector<Sphere> spheres);

  std::vector<Sphere>& spheres() { return spheres_; }
  const std::vector<Sphere>& spheres() const { return spheres_; }
  std::size_t size() const { return spheres_.size(); }

  // CSV output of the hydrodynamic loads: one line per sphere and time.
  static void write_force_header(std::ostream& os);
  void write_forces(std::ostream& os, double t) const;

 private:
  struct Sample { double t; Vec3 x; };
  std::vector<Sphere> spheres_;
  std::vector<Vec3> x0_;                       // positions at t = 0 [m]
  std::map<long, std::vector<Sample>> table_;  // prescribed path per id
  MotionMode mode_ = MotionMode::Fixed;
};

}  // namespace hsrod::calib

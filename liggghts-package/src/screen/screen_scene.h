// hsrod screening of a resolved CFD-DEM input script (doc:
// liggghts-package/doc/hsrod_screen.txt). What the stand-in fixes
// record while the unchanged script runs, and the scene file's values.
#pragma once

#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace hsrod::screen {

// A fix wall/gran primitive of the script.
struct WallPrimitive {
  std::string fix_id;
  char normal_axis = 'z';   // plane: its normal axis; cylinder: its axis
  bool cylinder = false;
  double position = 0.0;    // plane: coordinate [m]
  double radius = 0.0;      // cylinder radius [m]
  double centre[2] = {0.0, 0.0};  // cylinder axis position in the other two axes [m]
};

// The values of the scene file (calibration/tools/hsrod_case.py's JSON) the
// reduced model needs and the LIGGGHTS script does not hold.
struct SceneFile {
  std::string path;
  double viscosity = 1e-3;      // mu [Pa s]
  double fluid_density = 1000;  // rho_f [kg/m^3]
  double mean_velocity = 0.0;   // U [m/s]
  bool has_pore = false;
  double pore_radius = 0.0;     // R [m]
  double pore_x = 0.0;          // [m]
  double end_time = 0.0;        // physical time of the resolved run [s] (0: unknown)
  long cells = 0;               // resolved mesh cells (base mesh x refinement estimate)
  double reduced_dt = 2e-6;     // timestep of the reduced prediction [s]
  double reduced_t_max = 0.0;   // [s], 0: end_time
};

struct ScreenState {
  SceneFile scene;
  std::vector<WallPrimitive> walls;
  std::vector<std::string> replaced;  // "fix ID style -> what" lines for the report
  int couple_every = 0;               // DEM steps per CFD step (fix couple/cfd)
  bool coupling_seen = false;
  std::string group = "all";          // group of the coupling fix
};

// The state of a LAMMPS instance in screening mode (nullptr otherwise).
ScreenState *state_of(LAMMPS_NS::LAMMPS *lmp);
void set_state(LAMMPS_NS::LAMMPS *lmp, ScreenState *state);

// Reads the scene file; throws std::runtime_error naming the file and key.
SceneFile read_scene_file(const std::string &path);

}  // namespace hsrod::screen

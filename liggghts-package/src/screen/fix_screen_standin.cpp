#include "fix_screen_standin.h"

#include "screen_scene.h"

#include "domain.h"
#include "error.h"
#include "input.h"
#include "modify.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "comm.h"

using namespace LAMMPS_NS;
using hsrod::screen::ScreenState;
using hsrod::screen::state_of;

namespace {

ScreenState &screen_state(LAMMPS *lmp, Error *error) {
  ScreenState *state = state_of(lmp);
  if (!state) error->all(FLERR, "hsrod screen: stand-in fix created outside screening mode");
  return *state;
}

std::string replaced_line(int narg, char **arg, const char *what) {
  return std::string("fix ") + arg[0] + " " + (narg > 2 ? arg[2] : "") + " -> " + what;
}

}  // namespace

FixScreenInert::FixScreenInert(LAMMPS *lammps, int narg, char **arg) : Fix(lammps, narg, arg) {
  const bool integrator = narg > 2 && std::strcmp(arg[2], "nve/sphere") == 0;
  screen_state(lmp, error).replaced.push_back(
      replaced_line(narg, arg, integrator ? "not applied (fix rod/implicit integrates the rods)"
                                          : "not applied (the reduced model's drag replaces the CFD exchange)"));
}

FixScreenWall::FixScreenWall(LAMMPS *lammps, int narg, char **arg) : Fix(lammps, narg, arg) {
  ScreenState &state = screen_state(lmp, error);
  int i = 3;
  while (i < narg && std::strcmp(arg[i], "primitive") != 0) ++i;
  // primitive type N {x,y,z}plane pos | {x,y,z}cylinder R c1 c2
  if (i + 4 >= narg || std::strcmp(arg[i + 1], "type") != 0)
    error->all(FLERR, "hsrod screen: fix wall/gran: only 'primitive type N xplane|yplane|zplane pos' or "
                      "'primitive type N xcylinder|ycylinder|zcylinder R c1 c2' walls can be screened");
  hsrod::screen::WallPrimitive wall;
  wall.fix_id = id;
  const std::string kind = arg[i + 3];
  wall.normal_axis = kind[0];
  if (kind.size() == 6 && kind.compare(1, 5, "plane") == 0 && (kind[0] >= 'x' && kind[0] <= 'z')) {
    wall.position = std::atof(arg[i + 4]);
  } else if (kind.size() == 9 && kind.compare(1, 8, "cylinder") == 0 && (kind[0] >= 'x' && kind[0] <= 'z') &&
             i + 6 < narg) {
    wall.cylinder = true;
    wall.radius = std::atof(arg[i + 4]);
    wall.centre[0] = std::atof(arg[i + 5]);
    wall.centre[1] = std::atof(arg[i + 6]);
  } else {
    error->all(FLERR, "hsrod screen: fix wall/gran: primitive must be xplane, yplane, zplane, xcylinder, ycylinder "
                      "or zcylinder");
  }
  state.walls.push_back(wall);
  state.replaced.push_back(replaced_line(narg, arg, "recorded as a scene wall (implicit contact in fix rod/implicit)"));
}

FixScreenCoupling::FixScreenCoupling(LAMMPS *lammps, int narg, char **arg) : Fix(lammps, narg, arg) {
  ScreenState &state = screen_state(lmp, error);
  for (int i = 3; i + 1 < narg; ++i)
    if (std::strcmp(arg[i], "couple_every") == 0) state.couple_every = std::atoi(arg[i + 1]);
  state.coupling_seen = true;
  state.group = arg[1];
  state.replaced.push_back(replaced_line(narg, arg, "fix hsrod_screen_drag hele_shaw/drag + fix hsrod_screen_step rod/implicit"));
}

// The reduced model, added after this fix is in the fix list: the scene
// from the box (channel), the scene file (fluid, inflow, pore) and the
// script's fix rod/bonds.
void FixScreenCoupling::post_create() {
  ScreenState &state = screen_state(lmp, error);
  int bonds = -1;
  for (int i = 0; i < modify->nfix; ++i)
    if (std::strcmp(modify->fix[i]->style, "rod/bonds") == 0) bonds = i;
  if (bonds < 0)
    error->all(FLERR, "hsrod screen: no fix rod/bonds before fix couple/cfd: screening needs the rods as "
                      "create_rod + fix rod/bonds (as calibration/tools/hsrod_case.py writes them)");
  const auto &s = state.scene;
  char line[1024];
  const double L = domain->boxhi[0] - domain->boxlo[0], W = domain->boxhi[1] - domain->boxlo[1],
               H = domain->boxhi[2] - domain->boxlo[2];
  std::string pore;
  if (s.has_pore) {
    std::snprintf(line, sizeof line, " pore %.12g %.12g", s.pore_radius, s.pore_x);
    pore = line;
  }
  std::snprintf(line, sizeof line,
                "fix hsrod_screen_drag %s hele_shaw/drag channel %.12g %.12g %.12g origin %.12g %.12g %.12g%s "
                "viscosity %.12g fluid_density %.12g mean_velocity %.12g model auto timestep_check no placement_check no",
                state.group.c_str(), L, W, H, domain->boxlo[0], domain->boxlo[1], domain->boxlo[2], pore.c_str(),
                s.viscosity, s.fluid_density, s.mean_velocity);
  add_fix_line(line);
  std::snprintf(line, sizeof line, "fix hsrod_screen_step %s rod/implicit bonds %s drag hsrod_screen_drag",
                state.group.c_str(), modify->fix[bonds]->id);
  add_fix_line(line);
}

// Modify::add_fix with our own argument words (Input's buffers belong to the
// command being executed: the script's own `fix ... couple/cfd` line).
void FixScreenCoupling::add_fix_line(const char *line) {
  if (comm->me == 0 && screen) std::fprintf(screen, "hsrod screen: %s\n", line);
  std::vector<std::string> words;
  std::istringstream in(line);
  for (std::string w; in >> w;) words.push_back(w);
  std::vector<char *> argv;
  for (std::size_t i = 1; i < words.size(); ++i) argv.push_back(words[i].data());  // without "fix"
  modify->add_fix(static_cast<int>(argv.size()), argv.data());
}

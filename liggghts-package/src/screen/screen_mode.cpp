#include "screen_mode.h"

#include "fix_screen_standin.h"
#include "screen_scene.h"
#include "rod_bonds_limit.h"
#include "style_registration.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "fix.h"
#include "input.h"
#include "lammps.h"
#include "update.h"
#include "variable.h"

#include <mpi.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace hsrod::screen {
namespace {

template <typename T>
Fix *make(LAMMPS *lmp, int narg, char **arg) {
  return new T(lmp, narg, arg);
}

void say(LAMMPS *lmp, const std::string &text) {
  if (lmp->comm->me == 0) {
    if (lmp->screen) std::fprintf(lmp->screen, "%s\n", text.c_str());
    if (lmp->logfile) std::fprintf(lmp->logfile, "%s\n", text.c_str());
  }
}

std::string fmt(const char *format, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char text[512];
  std::snprintf(text, sizeof text, format, a, b, c, d);
  return text;
}

// All sphere centres and radii, gathered on every rank (screening runs are small).
struct Spheres {
  std::vector<double> x, r;
  std::vector<long> tag, mol;
};
Spheres gather(LAMMPS *lmp) {
  Atom *atom = lmp->atom;
  std::vector<double> mine;
  for (int i = 0; i < atom->nlocal; ++i) {
    mine.insert(mine.end(), {atom->x[i][0], atom->x[i][1], atom->x[i][2], atom->radius[i],
                             static_cast<double>(atom->tag[i]),
                             atom->molecule ? static_cast<double>(atom->molecule[i]) : 0.0});
  }
  int count = static_cast<int>(mine.size()), ranks = 1;
  MPI_Comm_size(lmp->world, &ranks);
  std::vector<int> counts(ranks), offsets(ranks, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, lmp->world);
  for (int p = 1; p < ranks; ++p) offsets[p] = offsets[p - 1] + counts[p - 1];
  std::vector<double> all(offsets[ranks - 1] + counts[ranks - 1]);
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, lmp->world);
  Spheres s;
  for (std::size_t k = 0; k + 5 < all.size(); k += 6) {
    s.x.insert(s.x.end(), {all[k], all[k + 1], all[k + 2]});
    s.r.push_back(all[k + 3]);
    s.tag.push_back(static_cast<long>(all[k + 4]));
    s.mol.push_back(static_cast<long>(all[k + 5]));
  }
  return s;
}

double evaluate(LAMMPS *lmp, const char *formula) {
  std::string command = std::string("variable hsrod_screen_eval equal \"") + formula + "\"";
  lmp->input->one(command.c_str());
  return lmp->input->variable->compute_equal(lmp->input->variable->find((char *)"hsrod_screen_eval"));
}

// 1. Stability of the script's (resolved run's) explicit DEM step of dt [s]:
// 1 when it exceeds the explicit limit of the script's rod bonds.
int check_timestep(LAMMPS *lmp, double dt) {
  const double limit = hsrod::explicit_bond_limit(lmp);
  if (limit > 0.0) {
    const bool unstable = dt > limit;
    say(lmp, fmt(unstable ? "  UNSTABLE timestep: the script's dt = %g s exceeds the explicit bond limit %g s of its "
                            "rods (fix nve/sphere in the resolved run would blow up; dt/limit = %.3g)"
                          : "  timestep: the script's dt = %g s is below the explicit bond limit %g s (dt/limit = %.3g): ok",
                 dt, limit, dt / limit));
    return unstable;
  }
  say(lmp, "  timestep: no fix rod/bonds (or no run yet): bond stability not checked");
  return 0;
}

// 2. Initial overlaps and spheres outside the channel.
struct Placement {
  int overlaps = 0, wall_overlaps = 0, outside = 0;
  double worst = 0.0;       // deepest sphere-sphere overlap over the contact distance
  double worst_wall = 0.0;  // deepest sphere-wall overlap over the radius
  int problems() const { return (overlaps > 0) + (wall_overlaps > 0) + (outside > 0); }
};

Placement check_placement(LAMMPS *lmp, const ScreenState &state, const SceneFile &scene) {
  Placement p;
  const Spheres s = gather(lmp);
  const std::size_t n = s.r.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (s.mol[i] == s.mol[j] && s.mol[i] != 0) continue;  // a rod's own spheres: bonded neighbours touch by design
      const double dx = s.x[3 * i] - s.x[3 * j], dy = s.x[3 * i + 1] - s.x[3 * j + 1], dz = s.x[3 * i + 2] - s.x[3 * j + 2];
      const double overlap = s.r[i] + s.r[j] - std::sqrt(dx * dx + dy * dy + dz * dz);
      if (overlap > 0.0) {
        ++p.overlaps;
        p.worst = std::max(p.worst, overlap / (s.r[i] + s.r[j]));
      }
    }
  const double *lo = lmp->domain->boxlo, *hi = lmp->domain->boxhi;
  for (std::size_t i = 0; i < n; ++i) {
    const double *x = &s.x[3 * i];
    bool out = false;
    for (int a = 0; a < 3; ++a) out = out || x[a] < lo[a] || x[a] > hi[a];
    for (const WallPrimitive &w : state.walls) {
      const int a = w.normal_axis - 'x';
      double gap;
      if (!w.cylinder) {
        gap = std::fabs(x[a] - w.position) - s.r[i];
      } else {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        const double rho = std::hypot(x[b] - w.centre[0], x[c] - w.centre[1]);
        out = out || rho < w.radius;
        gap = std::fabs(rho - w.radius) - s.r[i];
      }
      if (gap < 0.0) {
        ++p.wall_overlaps;
        p.worst_wall = std::max(p.worst_wall, -gap / s.r[i]);
      }
    }
    if (scene.has_pore) {
      const double W = hi[1] - lo[1];
      for (double yc : {lo[1], lo[1] + W})
        out = out || std::hypot(x[0] - scene.pore_x, x[1] - yc) < scene.pore_radius;
    }
    p.outside += out;
  }
  say(lmp, p.overlaps ? fmt("  OVERLAP: %g pair(s) of spheres of different rods overlap initially (worst %.3g of the "
                            "contact distance)", p.overlaps, p.worst)
                      : "  initial sphere-sphere overlaps between rods: none");
  say(lmp, p.wall_overlaps ? fmt("  OVERLAP: %g sphere-wall overlap(s) with the script's fix wall/gran walls (worst "
                                 "%.3g of the radius)", p.wall_overlaps, p.worst_wall)
                           : fmt("  initial sphere-wall overlaps (%g fix wall/gran walls): none",
                                 static_cast<double>(state.walls.size())));
  say(lmp, p.outside ? fmt("  OUTSIDE: %g sphere centre(s) outside the box or inside the pore cylinders", p.outside)
                     : "  spheres outside the channel or inside obstacles: none");
  return p;
}

// 4. Cost of the resolved run over t_max [s] at the script's DEM step dt [s]
// against the reduced prediction's `wall` seconds.
void report_cost(LAMMPS *lmp, const ScreenState &state, const SceneFile &scene, double dt, double t_max, double wall) {
  const double dem_steps = t_max / dt;
  const double cfd_steps = state.couple_every > 0 ? dem_steps / state.couple_every : 0.0;
  // Cost model, measured on the reference machine: ~1.1 us per cell and CFD
  // step (a 60k-cell pimpleFoam step takes ~65 ms serial) and ~1 us per DEM
  // step of a few spheres (stock LIGGGHTS).
  const double resolved = cfd_steps * static_cast<double>(scene.cells) * 1.1e-6 + dem_steps * 1.0e-6;
  say(lmp, fmt("  cost: resolved run ~%g cells x %g CFD steps (couple_every %g) + ", static_cast<double>(scene.cells),
               cfd_steps, state.couple_every) +
               fmt("%g DEM steps of dt = %g s", dem_steps, dt));
  say(lmp, fmt("        ~%.3g s serial (1.1 us per cell-step, 1 us per DEM step) against %.3g s for this reduced "
               "prediction: ~%.3g x", resolved, wall, wall > 0.0 ? resolved / wall : 0.0));
}

// 3. The reduced model's prediction over t_max [s] of physical time from the
// script's end, then its cost against the resolved run's (DEM step dt [s]).
void predict(LAMMPS *lmp, const ScreenState &state, const SceneFile &scene, double dt, double t_max) {
  const double t0 = evaluate(lmp, "time");
  char line[256];
  std::snprintf(line, sizeof line, "timestep %.12g", std::min(scene.reduced_dt, t_max));
  lmp->input->one(line);
  lmp->input->one("compute hsrod_screen_shape all rod/shape contacts hsrod_screen_step");
  lmp->input->one("thermo_style custom step time c_hsrod_screen_shape[2] c_hsrod_screen_shape[7] "
                  "c_hsrod_screen_shape[14]");
  const long steps = std::max(1L, std::lround(t_max / lmp->update->dt));
  const long chunk = std::max(1L, std::min(steps, std::lround(1e-4 / lmp->update->dt)));
  std::snprintf(line, sizeof line, "thermo %ld", chunk);
  lmp->input->one(line);
  const auto start = std::chrono::steady_clock::now();
  long done = 0;
  double outcome = 0.0;
  while (done < steps) {
    const long now = std::min(chunk, steps - done);
    std::snprintf(line, sizeof line, "run %ld", now);
    lmp->input->one(line);
    done += now;
    outcome = evaluate(lmp, "c_hsrod_screen_shape[14]");
    if (outcome > 0.0) break;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  static const char *classes[] = {"en route (not decided within the time)", "passed without wall contact",
                                  "passed with wall contact", "clogged"};
  const int k = static_cast<int>(std::lround(outcome));
  say(lmp, "  predicted by the reduced model over " + fmt("%g s (from t = %g s, %g steps of %g s):", done * lmp->update->dt, t0,
                                                         static_cast<double>(done), lmp->update->dt));
  say(lmp, std::string("    outcome: ") + (k >= 0 && k <= 3 ? classes[k] : "?"));
  say(lmp, fmt("    rod centre x = %g m, angle %g deg, relative deflection %g, lateral displacement %g W",
               evaluate(lmp, "c_hsrod_screen_shape[2]"), evaluate(lmp, "c_hsrod_screen_shape[7]"),
               evaluate(lmp, "c_hsrod_screen_shape[8]"), evaluate(lmp, "c_hsrod_screen_shape[9]")));
  report_cost(lmp, state, scene, dt, t_max, wall);
}

}  // namespace

std::string requested_scene(int argc, char **argv) {
  for (int i = 1; i + 2 < argc; ++i)
    if ((std::strcmp(argv[i], "-var") == 0 || std::strcmp(argv[i], "-v") == 0) &&
        std::strcmp(argv[i + 1], "hsrod_screen") == 0)
      return std::strcmp(argv[i + 2], "1") == 0 ? "scene.json" : argv[i + 2];
  return "";
}

bool begin(LAMMPS *lmp, const std::string &scene_path) {
  auto *state = new ScreenState;
  try {
    state->scene = read_scene_file(scene_path);
  } catch (const std::exception &e) {
    say(lmp, std::string("ERROR: ") + e.what());
    delete state;
    return false;
  }
  set_state(lmp, state);
  hsrod::register_fix_style(lmp, "couple/cfd", &make<FixScreenCoupling>);
  for (const char *style : {"couple/cfd/force", "couple/cfd/force/implicit", "couple/cfd/torque/implicit", "nve/sphere"})
    hsrod::register_fix_style(lmp, style, &make<FixScreenInert>);
  hsrod::register_fix_style(lmp, "wall/gran", &make<FixScreenWall>);
  say(lmp, "hsrod screen: screening mode (scene file " + scene_path +
               "): fix couple/cfd* and nve/sphere are replaced by the reduced model, fix wall/gran walls recorded");
  return true;
}

void report(LAMMPS *lmp) {
  ScreenState *state = state_of(lmp);
  if (!state) return;
  const SceneFile &scene = state->scene;
  say(lmp, "");
  say(lmp, "==== hsrod screen: pre-flight report ====");
  for (const std::string &line : state->replaced) say(lmp, "  replaced: " + line);
  if (!state->coupling_seen) say(lmp, "  WARNING: the script has no fix couple/cfd: nothing was coupled");
  int problems = 0;

  const double dt = lmp->update->dt;
  problems += check_timestep(lmp, dt);
  const Placement placement = check_placement(lmp, *state, scene);
  problems += placement.problems();

  const double t_resolved = scene.end_time;
  const double t_max = scene.reduced_t_max > 0.0 ? scene.reduced_t_max : (t_resolved > 0.0 ? t_resolved : 0.02);
  if (placement.problems() == 0) {
    predict(lmp, *state, scene, dt, t_max);
  } else {
    say(lmp, fmt("  prediction skipped: fix the %g overlap/placement problem(s) above first", placement.problems()));
  }
  say(lmp, fmt("==== hsrod screen: %g problem(s) ====", problems));
  set_state(lmp, nullptr);
  delete state;
}

}  // namespace hsrod::screen

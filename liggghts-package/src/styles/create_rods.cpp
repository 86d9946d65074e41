/* ----------------------------------------------------------------------
   hsrod - create_rods command (see create_rods.h)

   create_rods N drag ID spheres n diameter d type T density rho [keyword value ...]
     optional: layout random|lattice, seed S, angle alpha|random [deg],
               region x_min x_max [m], min_gap g [m], spacing s [m],
               bond_type B
   The planform and the gap come from the drag fix; the rods lie at the gap
   mid-plane. Atoms already in the box are kept clear of.
------------------------------------------------------------------------- */

#include "create_rods.h"

#include "create_rod.h"

#include "common/math_constants.h"
#include "fix_hele_shaw_drag.h"
#include "keyword_parsing.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "modify.h"

#include "geometry/rod_seeding.h"
#include "hydro/rod_hydrodynamics.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

CreateRods::CreateRods(LAMMPS *instance) : Pointers(instance) {}

namespace LAMMPS_NS {

int parse_seeded_rods_keyword(Error *error, const char *style, int narg, char **arg, int iarg, SeededRodsSpec &a) {
  const char *key = arg[iarg];
  static const char *known[] = {"drag", "spheres", "diameter", "type", "density", "layout", "seed",
                                "angle", "region", "min_gap", "spacing", "bond_type", "jitter"};
  if (std::none_of(std::begin(known), std::end(known), [&](const char *k) { return std::strcmp(k, key) == 0; }))
    return 0;
  const int count = std::strcmp(key, "region") == 0 || std::strcmp(key, "jitter") == 0 ? 2 : 1;
  if (iarg + count >= narg) {
    char msg[160];
    std::snprintf(msg, sizeof(msg), "Illegal %s command: %s expects %d value(s)", style, key, count);
    error->all(FLERR, msg);
  }
  const char *v = arg[iarg + 1];
  char msg[200];
  if (std::strcmp(key, "drag") == 0) {
    a.drag_id = v;
  } else if (std::strcmp(key, "spheres") == 0) {
    a.seeding.spheres = parse_integer(error, style, key, v);
    a.have_spheres = true;
  } else if (std::strcmp(key, "diameter") == 0) {
    a.seeding.sphere_diameter = parse_number(error, style, key, v);
    a.have_diameter = true;
  } else if (std::strcmp(key, "type") == 0) {
    a.type = parse_integer(error, style, key, v);
    a.have_type = true;
  } else if (std::strcmp(key, "density") == 0) {
    a.density = parse_number(error, style, key, v);
    a.have_density = true;
  } else if (std::strcmp(key, "layout") == 0) {
    if (std::strcmp(v, "random") == 0) a.seeding.layout = hsrod::SeedingLayout::random;
    else if (std::strcmp(v, "lattice") == 0) a.seeding.layout = hsrod::SeedingLayout::lattice;
    else {
      std::snprintf(msg, sizeof(msg), "Illegal %s command: layout must be random or lattice", style);
      error->all(FLERR, msg);
    }
  } else if (std::strcmp(key, "seed") == 0) {
    const int seed = parse_integer(error, style, key, v);
    if (seed < 1) {
      std::snprintf(msg, sizeof(msg), "Illegal %s command: seed must be an integer >= 1", style);
      error->all(FLERR, msg);
    }
    a.seeding.seed = static_cast<std::uint64_t>(seed);
  } else if (std::strcmp(key, "angle") == 0) {
    if (std::strcmp(v, "random") == 0) a.seeding.angle.reset();
    else a.seeding.angle = parse_number(error, style, key, v) * hsrod::kPi / 180.0;
  } else if (std::strcmp(key, "region") == 0) {
    a.seeding.x_min = parse_number(error, style, key, v);
    a.seeding.x_max = parse_number(error, style, key, arg[iarg + 2]);
  } else if (std::strcmp(key, "min_gap") == 0) {
    a.seeding.min_gap = parse_number(error, style, key, v);
  } else if (std::strcmp(key, "spacing") == 0) {
    a.seeding.spacing = parse_number(error, style, key, v);
  } else if (std::strcmp(key, "jitter") == 0) {
    a.seeding.jitter_position = parse_number(error, style, key, v);
    a.seeding.jitter_angle = parse_number(error, style, key, arg[iarg + 2]) * hsrod::kPi / 180.0;
  } else {
    a.bond_type = parse_integer(error, style, key, v);
  }
  return 1 + count;
}

void check_seeded_rods_required(Error *error, const char *style, const SeededRodsSpec &a) {
  if (!a.drag_id.empty() && a.have_spheres && a.have_diameter && a.have_type && a.have_density) return;
  char msg[200];
  std::snprintf(msg, sizeof(msg), "Illegal %s command: drag, spheres, diameter, type and density are required", style);
  error->all(FLERR, msg);
}

FixHeleShawDrag *seeding_drag_fix(LAMMPS *lmp, const char *style, const SeededRodsSpec &a) {
  const int ifix = lmp->modify->find_fix(a.drag_id.c_str());
  auto *drag = ifix < 0 ? nullptr : dynamic_cast<FixHeleShawDrag *>(lmp->modify->fix[ifix]);
  if (!drag) {
    const std::string msg =
        std::string(style) + ": drag " + a.drag_id + " must be the ID of a fix hele_shaw/drag defined before";
    lmp->error->all(FLERR, msg.c_str());
  }
  return drag;
}

// Seeded rods keep clear of rods made before.
std::vector<hsrod::RodObstacle> atoms_as_obstacles(LAMMPS *lmp) {
  Atom *atom = lmp->atom;
  std::vector<double> mine;
  for (int i = 0; i < atom->nlocal; ++i) mine.insert(mine.end(), {atom->x[i][0], atom->x[i][1], 2.0 * atom->radius[i]});
  int me = static_cast<int>(mine.size()), nprocs = lmp->comm->nprocs;
  std::vector<int> counts(nprocs), offsets(nprocs, 0);
  MPI_Allgather(&me, 1, MPI_INT, counts.data(), 1, MPI_INT, lmp->world);
  for (int p = 1; p < nprocs; ++p) offsets[p] = offsets[p - 1] + counts[p - 1];
  std::vector<double> all(offsets.back() + counts.back());
  MPI_Allgatherv(mine.data(), me, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, lmp->world);
  std::vector<hsrod::RodObstacle> out;
  for (std::size_t k = 0; k + 2 < all.size(); k += 3) {
    const Eigen::Vector2d p(all[k], all[k + 1]);
    out.push_back({p, p, all[k + 2]});
  }
  return out;
}

// Each rod as the create_rod command would read it (the same text, so the
// same numbers), without the map and special-list rebuild per rod.
void make_seeded_rods(CreateRod &creator, CreateRod::NextRodIds &next, const SeededRodsSpec &a,
                      const std::vector<hsrod::SeededRod> &rods, double z) {
  for (const hsrod::SeededRod &rod : rods) {
    char line[512];
    std::snprintf(line, sizeof(line),
                  "create_rod spheres %d diameter %.17g type %d density %.17g centre %.17g %.17g %.17g "
                  "angle %.17g bond_type %d",
                  a.seeding.spheres, a.seeding.sphere_diameter, a.type, a.density, rod.centre.x(), rod.centre.y(), z,
                  rod.angle * 180.0 / hsrod::kPi, a.bond_type);
    std::string command = line + std::strlen("create_rod ");
    if (a.seeding.spacing > 0) {
      std::snprintf(line, sizeof(line), " spacing %.17g", a.seeding.spacing);
      command += line;
    }
    std::vector<std::string> words;
    for (std::size_t at = 0; at < command.size();) {
      const std::size_t end = std::min(command.find(' ', at), command.size());
      if (end > at) words.push_back(command.substr(at, end - at));
      at = end + 1;
    }
    std::vector<char *> args;
    for (std::string &w : words) args.push_back(&w[0]);
    creator.add(static_cast<int>(args.size()), args.data(), next, false);
  }
}

}  // namespace LAMMPS_NS

namespace {

constexpr const char *kStyle = "create_rods";

SeededRodsSpec parse(Error *error, int narg, char **arg) {
  if (narg < 1) error->all(FLERR, "Illegal create_rods command: expects N (the number of rods, >= 1) first");
  SeededRodsSpec a;
  a.seeding.rods = parse_integer(error, kStyle, "N", arg[0]);
  if (a.seeding.rods < 1) error->all(FLERR, "Illegal create_rods command: N (the number of rods) must be >= 1");
  for (int iarg = 1; iarg < narg;) {
    const int used = parse_seeded_rods_keyword(error, kStyle, narg, arg, iarg, a);
    if (used == 0) {
      char msg[160];
      std::snprintf(msg, sizeof(msg), "Illegal create_rods command: unknown keyword '%s'", arg[iarg]);
      error->all(FLERR, msg);
    }
    iarg += used;
  }
  check_seeded_rods_required(error, kStyle, a);
  return a;
}

}  // namespace

void CreateRods::command(int narg, char **arg) {
  const SeededRodsSpec a = parse(error, narg, arg);
  const hsrod::RodHydrodynamics &scene = seeding_drag_fix(lmp, kStyle, a)->hydrodynamics();
  const double gap_height = scene.geometry().gap_height();  // [m]
  if (!(a.seeding.sphere_diameter > 0.0 && a.seeding.sphere_diameter < gap_height)) {
    char msg[256];
    std::snprintf(msg, sizeof(msg), "create_rods: diameter %g m must be > 0 and below the gap height %g m (beta = d/H < 1)",
                  a.seeding.sphere_diameter, gap_height);
    error->all(FLERR, msg);
  }
  std::vector<hsrod::SeededRod> rods;
  try {
    // The same seed on every rank gives the same rods everywhere.
    rods = hsrod::seed_rods(scene.geometry(), a.seeding, atoms_as_obstacles(lmp));
  } catch (const std::exception &e) {
    const std::string msg = std::string("create_rods: ") + e.what();
    error->all(FLERR, msg.c_str());
  }
  const double z = scene.gap_bottom() + 0.5 * scene.geometry().gap_height();
  CreateRod creator(lmp);
  CreateRod::NextRodIds next = creator.next_ids();
  make_seeded_rods(creator, next, a, rods, z);
  creator.finish();
  if (comm->me == 0) {
    const double phi = hsrod::rod_area_fraction(scene.geometry(), a.seeding, static_cast<int>(rods.size()));
    char msg[256];
    std::snprintf(msg, sizeof(msg), "create_rods: %zu rods of %d spheres seeded (%s), area fraction %.4g\n",
                  rods.size(), a.seeding.spheres,
                  a.seeding.layout == hsrod::SeedingLayout::random ? "random" : "lattice", phi);
    if (screen) std::fputs(msg, screen);
    if (logfile) std::fputs(msg, logfile);
  }
}

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

namespace {

constexpr const char *kStyle = "create_rods";

struct CreateRodsArgs {
  hsrod::RodSeedingRequest seeding;
  std::string drag_id;
  int type = 0;                  // atom type
  double density = 0.0;          // [kg/m^3]
  int bond_type = 1;
  bool have_spheres = false, have_diameter = false, have_type = false, have_density = false;
};

void need_values(Error *error, int narg, int iarg, int count, const char *keyword) {
  if (iarg + count >= narg) {
    char msg[160];
    std::snprintf(msg, sizeof(msg), "Illegal create_rods command: %s expects %d value(s)", keyword, count);
    error->all(FLERR, msg);
  }
}

CreateRodsArgs parse(Error *error, int narg, char **arg) {
  if (narg < 1) error->all(FLERR, "Illegal create_rods command: expects N (the number of rods, >= 1) first");
  CreateRodsArgs a;
  a.seeding.rods = parse_integer(error, kStyle, "N", arg[0]);
  if (a.seeding.rods < 1) error->all(FLERR, "Illegal create_rods command: N (the number of rods) must be >= 1");
  for (int iarg = 1; iarg < narg; iarg += 2) {
    const char *key = arg[iarg];
    need_values(error, narg, iarg, std::strcmp(key, "region") == 0 ? 2 : 1, key);
    const char *v = arg[iarg + 1];
    if (std::strcmp(key, "drag") == 0) {
      a.drag_id = v;
    } else if (std::strcmp(key, "spheres") == 0) {
      a.seeding.spheres = parse_integer(error, kStyle, key, v);
      a.have_spheres = true;
    } else if (std::strcmp(key, "diameter") == 0) {
      a.seeding.sphere_diameter = parse_number(error, kStyle, key, v);
      a.have_diameter = true;
    } else if (std::strcmp(key, "type") == 0) {
      a.type = parse_integer(error, kStyle, key, v);
      a.have_type = true;
    } else if (std::strcmp(key, "density") == 0) {
      a.density = parse_number(error, kStyle, key, v);
      a.have_density = true;
    } else if (std::strcmp(key, "layout") == 0) {
      if (std::strcmp(v, "random") == 0) a.seeding.layout = hsrod::SeedingLayout::random;
      else if (std::strcmp(v, "lattice") == 0) a.seeding.layout = hsrod::SeedingLayout::lattice;
      else error->all(FLERR, "Illegal create_rods command: layout must be random or lattice");
    } else if (std::strcmp(key, "seed") == 0) {
      const int seed = parse_integer(error, kStyle, key, v);
      if (seed < 1) error->all(FLERR, "Illegal create_rods command: seed must be an integer >= 1");
      a.seeding.seed = static_cast<std::uint64_t>(seed);
    } else if (std::strcmp(key, "angle") == 0) {
      if (std::strcmp(v, "random") == 0) a.seeding.angle.reset();
      else a.seeding.angle = parse_number(error, kStyle, key, v) * hsrod::kPi / 180.0;
    } else if (std::strcmp(key, "region") == 0) {
      a.seeding.x_min = parse_number(error, kStyle, key, v);
      a.seeding.x_max = parse_number(error, kStyle, key, arg[iarg + 2]);
      ++iarg;
    } else if (std::strcmp(key, "min_gap") == 0) {
      a.seeding.min_gap = parse_number(error, kStyle, key, v);
    } else if (std::strcmp(key, "spacing") == 0) {
      a.seeding.spacing = parse_number(error, kStyle, key, v);
    } else if (std::strcmp(key, "bond_type") == 0) {
      a.bond_type = parse_integer(error, kStyle, key, v);
    } else {
      char msg[160];
      std::snprintf(msg, sizeof(msg), "Illegal create_rods command: unknown keyword '%s'", key);
      error->all(FLERR, msg);
    }
  }
  if (a.drag_id.empty() || !a.have_spheres || !a.have_diameter || !a.have_type || !a.have_density)
    error->all(FLERR, "Illegal create_rods command: drag, spheres, diameter, type and density are required");
  return a;
}

// Every atom already in the box as a point obstacle of its own diameter
// (gathered from all ranks): seeded rods keep clear of rods made before.
std::vector<hsrod::RodObstacle> existing_atoms(LAMMPS *lmp) {
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

}  // namespace

void CreateRods::command(int narg, char **arg) {
  const CreateRodsArgs a = parse(error, narg, arg);
  const int ifix = modify->find_fix(a.drag_id.c_str());
  auto *drag = ifix < 0 ? nullptr : dynamic_cast<FixHeleShawDrag *>(modify->fix[ifix]);
  if (!drag) {
    const std::string msg = "create_rods: drag " + a.drag_id + " must be the ID of a fix hele_shaw/drag defined before";
    error->all(FLERR, msg.c_str());
  }
  const hsrod::RodHydrodynamics &scene = drag->hydrodynamics();
  std::vector<hsrod::SeededRod> rods;
  try {
    // The same seed on every rank gives the same rods everywhere.
    rods = hsrod::seed_rods(scene.geometry(), a.seeding, existing_atoms(lmp));
  } catch (const std::exception &e) {
    const std::string msg = std::string("create_rods: ") + e.what();
    error->all(FLERR, msg.c_str());
  }
  const double z = scene.gap_bottom() + 0.5 * scene.geometry().gap_height();
  // Each rod as the create_rod command would read it (the same text, so the
  // same numbers), without the map and special-list rebuild per rod.
  CreateRod creator(lmp);
  CreateRod::NextRodIds next = creator.next_ids();
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

/* ----------------------------------------------------------------------
   hsrod - create_rod command (see create_rod.h)

   create_rod keyword value ...
     required: spheres N, diameter d [m], type T, density rho [kg/m3],
               centre x y z [m]
     optional: angle alpha [deg] (0 = along y, perpendicular to the flow),
               offset dy [m], section 1|RxL, spacing s [m], mol ID,
               bond_type B
------------------------------------------------------------------------- */

#include "create_rod.h"
#include "common/math_constants.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "keyword_parsing.h"
#include "force.h"
#include "modify.h"
#include "fix.h"
#include "special.h"

#include "rod/rod_layout.h"

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

using namespace LAMMPS_NS;


CreateRod::CreateRod(LAMMPS *instance) : Pointers(instance) {}

namespace {
// What the command line asks for.
struct RodRequest {
  hsrod::RodSpec spec;
  int type = 0, mol = 0, bond_type = 1;  // mol 0: the next free molecule ID
  double density = -1.0, offset = 0.0, angle_deg = 0.0;
  bool have_spacing = false;  // spacing given (it must then be >= d)
};

// Spheres of one rod may touch, never overlap: an overlapping chain has
// bonds shorter than their own section (and no calibrated drag), and was
// refused only later by the step's bond-strain guard. spacing 0 does not
// stand for d: the keyword is omitted for touching spheres.
void check_spacing(Error *error, const hsrod::RodSpec &spec) {
  if (spec.spacing >= (1.0 - 1e-9) * spec.sphere_diameter) return;
  char msg[256];
  std::snprintf(msg, sizeof(msg),
                "create_rod: spacing %g m must be >= the sphere diameter d = %g m (the rod's spheres may touch, not "
                "overlap; omit spacing for touching spheres)", spec.spacing, spec.sphere_diameter);
  error->all(FLERR, msg);
}

RodRequest parse_request(Error *error, int narg, char **arg) {
  RodRequest r;
  hsrod::RodSpec &spec = r.spec;
  bool have[5] = {false, false, false, false, false};  // spheres diameter type density centre
  for (int iarg = 0; iarg < narg;) {
    const char *key = arg[iarg];
    auto need = [&](int n) {
      if (iarg + n >= narg) {
        char msg[256];
        std::snprintf(msg, sizeof(msg), "Illegal create_rod command: keyword %s needs %d value(s)", key, n);
        error->all(FLERR, msg);
      }
    };
    if (strcmp(key, "spheres") == 0) {
      need(1);
      spec.number_of_sections = parse_integer(error, "create_rod", key, arg[iarg + 1]);
      have[0] = true;
      iarg += 2;
    } else if (strcmp(key, "diameter") == 0) {
      need(1);
      spec.sphere_diameter = parse_number(error, "create_rod", key, arg[iarg + 1]);
      have[1] = true;
      iarg += 2;
    } else if (strcmp(key, "type") == 0) {
      need(1);
      r.type = parse_integer(error, "create_rod", key, arg[iarg + 1]);
      have[2] = true;
      iarg += 2;
    } else if (strcmp(key, "density") == 0) {
      need(1);
      r.density = parse_number(error, "create_rod", key, arg[iarg + 1]);
      have[3] = true;
      iarg += 2;
    } else if (strcmp(key, "centre") == 0 || strcmp(key, "center") == 0) {
      need(3);
      for (int a = 0; a < 3; a++) spec.centre[a] = parse_number(error, "create_rod", key, arg[iarg + 1 + a]);
      have[4] = true;
      iarg += 4;
    } else if (strcmp(key, "angle") == 0) {
      need(1);
      r.angle_deg = parse_number(error, "create_rod", key, arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(key, "offset") == 0) {
      need(1);
      r.offset = parse_number(error, "create_rod", key, arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(key, "spacing") == 0) {
      need(1);
      spec.spacing = parse_number(error, "create_rod", key, arg[iarg + 1]);
      r.have_spacing = true;
      iarg += 2;
    } else if (strcmp(key, "section") == 0) {
      need(1);
      try {
        const auto rl = hsrod::parse_section(arg[iarg + 1]);
        spec.section_rows = rl.first;
        spec.section_layers = rl.second;
      } catch (const std::invalid_argument &e) {
        error->all(FLERR, (std::string("create_rod: ") + e.what()).c_str());
      }
      iarg += 2;
    } else if (strcmp(key, "mol") == 0) {
      need(1);
      r.mol = parse_integer(error, "create_rod", key, arg[iarg + 1]);
      if (r.mol <= 0) error->all(FLERR, "create_rod: mol must be a positive molecule ID");
      iarg += 2;
    } else if (strcmp(key, "bond_type") == 0) {
      need(1);
      r.bond_type = parse_integer(error, "create_rod", key, arg[iarg + 1]);
      if (r.bond_type <= 0) error->all(FLERR, "create_rod: bond_type must be >= 1");
      iarg += 2;
    } else {
      char msg[256];
      std::snprintf(msg, sizeof(msg),
                    "Illegal create_rod command: unknown keyword '%s' (expected spheres, diameter, type, "
                    "density, centre, angle, offset, spacing, section, mol, bond_type)", key);
      error->all(FLERR, msg);
    }
  }
  const char *names[5] = {"spheres", "diameter", "type", "density", "centre"};
  for (int k = 0; k < 5; k++) {
    if (!have[k]) {
      char msg[128];
      std::snprintf(msg, sizeof(msg), "Illegal create_rod command: missing required keyword %s", names[k]);
      error->all(FLERR, msg);
    }
  }
  return r;
}

// The values' ranges, once every keyword is read (ntypes: the box's atom types).
void check_request(Error *error, const RodRequest &r, int ntypes) {
  const hsrod::RodSpec &spec = r.spec;
  if (spec.number_of_sections < 2) {
    char msg[128];
    std::snprintf(msg, sizeof(msg), "create_rod: spheres must be >= 2 (got %d)", spec.number_of_sections);
    error->all(FLERR, msg);
  }
  if (!(spec.sphere_diameter > 0.0)) error->all(FLERR, "create_rod: diameter must be > 0 m");
  if (!(r.density > 0.0)) error->all(FLERR, "create_rod: density must be > 0 kg/m3");
  if (r.type < 1 || r.type > ntypes) {
    char msg[128];
    std::snprintf(msg, sizeof(msg), "create_rod: type %d out of range 1..%d", r.type, ntypes);
    error->all(FLERR, msg);
  }
  if (r.have_spacing) check_spacing(error, spec);
}

// The rod's spheres and bonds (rod/rod_layout.h); every sphere must lie inside
// the box (periodic directions wrap). Sets the spec's angle and centre.
hsrod::RodLayout build_layout(Domain *domain, Error *error, RodRequest &r) {
  hsrod::RodSpec &spec = r.spec;
  const double pi = hsrod::kPi;
  spec.angle = r.angle_deg * pi / 180.0;
  spec.centre.y() += r.offset;
  const hsrod::RodLayout layout = hsrod::make_rod_layout(spec);
  for (const auto &s : layout.spheres) {
    for (int a = 0; a < 3; a++) {
      if (domain->periodicity[a]) continue;
      if (s.position[a] < domain->boxlo[a] || s.position[a] >= domain->boxhi[a]) {
        char msg[384];
        std::snprintf(msg, sizeof(msg),
                      "create_rod: sphere at (%g %g %g) is outside the simulation box in direction %c (a rod of %d "
                      "spheres at spacing %g m is %g m long; check centre, angle, spheres and spacing)",
                      s.position[0], s.position[1], s.position[2], "xyz"[a], spec.number_of_sections,
                      spec.effective_spacing(), spec.rod_length());
        error->all(FLERR, msg);
      }
    }
  }
  return layout;
}

// Bond slots per atom for this rod: its bonds are stored once (on the lower
// ID) with newton_bond, on both spheres otherwise.
void reserve_bonds(Atom *atom, Force *force, Error *error, const hsrod::RodLayout &layout, int bond_type) {
  std::vector<int> stored(layout.spheres.size(), 0);
  for (const auto &b : layout.bonds) {
    stored[b.first]++;
    if (!force->newton_bond) stored[b.second]++;
  }
  int needed = 0;
  for (int c : stored) needed = std::max(needed, c);
  if (atom->bond_per_atom < needed) {
    if (atom->nbonds > 0)
      error->all(FLERR, "create_rod: atoms already carry bonds with fewer bond slots per atom than this rod "
                        "needs; create the rod with the most bonds per sphere first");
    atom->bond_per_atom = needed;
    atom->avec->grow(atom->nmax);
  }
  if (atom->nbondtypes < bond_type) atom->nbondtypes = bond_type;
}

// Creates the spheres inside this processor's subdomain, IDs from first_tag
// on; returns each sphere's local index (-1: created by another processor).
std::vector<int> create_spheres(Atom *atom, Domain *domain, const RodRequest &r, const hsrod::RodLayout &layout,
                                int first_tag, int mol) {
  const double pi = hsrod::kPi;
  std::vector<int> local_index(layout.spheres.size(), -1);
  for (size_t s = 0; s < layout.spheres.size(); s++) {
    double xone[3] = {layout.spheres[s].position[0], layout.spheres[s].position[1], layout.spheres[s].position[2]};
    tagint image = ((tagint)IMGMAX << IMG2BITS) | ((tagint)IMGMAX << IMGBITS) | IMGMAX;
    domain->remap(xone, image);
    bool mine = true;
    for (int a = 0; a < 3; a++)
      if (xone[a] < domain->sublo[a] || xone[a] >= domain->subhi[a]) mine = false;
    if (!mine) continue;
    atom->avec->create_atom(r.type, xone);
    const int i = atom->nlocal - 1;
    atom->image[i] = image;
    atom->tag[i] = first_tag + static_cast<int>(s);
    atom->molecule[i] = mol;
    atom->radius[i] = 0.5 * r.spec.sphere_diameter;
    if (atom->density_flag) atom->density[i] = r.density;
    atom->rmass[i] = r.density * pi * std::pow(r.spec.sphere_diameter, 3) / 6.0;
    atom->num_bond[i] = 0;
    local_index[s] = i;
  }
  return local_index;
}

// The rod's bonds on the spheres this processor created.
void add_bonds(Atom *atom, Force *force, const hsrod::RodLayout &layout, const std::vector<int> &local_index,
               int first_tag, int bond_type) {
  auto add_bond = [&](int s, int partner) {
    const int i = local_index[s];
    if (i < 0) return;
    const int m = atom->num_bond[i]++;
    atom->bond_type[i][m] = bond_type;
    atom->bond_atom[i][m] = first_tag + partner;
  };
  for (const auto &b : layout.bonds) {
    add_bond(b.first, b.second);
    if (!force->newton_bond) add_bond(b.second, b.first);
  }
}
}  // namespace

void CreateRod::command(int narg, char **arg) {
  NextRodIds next = next_ids();
  add(narg, arg, next, true);
  finish();
}

// New IDs continue after the largest existing ones.
CreateRod::NextRodIds CreateRod::next_ids() {
  int local_max[2] = {0, 0};
  for (int i = 0; i < atom->nlocal; i++) {
    local_max[0] = std::max(local_max[0], atom->tag[i]);
    local_max[1] = std::max(local_max[1], atom->molecule[i]);
  }
  int global_max[2];
  MPI_Allreduce(local_max, global_max, 2, MPI_INT, MPI_MAX, world);
  return {global_max[0] + 1, global_max[1] + 1};
}

void CreateRod::add(int narg, char **arg, NextRodIds &next, bool report) {
  if (domain->box_exist == 0) error->all(FLERR, "create_rod command before simulation box is defined");
  if (!atom->molecular || !atom->molecule_flag || !atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "create_rod requires an atom style with spheres, bonds and molecule IDs "
                      "(atom_style hybrid granular molecular)");

  RodRequest request = parse_request(error, narg, arg);
  check_request(error, request, atom->ntypes);
  const hsrod::RodSpec &spec = request.spec;
  const hsrod::RodLayout layout = build_layout(domain, error, request);
  reserve_bonds(atom, force, error, layout, request.bond_type);

  const int first_tag = next.tag;
  const int mol = request.mol == 0 ? next.mol : request.mol;
  const int nlocal_before = atom->nlocal;
  const std::vector<int> local_index = create_spheres(atom, domain, request, layout, first_tag, mol);
  int created_here = atom->nlocal - nlocal_before, created = 0;
  MPI_Allreduce(&created_here, &created, 1, MPI_INT, MPI_SUM, world);
  if (created != static_cast<int>(layout.spheres.size()))
    error->all(FLERR, "create_rod: some spheres were not created (outside every processor's subdomain)");
  add_bonds(atom, force, layout, local_index, first_tag, request.bond_type);

  // Fixes with per-atom state initialise the new atoms.
  for (int f = 0; f < modify->nfix; f++)
    if (modify->fix[f]->create_attribute)
      for (int i = nlocal_before; i < atom->nlocal; i++) modify->fix[f]->set_arrays(i);

  atom->natoms += created;
  atom->nbonds += static_cast<bigint>(layout.bonds.size());
  next.tag = first_tag + created;
  next.mol = std::max(next.mol, mol + 1);
  if (!report) return;
  if (comm->me == 0) {
    char msg[256];
    std::snprintf(msg, sizeof(msg),
                  "create_rod: rod mol %d: %d spheres (section %dx%d) of d = %g m, %d bonds, angle %g deg, "
                  "IDs %d..%d\n", mol, created, spec.section_rows, spec.section_layers, spec.sphere_diameter,
                  static_cast<int>(layout.bonds.size()), request.angle_deg, first_tag, first_tag + created - 1);
    if (screen) fputs(msg, screen);
    if (logfile) fputs(msg, logfile);
  }
}

// The atom map and the special (1-2, 1-3, ...) lists once after the last
// rod: both are rebuilt over all atoms, so per rod they made seeding N rods
// O(N^2).
void CreateRod::finish() {
  if (atom->map_style) {
    atom->nghost = 0;
    atom->map_init();
    atom->map_set();
  }
  Special special(lmp);
  special.build();
}

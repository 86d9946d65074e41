/* ----------------------------------------------------------------------
   hsrod - fix rod/bonds (see fix_rod_bonds.h)
------------------------------------------------------------------------- */

#include "fix_rod_bonds.h"
#include "quaternion_storage.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "keyword_parsing.h"
#include "force.h"
#include "group.h"
#include "implicit_partners.h"
#include "neighbor_choice.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include "common/math_constants.h"
#include "rod/beam_bond.h"
#include "rod/rod_layout.h"
#include "rod/stability_limits.h"

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

using hsrod_glue::store_quaternion;
using hsrod_glue::to_quaternion;



}  // namespace

/* ---------------------------------------------------------------------- */

FixRodBonds::FixRodBonds(LAMMPS *instance, int narg, char **arg)
    : Fix(instance, narg, arg),
      timestep_check_(true),
      exclude_pairs_(true),
      orientation_(nullptr),
      bond_rest_(nullptr),
      elastic_energy_(0.0),
      max_strain_(0.0),
      explicit_limit_(0.0),
      limits_printed_(false),
      integrated_implicitly_(false),
      limits_reported_(false),
      limits_diameter_(0.0),
      limits_density_(0.0) {
  if (!atom->molecular || !atom->molecule_flag)
    error->all(FLERR, "fix rod/bonds requires an atom style with bonds and molecule IDs "
                      "(atom_style hybrid granular molecular)");
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, "fix rod/bonds requires per-atom radius, rmass, omega and torque "
                      "(atom_style hybrid granular molecular)");
  if (strcmp(update->unit_style, "si") != 0) error->all(FLERR, "fix rod/bonds requires 'units si'");

  parse_keywords(narg, arg);

  scalar_flag = 1;  // elastic energy of all bonds [J]
  extscalar = 1;
  vector_flag = 1;  // [1] elastic energy [J], [2] largest |axial strain| [-], [3] explicit limit [s]
  size_vector = 3;
  extvector = 0;
  global_freq = 1;
  restart_peratom = 1;
  create_attribute = 1;
  comm_forward = 4;

  grow_arrays(atom->nmax);
  atom->add_callback(0);
  atom->add_callback(1);
  for (int i = 0; i < atom->nlocal; i++) reset_atom(i);

  // Bonded spheres of a rod touch at rest; the granular neighbour lists of
  // this LIGGGHTS ignore special_bonds, so keep each rod out of its own pair
  // contacts (other rods and walls still touch it).
  if (exclude_pairs_) {
    char excl[] = "exclude", mol[] = "molecule";
    char *args[3] = {excl, mol, arg[1]};
    neighbor->modify_params(3, args);
    if (comm->me == 0 && screen)
      fprintf(screen, "fix rod/bonds: pairs within one rod of group %s excluded from pair contacts\n", arg[1]);
  }
}

void FixRodBonds::parse_keywords(int narg, char **arg) {
  bond_set_.youngs_modulus = -1.0;
  bool have_modulus = false;
  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg) {
      char msg[256];
      std::snprintf(msg, sizeof(msg), "Illegal fix rod/bonds command: keyword %s needs a value", arg[iarg]);
      error->all(FLERR, msg);
    }
    const char *key = arg[iarg];
    const char *val = arg[iarg + 1];
    if (strcmp(key, "youngs_modulus") == 0) {
      bond_set_.youngs_modulus = parse_number(error, "fix rod/bonds", key, val);
      have_modulus = true;
    } else if (strcmp(key, "poisson_ratio") == 0) {
      bond_set_.poisson_ratio = parse_number(error, "fix rod/bonds", key, val);
    } else if (strcmp(key, "damping") == 0) {
      bond_set_.damping_ratio = parse_number(error, "fix rod/bonds", key, val);
    } else if (strcmp(key, "bond_radius_ratio") == 0) {
      bond_set_.bond_radius_ratio = parse_number(error, "fix rod/bonds", key, val);
    } else if (strcmp(key, "timestep_check") == 0) {
      timestep_check_ = parse_yes_no(error, "fix rod/bonds", key, val);
    } else if (strcmp(key, "exclude_pairs") == 0) {
      exclude_pairs_ = parse_yes_no(error, "fix rod/bonds", key, val);
    } else {
      char msg[256];
      std::snprintf(msg, sizeof(msg),
                    "Illegal fix rod/bonds command: unknown keyword '%s' (expected youngs_modulus, "
                    "poisson_ratio, damping, bond_radius_ratio, timestep_check, exclude_pairs)", key);
      error->all(FLERR, msg);
    }
  }
  if (!have_modulus) error->all(FLERR, "Illegal fix rod/bonds command: missing required keyword youngs_modulus");
  if (!(bond_set_.youngs_modulus > 0.0)) error->all(FLERR, "fix rod/bonds: youngs_modulus must be > 0 Pa");
  if (!(bond_set_.poisson_ratio >= 0.0 && bond_set_.poisson_ratio < 0.5))
    error->all(FLERR, "fix rod/bonds: poisson_ratio must be in [0, 0.5)");
  if (!(bond_set_.damping_ratio >= 0.0 && bond_set_.damping_ratio <= 1.0))
    error->all(FLERR, "fix rod/bonds: damping (fraction of critical damping) must be in [0, 1]");
  if (!(bond_set_.bond_radius_ratio > 0.0 && bond_set_.bond_radius_ratio <= 1.0))
    error->all(FLERR, "fix rod/bonds: bond_radius_ratio must be in (0, 1]");
  if (atom->bond_per_atom > max_bonds_per_sphere) {
    char msg[256];
    std::snprintf(msg, sizeof(msg), "fix rod/bonds supports at most %d bonds per sphere (data has %d)",
                  max_bonds_per_sphere, atom->bond_per_atom);
    error->all(FLERR, msg);
  }

}

FixRodBonds::~FixRodBonds() {
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(orientation_);
  memory->destroy(bond_rest_);
}

int FixRodBonds::setmask() {
  int mask = 0;
  mask |= POST_INTEGRATE;
  mask |= POST_FORCE;
  return mask;
}

/* ---------------------------------------------------------------------- */

void FixRodBonds::init() {
  // Whether a fix rod/implicit integrates these bonds (decided here, every run).
  integrated_implicitly_ = implicit_integrator_of(modify, error, id) != nullptr;
  if (bond_set_.damping_ratio > 0.0 && !comm->ghost_velocity)
    error->all(FLERR, "fix rod/bonds: damping > 0 needs ghost velocities: add 'communicate single vel yes'");
  compute_stability_limits();
  hsrod::choose_neighbor_style(lmp, "fix rod/bonds");
}

/* ---------------------------------------------------------------------- */

void FixRodBonds::setup(int) {
  comm->forward_comm_fix(this);
  compute_bonds();
}

void FixRodBonds::post_integrate() {
  if (integrated_implicitly_) return;
  // Orientations follow the mid-step angular velocity: q <- exp(dt omega) q.
  const double dt = update->dt;
  double **omega = atom->omega;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const Eigen::Vector3d w(omega[i][0], omega[i][1], omega[i][2]);
    if (w.squaredNorm() == 0.0) continue;
    const Eigen::Quaterniond q = hsrod::quaternion_from_rotation_vector(dt * w) * to_quaternion(orientation_[i]);
    store_quaternion(q.normalized(), orientation_[i]);
  }
}

void FixRodBonds::post_force(int) {
  if (integrated_implicitly_) return;
  comm->forward_comm_fix(this);
  compute_bonds();
}

FixRodBonds::BondRestRecord *FixRodBonds::find_or_create_record(int i, int j, int partner_tag) {
  BondRestRecord *rec = records(i);
  for (int r = 0; r < max_bonds_per_sphere; r++)
    if (static_cast<int>(rec[r].partner_tag) == partner_tag) return &rec[r];
  // First time this bond is seen: its current geometry is its rest state.
  for (int r = 0; r < max_bonds_per_sphere; r++) {
    if (rec[r].partner_tag != 0.0) continue;
    double **x = atom->x;
    const Eigen::Vector3d xi(x[i][0], x[i][1], x[i][2]), xj(x[j][0], x[j][1], x[j][2]);
    const auto rest = hsrod::BeamBondRest::from_current(xi, to_quaternion(orientation_[i]), xj,
                                                        to_quaternion(orientation_[j]));
    rec[r].partner_tag = partner_tag;
    for (int a = 0; a < 3; a++) rec[r].rest_vector[a] = rest.rest_vector_in_frame_i[a];
    store_quaternion(rest.rest_relative_rotation, rec[r].rest_rotation);
    return &rec[r];
  }
  error->one(FLERR, "fix rod/bonds: more bonds on one sphere than rest-state slots");
  return nullptr;
}

void FixRodBonds::compute_bonds() {
  double **x = atom->x, **v = atom->v, **omega = atom->omega;
  double **f = atom->f, **torque = atom->torque;
  double *radius = atom->radius, *rmass = atom->rmass;
  int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const bool newton_bond = force->newton_bond;

  elastic_energy_ = 0.0;
  max_strain_ = 0.0;
  implicit_state_pending_ = false;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int m = 0; m < atom->num_bond[i]; m++) {
      const int partner_tag = atom->bond_atom[i][m];
      int j = atom->map(partner_tag);
      if (j < 0) {
        char msg[256];
        std::snprintf(msg, sizeof(msg),
                      "fix rod/bonds: bond partner %d of atom %d missing on this proc: the partner was lost or "
                      "deleted (%ld atoms now), or ghost atoms do not reach one bond length (use 'communicate "
                      "single cutoff <bond length + skin> vel yes')",
                      partner_tag, atom->tag[i], static_cast<long>(atom->natoms));
        error->one(FLERR, msg);
      }
      j = domain->closest_image(i, j);
      const BondRestRecord *rec = find_or_create_record(i, j, partner_tag);

      hsrod::SphereState si, sj;
      si.position = Eigen::Vector3d(x[i][0], x[i][1], x[i][2]);
      sj.position = Eigen::Vector3d(x[j][0], x[j][1], x[j][2]);
      si.orientation = to_quaternion(orientation_[i]);
      sj.orientation = to_quaternion(orientation_[j]);
      si.velocity = Eigen::Vector3d(v[i][0], v[i][1], v[i][2]);
      sj.velocity = Eigen::Vector3d(v[j][0], v[j][1], v[j][2]);
      si.angular_velocity = Eigen::Vector3d(omega[i][0], omega[i][1], omega[i][2]);
      sj.angular_velocity = Eigen::Vector3d(omega[j][0], omega[j][1], omega[j][2]);

      hsrod::BeamBondRest rest;
      rest.rest_vector_in_frame_i = Eigen::Vector3d(rec->rest_vector[0], rec->rest_vector[1], rec->rest_vector[2]);
      rest.rest_relative_rotation = to_quaternion(rec->rest_rotation);

      const auto stiffness = bond_set_.stiffness(radius[i], radius[j], rest.rest_length());
      hsrod::BeamBondDamping damping;
      if (bond_set_.damping_ratio > 0.0) {
        const double reduced_mass = rmass[i] * rmass[j] / (rmass[i] + rmass[j]);
        const double inertia_i = 0.4 * rmass[i] * radius[i] * radius[i];
        const double inertia_j = 0.4 * rmass[j] * radius[j] * radius[j];
        const double reduced_inertia = inertia_i * inertia_j / (inertia_i + inertia_j);
        damping = hsrod::BeamBondDamping::critical_fraction(bond_set_.damping_ratio, stiffness, reduced_mass, reduced_inertia);
      }
      const auto loads = hsrod::evaluate_beam_bond(si, sj, rest, stiffness, damping);
      if (integrated_implicitly_) continue;  // setup only records rest states

      for (int a = 0; a < 3; a++) {
        f[i][a] -= loads.force_on_j[a];
        torque[i][a] += loads.torque_on_i[a];
      }
      // With newton_bond the bond is stored once and j (possibly a ghost,
      // summed back by reverse communication) gets its share here;
      // otherwise j evaluates its own copy of the bond.
      if (newton_bond) {
        for (int a = 0; a < 3; a++) {
          f[j][a] += loads.force_on_j[a];
          torque[j][a] += loads.torque_on_j[a];
        }
        elastic_energy_ += loads.elastic_energy;
      } else {
        elastic_energy_ += 0.5 * loads.elastic_energy;
      }
      max_strain_ = std::max(max_strain_, std::fabs(loads.axial_strain));
    }
  }
}

void FixRodBonds::refresh_implicit_bond_state() {
  if (!implicit_state_pending_ || !integrated_implicitly_ || !implicit_bond_state_) return;
  implicit_bond_state_(elastic_energy_, max_strain_);
  implicit_state_pending_ = false;
}

double FixRodBonds::compute_scalar() {
  refresh_implicit_bond_state();
  double total = 0.0;
  MPI_Allreduce(&elastic_energy_, &total, 1, MPI_DOUBLE, MPI_SUM, world);
  return total;
}

double FixRodBonds::compute_vector(int n) {
  if (n == 0) return compute_scalar();
  if (n == 1) {
    refresh_implicit_bond_state();
    double largest = 0.0;
    MPI_Allreduce(&max_strain_, &largest, 1, MPI_DOUBLE, MPI_MAX, world);
    return largest;
  }
  return explicit_bond_limit();  // with the bond damping (computed now if init() skipped it)
}


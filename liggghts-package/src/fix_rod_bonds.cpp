/* ----------------------------------------------------------------------
   hsrod - fix rod/bonds (see fix_rod_bonds.h)
------------------------------------------------------------------------- */

#include "fix_rod_bonds.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "keyword_parsing.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "neighbor.h"
#include "update.h"

#include "rod_gather.h"

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

Eigen::Quaterniond to_quaternion(const double *q) { return Eigen::Quaterniond(q[0], q[1], q[2], q[3]); }

void store_quaternion(const Eigen::Quaterniond &q, double *out) {
  out[0] = q.w();
  out[1] = q.x();
  out[2] = q.y();
  out[3] = q.z();
}



}  // namespace

/* ---------------------------------------------------------------------- */

FixRodBonds::FixRodBonds(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg),
      youngs_modulus_(-1.0),
      poisson_ratio_(0.3),
      damping_ratio_(0.0),
      bond_radius_ratio_(1.0),
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
      youngs_modulus_ = parse_number(error, "fix rod/bonds", key, val);
      have_modulus = true;
    } else if (strcmp(key, "poisson_ratio") == 0) {
      poisson_ratio_ = parse_number(error, "fix rod/bonds", key, val);
    } else if (strcmp(key, "damping") == 0) {
      damping_ratio_ = parse_number(error, "fix rod/bonds", key, val);
    } else if (strcmp(key, "bond_radius_ratio") == 0) {
      bond_radius_ratio_ = parse_number(error, "fix rod/bonds", key, val);
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
  if (!(youngs_modulus_ > 0.0)) error->all(FLERR, "fix rod/bonds: youngs_modulus must be > 0 Pa");
  if (!(poisson_ratio_ >= 0.0 && poisson_ratio_ < 0.5))
    error->all(FLERR, "fix rod/bonds: poisson_ratio must be in [0, 0.5)");
  if (!(damping_ratio_ >= 0.0 && damping_ratio_ <= 1.0))
    error->all(FLERR, "fix rod/bonds: damping (fraction of critical damping) must be in [0, 1]");
  if (!(bond_radius_ratio_ > 0.0 && bond_radius_ratio_ <= 1.0))
    error->all(FLERR, "fix rod/bonds: bond_radius_ratio must be in (0, 1]");
  if (atom->bond_per_atom > max_bonds_per_sphere) {
    char msg[256];
    std::snprintf(msg, sizeof(msg), "fix rod/bonds supports at most %d bonds per sphere (data has %d)",
                  max_bonds_per_sphere, atom->bond_per_atom);
    error->all(FLERR, msg);
  }

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
  if (damping_ratio_ > 0.0 && !comm->ghost_velocity)
    error->all(FLERR, "fix rod/bonds: damping > 0 needs ghost velocities: add 'communicate single vel yes'");
  compute_stability_limits();
}

void FixRodBonds::compute_stability_limits() {
  // The stiffest, lightest sphere of the group bounds the explicit step.
  double dmin = 1e300, mass_min = 1e300;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    dmin = std::min(dmin, 2.0 * atom->radius[i]);
    mass_min = std::min(mass_min, atom->rmass[i]);
  }
  double local[2] = {dmin, mass_min}, global[2];
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MIN, world);
  if (global[0] > 1e299) {
    explicit_limit_ = 0.0;
    return;
  }
  const double d = global[0];
  const double pi = 3.14159265358979323846;
  const double density = global[1] / (pi * d * d * d / 6.0);

  // The limits depend only on the spheres and the material: computed once
  // and reused by later runs (the damped limit takes an eigen-bisection).
  if (!(d == limits_diameter_ && density == limits_density_)) {
    hsrod::RodSpec chain;
    chain.number_of_sections = 20;  // omega_max of a chain has converged by 20 spheres
    chain.sphere_diameter = d;
    hsrod::BeamBondMaterial bond{youngs_modulus_, poisson_ratio_, bond_radius_ratio_ * d, damping_ratio_};
    limits_ = hsrod::compute_stability_limits(hsrod::make_rod_layout(chain),
                                              {d, density, youngs_modulus_, poisson_ratio_}, bond, 0.0);
    limits_diameter_ = d;
    limits_density_ = density;
  }
  const hsrod::RodStabilityLimits &limits = limits_;
  explicit_limit_ = limits.explicit_bond_limit;  // includes the bond damping

  if (comm->me == 0 && !limits_printed_) {
    const std::string table = limits.table(update->dt);
    char head[256];
    std::snprintf(head, sizeof(head),
                  "fix rod/bonds %s: stability limits for d = %g m, rho = %g kg/m3, E = %g Pa "
                  "(timestep %g s, explicit limit with damping %g s)\n",
                  id, d, density, youngs_modulus_, update->dt, explicit_limit_);
    if (screen) fprintf(screen, "%s%s", head, table.c_str());
    if (logfile) fprintf(logfile, "%s%s", head, table.c_str());
    limits_printed_ = true;
  }
  const bool first_report = !limits_reported_;
  limits_reported_ = true;
  if (integrated_implicitly_) {
    if (first_report && comm->me == 0 && screen)
      fprintf(screen, "fix rod/bonds %s: bonds integrated implicitly (fix rod/implicit): the explicit limits above do "
                      "not bind this run\n", id);
    return;
  }
  if (update->dt > 0.2 * limits.rayleigh_time && comm->me == 0 && first_report) {
    char msg[256];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/bonds: timestep %g s exceeds 20%% of the Rayleigh time %g s; Hertz contacts "
                  "may be inaccurate", update->dt, limits.rayleigh_time);
    error->warning(FLERR, msg);
  }
  if (timestep_check_ && update->dt > explicit_limit_) {
    char msg[512];
    std::snprintf(msg, sizeof(msg),
                  "fix rod/bonds: timestep %g s exceeds the explicit stability limit %g s of the rod's "
                  "bonds (2/omega_max, E = %g Pa, d = %g m); reduce the timestep or set "
                  "'timestep_check no' to run anyway", update->dt, explicit_limit_, youngs_modulus_, d);
    error->all(FLERR, msg);
  }
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
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int m = 0; m < atom->num_bond[i]; m++) {
      const int partner_tag = atom->bond_atom[i][m];
      int j = atom->map(partner_tag);
      if (j < 0) {
        char msg[256];
        std::snprintf(msg, sizeof(msg),
                      "fix rod/bonds: bond partner %d of atom %d missing on this proc; ghost atoms must "
                      "reach one bond length: use 'communicate single cutoff <bond length + skin> vel yes'",
                      partner_tag, atom->tag[i]);
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

      const double bond_diameter = 2.0 * bond_radius_ratio_ * std::min(radius[i], radius[j]);
      hsrod::BeamBondMaterial material{youngs_modulus_, poisson_ratio_, bond_diameter, damping_ratio_};
      const auto stiffness = hsrod::BeamBondStiffness::from_material(material, rest.rest_length());
      hsrod::BeamBondDamping damping;
      if (damping_ratio_ > 0.0) {
        const double reduced_mass = rmass[i] * rmass[j] / (rmass[i] + rmass[j]);
        const double inertia_i = 0.4 * rmass[i] * radius[i] * radius[i];
        const double inertia_j = 0.4 * rmass[j] * radius[j] * radius[j];
        const double reduced_inertia = inertia_i * inertia_j / (inertia_i + inertia_j);
        damping = hsrod::BeamBondDamping::critical_fraction(damping_ratio_, stiffness, reduced_mass, reduced_inertia);
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

Eigen::Quaterniond FixRodBonds::orientation(int i) const { return to_quaternion(orientation_[i]); }

void FixRodBonds::set_orientation(int i, const Eigen::Quaterniond &q) { store_quaternion(q.normalized(), orientation_[i]); }

std::vector<GatheredBond> FixRodBonds::rest_states(int i) {
  std::vector<GatheredBond> out;
  BondRestRecord *rec = records(i);
  for (int r = 0; r < max_bonds_per_sphere; r++) {
    if (rec[r].partner_tag == 0.0) continue;
    // Only bonds that are still in the topology.
    bool present = false;
    for (int m = 0; m < atom->num_bond[i]; m++)
      if (atom->bond_atom[i][m] == static_cast<int>(rec[r].partner_tag)) present = true;
    if (!present) continue;
    out.push_back({static_cast<int>(rec[r].partner_tag),
                   Eigen::Vector3d(rec[r].rest_vector[0], rec[r].rest_vector[1], rec[r].rest_vector[2]),
                   to_quaternion(rec[r].rest_rotation)});
  }
  return out;
}

double FixRodBonds::compute_scalar() {
  double total = 0.0;
  MPI_Allreduce(&elastic_energy_, &total, 1, MPI_DOUBLE, MPI_SUM, world);
  return total;
}

double FixRodBonds::compute_vector(int n) {
  if (n == 0) return compute_scalar();
  if (n == 1) {
    double largest = 0.0;
    MPI_Allreduce(&max_strain_, &largest, 1, MPI_DOUBLE, MPI_MAX, world);
    return largest;
  }
  return explicit_limit_;
}

/* ---------------------------------------------------------------------- per-atom data */

void FixRodBonds::reset_atom(int i) {
  store_quaternion(Eigen::Quaterniond::Identity(), orientation_[i]);
  for (int a = 0; a < max_bonds_per_sphere * record_doubles; a++) bond_rest_[i][a] = 0.0;
}

void FixRodBonds::grow_arrays(int nmax) {
  memory->grow(orientation_, nmax, 4, "rod/bonds:orientation");
  memory->grow(bond_rest_, nmax, max_bonds_per_sphere * record_doubles, "rod/bonds:bond_rest");
}

void FixRodBonds::copy_arrays(int i, int j, int) {
  std::memcpy(orientation_[j], orientation_[i], 4 * sizeof(double));
  std::memcpy(bond_rest_[j], bond_rest_[i], max_bonds_per_sphere * record_doubles * sizeof(double));
}

void FixRodBonds::set_arrays(int i) { reset_atom(i); }

int FixRodBonds::pack_exchange(int i, double *buf) {
  std::memcpy(buf, orientation_[i], 4 * sizeof(double));
  std::memcpy(buf + 4, bond_rest_[i], max_bonds_per_sphere * record_doubles * sizeof(double));
  return peratom_doubles;
}

int FixRodBonds::unpack_exchange(int nlocal, double *buf) {
  std::memcpy(orientation_[nlocal], buf, 4 * sizeof(double));
  std::memcpy(bond_rest_[nlocal], buf + 4, max_bonds_per_sphere * record_doubles * sizeof(double));
  return peratom_doubles;
}

int FixRodBonds::pack_restart(int i, double *buf) {
  buf[0] = peratom_doubles + 1;
  pack_exchange(i, buf + 1);
  return peratom_doubles + 1;
}

void FixRodBonds::unpack_restart(int nlocal, int nth) {
  double **extra = atom->extra;
  // Skip the data of the fixes stored before this one.
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  unpack_exchange(nlocal, &extra[nlocal][m]);
}

int FixRodBonds::size_restart(int) { return peratom_doubles + 1; }

int FixRodBonds::maxsize_restart() { return peratom_doubles + 1; }

int FixRodBonds::pack_comm(int n, int *list, double *buf, int, int *) {
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int j = list[k];
    for (int a = 0; a < 4; a++) buf[m++] = orientation_[j][a];
  }
  return 4;  // LIGGGHTS' Comm expects datums per atom, not the total
}

void FixRodBonds::unpack_comm(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int a = 0; a < 4; a++) orientation_[i][a] = buf[m++];
}

double FixRodBonds::memory_usage() { return static_cast<double>(atom->nmax) * peratom_doubles * sizeof(double); }

/* ----------------------------------------------------------------------
   hsrod - flexible rods in Hele-Shaw channels (LIGGGHTS package)

   fix rod/bonds: elastic beam bonds between the spheres of a rod.
   The bond law lives in drag-models/rod/beam_bond.h; this fix gathers the
   bonded pairs from LIGGGHTS' bond topology, keeps each sphere's
   orientation and each bond's rest state as per-atom data (so they migrate
   with the atoms and survive write_restart/read_restart), and scatters the
   bond forces and torques. It hands out the rod's bond set (E, nu, bond
   thickness -> stiffness, rod/rod_bond_set.h) and, through RodBondRecords,
   the per-atom orientations and rest states a rod gather needs.
   Per-atom storage in fix_rod_bonds_storage.cpp.
   Doc: liggghts-package/doc/fix_rod_bonds.txt
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

FixStyle(rod/bonds,FixRodBonds)

#else

#ifndef LMP_FIX_ROD_BONDS_H
#define LMP_FIX_ROD_BONDS_H

#include "fix.h"

#include "rod_bond_records.h"

#include "rod/rod_bond_set.h"
#include "rod/stability_limits.h"

#include <Eigen/Geometry>

#include <functional>
#include <vector>

namespace LAMMPS_NS {

class FixRodBonds : public Fix, public RodBondRecords {
 public:
  FixRodBonds(class LAMMPS *, int, char **);
  ~FixRodBonds();
  int setmask();
  void init();
  void setup(int);
  void post_integrate();
  void post_force(int);
  double compute_scalar();
  double compute_vector(int);

  void grow_arrays(int);
  void copy_arrays(int, int, int);
  void set_arrays(int);
  int pack_exchange(int, double *);
  int unpack_exchange(int, double *);
  int pack_restart(int, double *);
  void unpack_restart(int, int);
  int size_restart(int);
  int maxsize_restart();
  int pack_comm(int, int *, double *, int, int *);
  void unpack_comm(int, int, double *);
  double memory_usage();

  // Largest number of bonds one sphere can store a rest state for.
  static const int max_bonds_per_sphere = 8;

  // Explicit stability limit of the rod's bonds [s], bond damping included
  // (computed in init(); when a fix rod/implicit integrates the bonds, init()
  // skips the damping's costly reduction and it is computed here on demand).
  double explicit_bond_limit();
  // The limit as init() left it: without the damping's reduction (2/omega_max)
  // when the bonds are integrated implicitly [s]; bond_limit_damped() says which.
  double explicit_bond_limit_known() const { return explicit_limit_; }
  bool bond_limit_damped() const { return limits_.damping_included; }

  // The rod's bonds as one material: the one place where E, nu and the
  // bond thickness become stiffness (rod/rod_bond_set.h).
  const hsrod::RodBondSet &bond_set() const { return bond_set_; }
  // RodBondRecords: per local atom i, for rod gathers.
  Eigen::Quaterniond orientation(int i) const override;
  void rest_states(int i, std::vector<GatheredBond> &out) const override;

  // Under a fix rod/implicit that names this fix (looked up at init(),
  // implicit_partners.h) this fix neither moves orientations nor adds bond
  // loads; the integrator writes the new orientations back (set_orientation)
  // and reports the bonds' state (set_implicit_bond_state).
  // Under fix rod/implicit the bonds are evaluated by the integrator, which
  // provides what f_ID shows: this processor's share of the elastic energy
  // [J] and the largest |axial strain| [-] after its last step. It is asked
  // only when f_ID is read (thermo, fix print), not every step: a bond pass
  // over every rod costs ~5 % of a step. The integrator marks each step.
  using ImplicitBondState = std::function<void(double &elastic_energy, double &max_strain)>;
  void set_implicit_bond_state(ImplicitBondState evaluate) { implicit_bond_state_ = std::move(evaluate); }
  void implicit_step_taken() { implicit_state_pending_ = true; }
  void set_orientation(int i, const Eigen::Quaterniond &q);

 private:
  // Rest state of one bond as stored per atom: 8 doubles, see beam_bond.h.
  struct BondRestRecord {
    double partner_tag;        // 0 = unused slot
    double rest_vector[3];     // x_j - x_i at rest, in i's body frame [m]
    double rest_rotation[4];   // q_i^-1 q_j at rest (w, x, y, z)
  };
  static const int record_doubles = sizeof(BondRestRecord) / sizeof(double);
  static const int peratom_doubles = 4 + max_bonds_per_sphere * record_doubles;

  ImplicitBondState implicit_bond_state_;
  bool implicit_state_pending_ = false;  // a step was taken since the bond state was last evaluated
  void refresh_implicit_bond_state();
  hsrod::RodBondSet bond_set_; // E [Pa], nu [-], damping (fraction of critical) [-], bond diameter / sphere diameter [-]
  bool timestep_check_;        // refuse a timestep above the explicit limit
  bool exclude_pairs_;         // keep the rod out of its own pair contacts

  double **orientation_;       // per atom: body -> lab quaternion (w, x, y, z)
  double **bond_rest_;         // per atom: max_bonds_per_sphere BondRestRecord
  double elastic_energy_;      // [J], this proc, last evaluation
  double max_strain_;          // largest |axial strain| [-], this proc
  double explicit_limit_;      // [s]
  bool limits_printed_;
  bool integrated_implicitly_;
  bool limits_reported_;       // warnings given once per fix, not per run
  hsrod::RodStabilityLimits limits_;  // cached for the spheres below
  double limits_diameter_;     // [m]
  double limits_density_;      // [kg/m3]

  BondRestRecord *records(int i) { return reinterpret_cast<BondRestRecord *>(bond_rest_[i]); }
  const BondRestRecord *records(int i) const { return reinterpret_cast<const BondRestRecord *>(bond_rest_[i]); }
  BondRestRecord *find_or_create_record(int i, int j, int partner_tag);
  void reset_atom(int i);
  void compute_stability_limits();
  // limits_ for spheres of diameter d [m] and density rho [kg/m3], with the
  // damping's reduction if `damped` (cached: recomputed only when needed).
  void ensure_limits(double d, double density, bool damped);
  void compute_bonds();
  void parse_keywords(int narg, char **arg);
};

}  // namespace LAMMPS_NS

#endif
#endif

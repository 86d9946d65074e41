/* ----------------------------------------------------------------------
   hsrod - fix hele_shaw/drag: confined hydrodynamic forces on rods in a
   Hele-Shaw channel or pore constriction (the reduced model).
   A thin adapter: it parses its keywords into a scene and a model spec,
   builds the facade hsrod::RodHydrodynamics (drag-models/hydro/
   rod_hydrodynamics.h, which owns geometry, background flow, model and
   `auto` policy), gathers each rod, asks the facade for its loads and
   scatters forces and torques. Doc: doc/fix_hele_shaw_drag.txt
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

FixStyle(hele_shaw/drag,FixHeleShawDrag)

#else

#ifndef LMP_FIX_HELE_SHAW_DRAG_H
#define LMP_FIX_HELE_SHAW_DRAG_H

#include "fix.h"

#include <Eigen/Core>

#include <memory>

namespace hsrod {
class BackgroundFlow;
class RodHydrodynamics;
struct SceneSpec;
struct ModelSpec;
}  // namespace hsrod

namespace LAMMPS_NS {

class FixHeleShawDrag : public Fix {
 public:
  FixHeleShawDrag(class LAMMPS *, int, char **);
  ~FixHeleShawDrag();
  int setmask();
  void init();
  void setup(int);
  void post_force(int);
  double compute_vector(int);
  double memory_usage();
  void grow_arrays(int);
  void copy_arrays(int, int, int);
  int pack_exchange(int, double *);
  int unpack_exchange(int, double *);
  void write_restart(FILE *);
  void restart(char *);

  // The scene's hydrodynamics (geometry, background flow, model, per-rod
  // state); other styles find this fix by ID and use it. The model exists
  // after this fix's init().
  hsrod::RodHydrodynamics &hydrodynamics() { return *hydro_; }
  const hsrod::RodHydrodynamics &hydrodynamics() const { return *hydro_; }
  const hsrod::BackgroundFlow &flow() const;
  double explicit_drag_limit() const { return explicit_limit_; }  // 2 m / zeta_max [s], from setup

  // Under a fix rod/implicit that names this fix (looked up at init(),
  // implicit_partners.h) the drag is applied inside the implicit step: this
  // fix then adds no force and reports the loads the integrator stores.
  bool applied_by_integrator() const { return applied_by_integrator_; }
  // Stores the load on local atom i for output: driving force and total
  // hydrodynamic force [N] (friction = total - driving = -(R v)), torque [N m].
  void store_loads(int i, const Eigen::Vector3d &driving, const Eigen::Vector3d &total, const Eigen::Vector3d &torque);

  // Columns of the per-atom array (0-based; f_ID[c+1] in scripts).
  enum LoadColumn { TOTAL_X = 0, DRIVING_X = 3, FRICTION_X = 6, TORQUE_X = 9, N_LOAD_COLUMNS = 12 };

 private:
  // fix_hele_shaw_drag_checks.cpp: the scene and the spheres checked before any work.
  void check_confinement_before_solve(const hsrod::SceneSpec &scene, const hsrod::ModelSpec &model);
  void check_placement();
  void warn_pillar_resolution(const hsrod::SceneSpec &scene);
  bool midplane_warned_ = false;  // rods off the gap mid-plane are warned about once
  std::unique_ptr<hsrod::RodHydrodynamics> hydro_;
  bool applied_by_integrator_;
  double **hydro_force_;          // per atom, last load: total, driving, friction [N], torque [N m] (LoadColumn)
  double total_force_[3];         // on the group [N]
  int force_flag_;
  bigint force_step_;             // step at which total_force_ was summed (implicit mode)
  bool timestep_check_;           // explicit mode: refuse dt above the drag limit
  bool placement_check_;          // refuse spheres outside the fluid / in the gap walls at init
  double explicit_limit_;         // 2 m / zeta_max [s]
  bool limit_reported_;           // the limit is printed once, not per run

  // fix_hele_shaw_drag_keywords.cpp: the keywords into the facade's specs.
  void parse_keywords(int narg, char **arg, hsrod::SceneSpec &scene, hsrod::ModelSpec &model);
  void choose_model();
  void check_explicit_limit();
  void report(const char *line);  // to screen and log file on rank 0
};

}  // namespace LAMMPS_NS

#endif
#endif

/* ----------------------------------------------------------------------
   hsrod - fix hele_shaw/drag: confined hydrodynamic forces on rods in a
   Hele-Shaw channel or pore constriction (the reduced model).
   Physics in drag-models/ (geometry, flow, hydro); this fix builds the
   scene from its keywords, gathers each rod, evaluates the selected model
   and scatters forces and torques. Doc: doc/fix_hele_shaw_drag.txt
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

FixStyle(hele_shaw/drag,FixHeleShawDrag)

#else

#ifndef LMP_FIX_HELE_SHAW_DRAG_H
#define LMP_FIX_HELE_SHAW_DRAG_H

#include "fix.h"

#include "hydro/twoway_window_options.h"

#include <memory>
#include <string>

namespace hsrod {
class BackgroundFlow;
class ChannelGeometry;
class HydrodynamicModel;
struct RodGeometry;
struct RodDrag;
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

  // For fix rod/implicit, which applies the drag inside its implicit step.
  void set_applied_by_integrator(bool flag) { applied_by_integrator_ = flag; }
  const hsrod::ChannelGeometry &geometry() const { return *geometry_; }
  const hsrod::BackgroundFlow &flow() const { return *flow_; }
  const hsrod::HydrodynamicModel &model() const { return *model_; }
  double gap_bottom() const { return gap_bottom_; }    // z of the lower gap wall [m]
  int section_size() const { return section_size_; }
  double explicit_drag_limit() const { return explicit_limit_; }  // 2 m / zeta_max [s]
  // Stores the hydrodynamic force on local atom i for output.
  void store_force(int i, const double *force);

 private:
  std::unique_ptr<hsrod::ChannelGeometry> geometry_;
  std::unique_ptr<hsrod::BackgroundFlow> flow_;
  std::unique_ptr<hsrod::HydrodynamicModel> model_;
  std::string model_name_;        // as asked ("auto" resolved in init)
  double viscosity_;              // mu [Pa s]
  double fluid_density_;          // rho_f [kg/m3]
  double gap_bottom_;             // z of the lower gap wall [m]
  double tolerance_;              // auto: accepted relative deflection error [-]
  std::string coefficients_file_; // "" = built-in defaults
  hsrod::TwoWayWindowOptions window_;  // level 4 (twoway) window settings
  int section_size_;              // spheres per rod cross-section
  bool applied_by_integrator_;
  double **hydro_force_;          // per atom: last hydrodynamic force [N]
  double total_force_[3];         // on the group [N]
  int force_flag_;
  bool timestep_check_;           // explicit mode: refuse dt above the drag limit
  double explicit_limit_;         // 2 m / zeta_max [s]
  bool limit_reported_;           // the limit is printed once, not per run

  void build_model(double sphere_diameter);
  std::string choose_auto_level(double sphere_diameter);
  void check_explicit_limit();
};

}  // namespace LAMMPS_NS

#endif
#endif

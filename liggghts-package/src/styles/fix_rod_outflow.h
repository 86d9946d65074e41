/* ----------------------------------------------------------------------
   hsrod - fix rod/outflow: outflow removal of whole rods. A rod (molecule)
   of the group whose sphere centres are all at x >= x_out is deleted, its
   atoms and bonds together, so a suspension can stream through a channel
   for long times without piling up at the outlet face. Fixes that keep
   state per rod are told first (support/rod_removal.h): fix rod/implicit
   drops its records, fix rod/outcome keeps the outcome it recorded.
   Doc: doc/fix_rod_outflow.txt
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

FixStyle(rod/outflow,FixRodOutflow)

#else

#ifndef LMP_FIX_ROD_OUTFLOW_H
#define LMP_FIX_ROD_OUTFLOW_H

#include "fix.h"

#include <vector>

namespace LAMMPS_NS {

class FixRodOutflow : public Fix {
 public:
  FixRodOutflow(class LAMMPS *, int, char **);
  int setmask();
  void init();
  void setup_pre_exchange();
  void pre_exchange();
  void end_of_step();
  void post_run();
  double compute_vector(int);
  void write_restart(FILE *);
  void restart(char *);

 private:
  double outlet_x_;             // the removal plane x = x_out [m]
  long rods_removed_;           // since the fix was defined
  long spheres_removed_;        // since the fix was defined
  long rods_removed_at_setup_;  // at the current run's start (post_run's report)
  // Rods of the group with every sphere centre at x >= outlet_x_, sorted,
  // the same on every processor (collective).
  std::vector<int> rods_past_outlet();
  // Deletes the rods' atoms on every processor (collective) after telling
  // the fixes that keep per-rod state.
  void remove_rods(const std::vector<int> &molecules);
};

}  // namespace LAMMPS_NS

#endif
#endif

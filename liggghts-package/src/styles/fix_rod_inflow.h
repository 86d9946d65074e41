/* ----------------------------------------------------------------------
   hsrod - fix rod/inflow: inflow seeding. Every N steps, `count` straight
   rods of the create_rods kind are placed at random in an entrance band
   x in [x0, x1] of the planform, clear of every atom in the box (an
   attempt with no free place is skipped and counted), or as many as keep
   a number concentration in the band. Placement:
   drag-models/geometry/rod_seeding.h; the rods are made as create_rod
   makes them. Doc: doc/fix_rod_inflow.txt
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

FixStyle(rod/inflow,FixRodInflow)

#else

#ifndef LMP_FIX_ROD_INFLOW_H
#define LMP_FIX_ROD_INFLOW_H

#include "fix.h"

#include "create_rods.h"

namespace LAMMPS_NS {

class FixRodInflow : public Fix {
 public:
  FixRodInflow(class LAMMPS *, int, char **);
  int setmask();
  void init();
  void setup(int);
  void pre_exchange();
  void pre_neighbor();
  double compute_vector(int);
  void write_restart(FILE *);
  void restart(char *);

 private:
  SeededRodsSpec spec_;             // the rods and the entrance band (spec_.seeding.x_min, x_max [m])
  int rods_per_insertion_;          // rods placed at each insertion step [-] (count)
  double concentration_;            // else: rods per m^2 of the band's fluid kept in it (< 0: count mode)
  int band_target_;                 // the rods that make that concentration in the band [-]
  int rods_in_band_;                // rods with their centre in the band after the last insertion [-]
  class FixHeleShawDrag *drag_;
  long rods_inserted_;              // since the fix was defined
  long rods_refused_;               // attempts that found no free place
  long attempts_;                   // every attempt so far: its seeding sequence
  int next_tag_, next_mol_;         // IDs never reused, also after rods were removed
  bool rest_states_pending_;        // new rods' bonds get their rest states once ghosts exist
  void insert();
  int rods_in_band();  // rods of the group whose centre lies in the band (collective)
};

}  // namespace LAMMPS_NS

#endif
#endif

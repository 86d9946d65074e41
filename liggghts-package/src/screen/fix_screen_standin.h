// hsrod screening: stand-ins for the resolved-coupling fixes of an
// unchanged CFD-DEM script (doc: liggghts-package/doc/hsrod_screen.txt).
// In screening mode these classes are registered under the names
//   couple/cfd                 -> FixScreenCoupling: records couple_every and,
//                                 right after its creation, adds the reduced
//                                 model (fix hele_shaw/drag + fix rod/implicit)
//   couple/cfd/force, couple/cfd/force/implicit, couple/cfd/torque/implicit
//                              -> FixScreenInert: the drag is the reduced model's
//   nve/sphere                 -> FixScreenInert: fix rod/implicit integrates
//   wall/gran                  -> FixScreenWall: records the primitive (the
//                                 reduced model's walls are implicit contacts)
// so the script's own lines run unchanged. No stand-in does anything in a run.
#pragma once

#include "fix.h"

namespace LAMMPS_NS {

class FixScreenInert : public Fix {
 public:
  FixScreenInert(class LAMMPS *, int, char **);
  int setmask() override { return 0; }
};

class FixScreenWall : public Fix {
 public:
  FixScreenWall(class LAMMPS *, int, char **);
  int setmask() override { return 0; }
};

class FixScreenCoupling : public Fix {
 public:
  FixScreenCoupling(class LAMMPS *, int, char **);
  int setmask() override { return 0; }
  void post_create() override;

 private:
  void add_fix_line(const char *line);
};

}  // namespace LAMMPS_NS

/* ----------------------------------------------------------------------
   hsrod - fix rod/outcome: classifies each rod of the group as passed
   without wall contact, passed with contact, or clogged (criteria and
   hysteresis in drag-models/rod/rod_outcome.h), records the time and
   position of first wall contact, and tells the script when every rod is
   decided so that a chunked run can stop. Several rods: a rod resting
   against a trapped rod is clogged too, "held by rod k"
   (drag-models/rod/rod_outcome_set.h).
   Doc: doc/fix_rod_outcome.txt
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

FixStyle(rod/outcome,FixRodOutcome)

#else

#ifndef LMP_FIX_ROD_OUTCOME_H
#define LMP_FIX_ROD_OUTCOME_H

#include "fix.h"

#include "rod/rod_outcome_set.h"

#include <memory>
#include <set>

namespace LAMMPS_NS {

class FixRodOutcome : public Fix {
 public:
  FixRodOutcome(class LAMMPS *, int, char **);
  int setmask();
  void init();
  void setup(int);
  void end_of_step();
  double compute_vector(int);
  double pass_x() const { return criteria_.pass_x; }  // a rod has passed once its centre is past it [m]

 private:
  void sample();
  class FixHeleShawDrag *drag_;
  hsrod::RodOutcomeCriteria criteria_;
  bool pass_x_given_, averaging_given_, clog_given_;
  std::unique_ptr<hsrod::RodOutcomeSet> rods_;  // per molecule ID, identical on every proc
  std::set<int> reported_;                      // rods whose decision was printed
  // Pairs of rods (molecule IDs) whose spheres overlap now, from all procs.
  std::vector<std::pair<int, int>> touching_rods();
  void report_decision(int mol, const hsrod::RodOutcomeTracker &tracker);
  bool all_decided_;
  bool criteria_reported_ = false;
};

}  // namespace LAMMPS_NS

#endif
#endif

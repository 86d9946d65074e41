// Where the time of an implicit rod run went: the
// per-step and per-sphere-step wall time of fix rod/implicit, split into
// the drag model's evaluation, the bond loads and Jacobians, the wall and
// self-contacts, the linear solve (assembly, factorisation, update) and the
// rest (gathering the rods, the accuracy guard's checks and copies,
// scattering the results).
#pragma once

#include "dynamics/overdamped_rod_step.h"

#include <string>

namespace hsrod {

struct StepCost {
  long steps = 0;               // time steps of the run
  long sphere_steps = 0;        // sum over steps of the spheres advanced
  double total_seconds = 0.0;   // wall time inside the integrator [s]
  double drag_seconds = 0.0;    // drag model evaluations (including at substeps) [s]
  OverdampedSolverStatistics solver;  // the solvers' own split, summed over rods (substeps included)

  // The rest: total minus drag, bonds, contacts and solve [s] (>= 0).
  double other_seconds() const;
  // One line: "N steps, X us per step, Y us per sphere-step: drag model a %, bonds b %, ...".
  std::string report() const;
};

// Adds b's counters and times to a.
void accumulate(OverdampedSolverStatistics& a, const OverdampedSolverStatistics& b);
// a - b, counter by counter (statistics of a run from totals before and after it).
OverdampedSolverStatistics difference(const OverdampedSolverStatistics& a, const OverdampedSolverStatistics& b);

}  // namespace hsrod

// The paper's pore passage (Braesel et al. 2024, Table 1 lower half: pore
// constriction L = 600 um, W = 200 um, R = 85 um, H = 20 um, Re = 2; a rod of
// 10 spheres of 3 um at alpha = 10 deg, centre (150, 100, 10) um) driven
// directly through drag-models: the hydrodynamic model of a level, the kept
// OverdampedRodSolver, Hertz walls and self-contact, as fix rod/implicit
// does it, without LIGGGHTS. Shared by the integrator-regression test and
// the program that recorded its reference trajectories.
#pragma once

#include "dynamics/guarded_step.h"

#include <string>
#include <vector>

namespace hsrod_test {

struct PassageSample {
  int step = 0;
  double x_centre = 0.0;   // centre-of-mass x [m]
  double angle_deg = 0.0;  // eq. (1) [deg]
  double lateral = 0.0;    // (y_com - W/2) / W [-]
};

struct PassageCase {
  std::string model;             // "isotropic", "local", "nonlocal", "twoway"
  double youngs_modulus = 15e6;  // E of rod and walls [Pa]
  double dt = 4e-6;              // [s]
  int steps = 1100;              // 4.4 ms at 4e-6 s: x = 150 um -> ~520 um
  int sample_every = 100;        // steps between samples
  double window_cells = 2.0;     // level 4 only: cells per d (2 keeps the test short)
};

// Samples at step 0, sample_every, ..., steps. `cache_dir`: flow-field cache.
std::vector<PassageSample> run_pore_passage(const PassageCase& c, const std::string& cache_dir);

// Work of a guarded passage: substeps taken and trial substeps rejected
// (each one solve of the rod's system).
struct PassageWork {
  long substeps = 0;
  long rejected_trials = 0;
  long solves() const { return substeps + rejected_trials; }
};

// The same passage through the accuracy guard (guarded_rod_step with
// `limits`, the drag re-evaluated at substeps), as fix rod/implicit takes it:
// each step's velocities are the next step's OverdampedRod::velocities.
std::vector<PassageSample> run_guarded_pore_passage(const PassageCase& c, const hsrod::StepGuardLimits& limits,
                                                    const std::string& cache_dir, PassageWork& work);

}  // namespace hsrod_test

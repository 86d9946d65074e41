// The `auto` policy of the model keyword: the cheapest level whose error
// against the resolved reference, as measured in the cross-check
// (hsrod_crosscheck_levels), stays within a tolerance for this scene.
//
// Error model: the cross-check record (level_error_record(), written by
// hsrod_crosscheck_levels --error-record-cpp from the resolved campaign,
// calibration/data/level_error_record.csv): for each level and each resolved
// rigid straight rod of n touching spheres at beta, the largest relative
// error of its totals (friction and held-in-flow load, along and across the
// axis) and of its force-free velocity. A scene's expected error per level
// is that record interpolated linearly in n and in beta (clamped outside the
// recorded ranges, flagged as extrapolated), the worst over its rods.
//
// Bending: levels 1-2 are local and miss the bending load that the non-local
// coupling adds along a rod held across the flow (the force per sphere on
// the rod held at its start, minus the rod mean, across the rod, from level
// 3) times the compliance L^3 / (48 EI) of a simply supported beam
// (Euler-Bernoulli, mid-span load): the deflection a local level misses, as
// a fraction of the rod length L. A flexible rod whose estimate exceeds the
// deflection tolerance is given a non-local level (3 or 4) only.
//
// Walls and pores: a second record, the worst errors of
// each level against the resolved rows near a side wall and beside a pore
// cylinder (near_wall_error_record(), written by hsrod_crosscheck_scenes
// --wall-record-cpp from calibration/data/level_error_near_walls.csv, levels
// with their near-wall correction, hydro/wall_proximity.h), per geometry,
// beta and surface gap. The scene's gaps: the smallest surface gap of its
// spheres to a side wall now, and, with pore cylinders, the gap a sphere
// keeps passing the narrowest opening on its centre line, (w_min - d) / 2,
// or its gap to a cylinder now if smaller. A level's expected error is the
// larger of the slit record's and the near-wall record's at these gaps
// (linear in the gap between recorded gaps, at the nearest recorded beta;
// clamped below the smallest gap; beyond the largest recorded gap g_f it
// falls linearly to 0 at 2 g_f, an assumption: the record's errors fall with
// the gap and the slit record holds far from walls).
//
// What the records do not cover: bent rods near walls, beta and n outside
// the campaigns, near-wall cases at beta other than 0.15 and 0.3.
// Known limit of the pore gap: it is a sphere's on its own streamline through
// the middle of the opening. A rod tilted across the flow passes its end
// spheres closer (the 4-sphere rod of calibration/validation/pore_passage:
// 1.2-1.9 d at the throat, where 2.5 d is read), so the expected error of
// levels 2-3 is low there. The rod's lateral extent is not used, because a rod
// wider than the opening would then always read gap 0 and get level 4 in every
// clogging scene (measured: ~57x level 2's cost).
#pragma once

#include "hydro/hydrodynamic_model.h"

#include <string>
#include <vector>

namespace hsrod {

// One row of the cross-check record.
struct LevelErrorRow {
  int level;              // 1-4 (hydro/model_registry.h)
  double beta;            // d / H [-]
  int n;                  // spheres of the rigid straight rod
  double force_error;     // largest |model / resolved - 1| of R_par, R_perp, D_par, D_perp [-]
  double velocity_error;  // largest |model / resolved - 1| of lambda_par, lambda_perp [-]
  double r_error;         // |model / resolved - 1| of r = lambda_perp / lambda_par [-]
};

// The built-in record and its provenance (auto_model_choice_record.cpp).
const std::vector<LevelErrorRow>& level_error_record();
const char* level_error_record_provenance();

// One row of the near-wall record.
struct NearWallErrorRow {
  int level;            // 1-4
  bool pore;            // beside a pore cylinder (else a side wall)
  double beta;          // d / H [-]
  double gap_over_d;    // smallest surface gap to the wall / cylinder [d]
  double force_error;   // largest |model / resolved - 1| of the totals [-]
  double profile_rms;   // largest per-sphere profile RMS error [-]
};
const std::vector<NearWallErrorRow>& near_wall_error_record();
const char* near_wall_error_record_provenance();

// Level `level`'s expected error of the totals at surface gap `gap_over_d`
// from a wall (pore = false) or a pore cylinder (see above); 0 when the
// record has no rows for it. `extrapolated` is set when beta is not a
// recorded one or the gap is below the smallest recorded gap.
double expected_near_wall_error(const std::vector<NearWallErrorRow>& record, int level, bool pore, double beta,
                                double gap_over_d, bool& extrapolated);

// The scene's surface gaps [d] that the near-wall record is read at: to the
// side walls (the rods' smallest now) and to pore cylinders (see above;
// +infinity without cylinders).
struct SceneWallGaps {
  double wall = 0.0, pore = 0.0;
};
SceneWallGaps scene_wall_gaps(const std::vector<RodGeometry>& rods, const ChannelGeometry& geometry);

struct ExpectedLevelError {
  bool known = false;         // the record has rows of this level
  bool extrapolated = false;  // beta or n outside the recorded range (clamped)
  double force = 0.0, velocity = 0.0, r = 0.0;  // [-]
  double total() const { return force > velocity ? force : velocity; }
};

// Level `level`'s expected error for a rigid rod of n spheres at beta.
ExpectedLevelError expected_level_error(const std::vector<LevelErrorRow>& record, int level, double beta, int n);

struct AutoModelChoice {
  std::string model;                   // registered name (hydro/model_registry.h)
  double estimated_deflection = 0.0;   // largest deflection a local level misses, over L [-] (0 for rigid spheres)
  bool flexible = false;               // false: no bonds, the spheres are rigid (no bending to miss)
  double expected_error = 0.0;         // the chosen level's expected error (totals, free velocity) [-]
  bool within_tolerance = false;       // expected_error <= the error tolerance
  bool extrapolated = false;           // the scene is outside the record for the chosen level
  std::vector<double> level_errors;    // expected error of levels 1..4 [-] (< 0: not in the record)
  SceneWallGaps wall_gaps;             // the scene's gaps to walls and pore cylinders [d]
  std::vector<double> near_wall_errors;  // the near-wall record's part of level_errors, levels 1..4 [-]
  std::string summary;                 // one line for the log: every level's error, the choice and why
};

// `rods` the scene's rods, `beta` = d / H; `bending_stiffness` EI [N m^2]
// of the rod's bonds, or <= 0 for unbonded (rigid) spheres; `level3` the
// non-local model at the scene's beta (for the bending estimate);
// `deflection_tolerance` the accepted missed deflection over L [-];
// `error_tolerance` the accepted relative error of forces and velocities [-].
AutoModelChoice choose_auto_model(const std::vector<RodGeometry>& rods, const BackgroundFlow& flow, double beta,
                                  const HydrodynamicModel& level3, double bending_stiffness,
                                  double deflection_tolerance, double error_tolerance,
                                  const std::vector<LevelErrorRow>& record = level_error_record(),
                                  const std::vector<NearWallErrorRow>& near_wall = near_wall_error_record());

}  // namespace hsrod

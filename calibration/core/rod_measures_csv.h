// hsrod calibration: the paper's rod measures from a coupled run's spheres,
// written as CSV once per coupling interval.
//
// Plain C++17. The measures are those of compute rod/shape (Braesel et al.
// 2024, Sec. 2.3) with the same conventions; eq. (1) and eq. (2) come from
// drag-models/rod/rod_measures.h (not re-implemented here):
//   angle_deg       eq. (1) from the end sections' centres [deg]
//   deflection      eq. (2), L_Rod = N_sec x mean section distance [-]
//   lateral_over_W  (y_com - y_centre) / W [-]
//   vx_over_U       v_x of the centre of mass / mean inflow U [-]
// A rod = the spheres of one molecule ID (create_rod), ordered by atom ID
// section by section; spheres without a molecule ID form one rod (id 0).
#pragma once

#include <iosfwd>
#include <vector>

#include "sphere_set.h"

namespace hsrod::calib {

struct RodMeasures {
  long rod = 0;              // molecule ID
  int n_spheres = 0;
  Vec3 com{};                // centre of mass (volume-weighted) [m]
  Vec3 vel{};                // velocity of the centre of mass [m/s]
  double angle_deg = 0.0;    // eq. (1) [deg]
  double deflection = 0.0;   // eq. (2) [-]
  double lateral = 0.0;      // (y_com - y_centre)/W [-]
  double vx_over_u = 0.0;    // v_x / U [-] (0 if U not given)
};

struct RodMeasureSettings {
  double channel_width = 0.0;   // W [m]
  double channel_centre = 0.0;  // y of the channel centre line [m]
  double mean_velocity = 0.0;   // U [m/s], 0 = not given
  int section_size = 1;         // spheres per cross-section
};

// Measures of every rod among `spheres` (ordered by molecule ID).
std::vector<RodMeasures> measure_rods(const std::vector<Sphere>& spheres, const RodMeasureSettings& s);

void write_rod_measures_header(std::ostream& os);
void write_rod_measures(std::ostream& os, double t, const std::vector<RodMeasures>& rods);

}  // namespace hsrod::calib

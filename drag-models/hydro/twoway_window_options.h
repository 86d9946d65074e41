// Settings of the level-4 model (hydro/twoway_window_model.h), in a header
// of their own so that adapters can hold them without the solver headers.
#pragma once

namespace hsrod {

struct TwoWayWindowOptions {
  double cells_per_diameter = 4.0;  // lattice spacing h = d / cells_per_diameter [-] (4: footprint = sphere disc)
  // Two scales: the walls' reflection on a window of d / reflection_cells_per_diameter
  // cells, the rest of the mobility from the fine lattice's free-space Green's
  // table (hydro/twoway_window_model.h). 0: min(2, cells_per_diameter); equal to
  // cells_per_diameter: one scale (the whole mobility from one window of the fine lattice).
  double reflection_cells_per_diameter = 0.0;  // [-], in [1, cells_per_diameter]
  double margin = 0.0;              // window reach beyond the rod [m]; 0: auto (see margin_for)
  double fine_margin = 0.0;         // reach of the window's fine zone (cells of size h) [m]; 0: auto (fine_margin_for)
  double grading = 0.0;             // growth ratio of the cells between fine zone and window edge [-], (1, 2];
                                    // 0: 1.2 with one scale, 1.4 with two (the window then carries only the smooth part)
  double update_distance = 0.0;     // re-solve after this sphere displacement [m]; 0: d / 2
  int update_every = 0;             // also re-solve after this many evaluations; 0: never by count
  long max_window_cells = 400000;   // larger windows are refused (std::invalid_argument)
};

}  // namespace hsrod

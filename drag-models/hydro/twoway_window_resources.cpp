// Level 4's bounded work: a window above max_window_cells is refused when it
// is placed; asked before the run, the user gets the figures and the
// keywords that shrink the window instead of a refusal from the first step.
#include "hydro/twoway_window_model.h"

#include <cstdio>

namespace hsrod {

std::string TwoWayWindowModel::resource_problem(const RodGeometry& rod, const BackgroundFlow& flow,
                                                const ResourceLimits& /*limits*/) const {
  const long cells = window_cells_for(rod, flow);
  if (cells <= max_window_cells()) return "";
  char msg[512];
  std::snprintf(msg, sizeof(msg),
                "model twoway: the window of rod %d (%d spheres) would have %ld cells, above the limit of %ld: use a "
                "coarser window_cells (2 to 16), a smaller window_margin or window_fine, or a shorter rod (or model "
                "nonlocal / local)",
                rod.id, rod.size(), cells, max_window_cells());
  return msg;
}

}  // namespace hsrod

#include "flow/make_background_flow.h"

namespace hsrod {

std::unique_ptr<BackgroundFlow> make_background_flow(const ChannelGeometry& geometry,
                                                     const FluidProperties& fluid,
                                                     const Inflow& inflow,
                                                     const BackgroundFlowOptions& options) {
  if (geometry.is_straight() && !options.force_grid)
    return std::make_unique<StraightChannelFlow>(geometry, fluid, inflow);
  return std::make_unique<GridBrinkmanFlow>(geometry, fluid, inflow, options.grid);
}

}  // namespace hsrod

// Picks the cheapest background-flow model that is exact for the scene
// (skip what the scene does not need): the closed-form profile
// for a straight channel (no grid is ever built), the cached grid solver for
// any other planform.
#pragma once

#include "flow/background_flow.h"
#include "flow/grid_brinkman_flow.h"
#include "flow/straight_channel_flow.h"

#include <memory>

namespace hsrod {

struct BackgroundFlowOptions {
  // Use the grid solver even for a straight channel (verification only).
  bool force_grid = false;
  GridBrinkmanOptions grid;
};

std::unique_ptr<BackgroundFlow> make_background_flow(const ChannelGeometry& geometry,
                                                     const FluidProperties& fluid,
                                                     const Inflow& inflow,
                                                     const BackgroundFlowOptions& options = {});

}  // namespace hsrod

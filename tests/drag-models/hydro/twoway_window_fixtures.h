// The scene shared by the level-4 window tests: the pore scene's spheres in a
// wall-free uniform stream, and a level-4 model with a state of its own.
#pragma once

#include "common/math_constants.h"
#include "flow/uniform_flow.h"
#include "hydro/twoway_window_model.h"

#include <memory>
#include <string>

namespace hsrod_test {

constexpr double kMu = 1e-3;   // Pa s
constexpr double kD = 3e-6;    // m, the pore scene's spheres
using hsrod::kPi;

// Uniform gap-averaged stream of 1 mm/s along x in a slit of gap H, with a
// planform large enough to hold any window (no walls).
class UniformSlitStream : public hsrod::UniformFlow {
 public:
  explicit UniformSlitStream(double gap) : UniformFlow(wide_slit(gap, {1e-3, 0.0})) {}
};

// Level 4 at confinement beta = d / H for the pore scene's spheres.
inline std::unique_ptr<hsrod::TwoWayWindowSession> level4(double beta, hsrod::TwoWayWindowOptions options = {}) {
  return std::make_unique<hsrod::TwoWayWindowSession>(hsrod::HydrodynamicParameters{kMu, kD / beta, kD},
                                                      hsrod::ConfinementTable::default_table(), options);
}

}  // namespace hsrod_test

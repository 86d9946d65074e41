// Helpers shared by the background-flow tests.
#pragma once

#include "flow/background_flow.h"
#include "flow/fluid_properties.h"
#include "geometry/channel_geometry.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <initializer_list>
#include <string>

namespace hsrod::test {

// The paper's pore scene, read from pore_scene_braesel2024.txt (source in the file).
struct PaperPoreScene {
  double length, width, pore_radius, gap_height, x_pore;  // m
  FluidProperties fluid;
  double reynolds;  // channel Reynolds number of the paper's definition
  ChannelGeometry geometry() const;
  ChannelGeometry straight_geometry() const;  // same channel without the pore
};
PaperPoreScene load_paper_pore_scene();

// A fresh directory under the system temp dir, removed with its content.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Gap-integrated flow rate Q(x) = H * integral of u_x(x, y) dy [m^3/s]
// (midpoint rule with `samples` points across the channel width).
double flow_rate_through(const BackgroundFlow& flow, double x, int samples = 6000);

// Expects fn() to throw std::invalid_argument whose message contains every
// one of `fragments`.
void expect_invalid_argument(const std::function<void()>& fn,
                             std::initializer_list<const char*> fragments);

}  // namespace hsrod::test

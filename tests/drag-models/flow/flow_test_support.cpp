#include "flow_test_support.h"

#include "geometry/pore_constriction.h"

#include <atomic>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace hsrod::test {

PaperPoreScene load_paper_pore_scene() {
  const std::string file = std::string(HSROD_TEST_DATA_DIR) + "/pore_scene_braesel2024.txt";
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot open " + file);
  std::map<std::string, double> v;
  std::string line;
  while (std::getline(in, line)) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream s(line);
    std::string name;
    double value;
    if (s >> name >> value) v[name] = value;
  }
  PaperPoreScene p;
  p.length = v.at("channel_length_m");
  p.width = v.at("channel_width_m");
  p.pore_radius = v.at("pore_radius_m");
  p.gap_height = v.at("sphere_diameter_m") / v.at("confinement_beta");
  p.x_pore = 0.5 * p.length;
  p.fluid.dynamic_viscosity = v.at("fluid_viscosity_Pa_s");
  p.fluid.density = v.at("fluid_density_kg_m3");
  p.reynolds = v.at("channel_reynolds");
  return p;
}

ChannelGeometry PaperPoreScene::geometry() const {
  return make_pore_constriction(length, width, gap_height, pore_radius, x_pore);
}

ChannelGeometry PaperPoreScene::straight_geometry() const {
  return make_straight_channel(length, width, gap_height);
}

TempDir::TempDir() {
  static std::atomic<int> counter{0};
  path_ = std::filesystem::temp_directory_path() /
          ("hsrod-flow-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

double flow_rate_through(const BackgroundFlow& flow, double x, int samples) {
  const ChannelGeometry& g = flow.geometry();
  const double dy = g.width() / samples;
  double q = 0.0;
  for (int k = 0; k < samples; ++k) q += flow.velocity(x, g.y_lo() + (k + 0.5) * dy).x() * dy;
  return q * g.gap_height();
}

void expect_invalid_argument(const std::function<void()>& fn,
                             std::initializer_list<const char*> fragments) {
  try {
    fn();
    ADD_FAILURE() << "expected std::invalid_argument, nothing was thrown";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    for (const char* f : fragments)
      EXPECT_NE(msg.find(f), std::string::npos) << "message \"" << msg << "\" lacks \"" << f << "\"";
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected std::invalid_argument, got: " << e.what();
  }
}

}  // namespace hsrod::test

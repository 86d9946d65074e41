// hsrod_passage_drift: where the lateral drift of the dynamic pore passage
// (calibration/validation/pore_passage) comes from, level by level.
//
//   hsrod_passage_drift TRAJECTORY.csv [--every N]
//
// TRAJECTORY.csv: a run's samples (t, x_com, y_com, angle_deg, ...; run.py's
// levelK_*.csv or resolved.csv). At every N-th sample the 4-sphere rod of the
// scene (d = 3 um, straight, at the sample's centre and paper angle alpha,
// lab direction -(90 + alpha) deg) is held rigid in the scene's background flow
// (channel 84 x 36 x 10 um, pore cylinders R = 9 um at x = 42 um, mean 0.01 m/s)
// and its free rigid velocity (rigid_rod_load.h) is printed for levels 1-4:
// with the near-wall correction (built-in), without it, and with the
// background flow's lateral component removed (u_y = 0: what the flow's
// convergence and divergence in the pore contribute). Also the sample's own
// lateral velocity dy/dt (finite difference of the trajectory).
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <memory>

#include "flow/make_background_flow.h"
#include "hydro/local_models.h"
#include "hydro/model_registry.h"
#include "hydro/rigid_rod_load.h"
#include "resolved_campaign.h"

namespace {

// The background flow with its lateral component removed.
class AlongOnly : public hsrod::BackgroundFlow {
 public:
  explicit AlongOnly(const hsrod::BackgroundFlow& f) : f_(f) {}
  Eigen::Vector2d velocity(double x, double y) const override { return {f_.velocity(x, y).x(), 0.0}; }
  Eigen::Matrix2d velocity_gradient(double x, double y) const override {
    Eigen::Matrix2d g = f_.velocity_gradient(x, y);
    g.row(1).setZero();
    return g;
  }
  double pressure(double x, double y) const override { return f_.pressure(x, y); }
  double mean_velocity() const override { return f_.mean_velocity(); }
  const hsrod::ChannelGeometry& geometry() const override { return f_.geometry(); }
  std::string description() const override { return "lateral component removed"; }

 private:
  const hsrod::BackgroundFlow& f_;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Free rigid velocity of the pore-passage rod along a trajectory, levels 1-4, with and without parts"};
  std::string path;
  int every = 20;
  app.add_option("trajectory", path)->required()->check(CLI::ExistingFile);
  app.add_option("--every", every, "use every N-th sample");
  CLI11_PARSE(app, argc, argv);
  try {
    const double d = 3e-6, H = 10e-6, U = 0.01, W = 36e-6, kPi = 3.14159265358979323846;
    const hsrod::ChannelGeometry channel(84e-6, W, H, 0.0, 0.0, {{42e-6, 0.0, 9e-6}, {42e-6, W, 9e-6}});
    const auto flow = hsrod::make_background_flow(channel, hsrod::FluidProperties{1e-3, 1000.0},
                                                  hsrod::Inflow::mean_velocity(U));
    const AlongOnly along(*flow);
    const hsrod::HydrodynamicParameters p{1e-3, H, d};
    const auto table = hsrod::ConfinementTable::default_table();
    const auto rows = hsrod::calib::read_csv_rows(path);
    std::printf("# V_y / U of the free rigid rod (with correction | without | u_y = 0); trajectory's dy/dt / U\n");
    std::printf("%7s %6s %9s", "x[um]", "alpha", "traj");
    for (const char* l : {"L1", "L2", "L3", "L4"}) std::printf(" | %-6s %8s %8s %8s", l, "with", "no wall", "u_y=0");
    std::printf("\n");
    for (std::size_t k = every; k + 1 < rows.size(); k += every) {
      const double x = std::stod(rows[k].at("x_com")), y = std::stod(rows[k].at("y_com"));
      const double alpha = std::stod(rows[k].at("angle_deg"));
      const double dydt = (std::stod(rows[k + 1].at("y_com")) - std::stod(rows[k - 1].at("y_com"))) /
                          (std::stod(rows[k + 1].at("t")) - std::stod(rows[k - 1].at("t")));
      const double phi = -(90.0 + alpha) * kPi / 180.0;
      hsrod::RodGeometry rod;
      rod.sphere_diameter = d;
      for (int i = 0; i < 4; ++i)
        rod.positions.emplace_back(x + (i - 1.5) * d * std::cos(phi), y + (i - 1.5) * d * std::sin(phi), 0.5 * H);
      std::printf("%7.2f %6.1f %+9.5f", x * 1e6, alpha, dydt / U);
      for (const char* level : {"isotropic", "local", "nonlocal", "twoway"}) {
        double v[3];
        for (int variant = 0; variant < 3; ++variant) {
          auto model = hsrod::make_hydrodynamic_model(level, p, table);
          if (variant == 1) dynamic_cast<hsrod::LocalDragBase&>(*model).set_wall_proximity(hsrod::WallProximityLaw{});
          hsrod::RodDrag drag;
          model->evaluate(rod, variant == 2 ? static_cast<const hsrod::BackgroundFlow&>(along) : *flow, drag);
          v[variant] = hsrod::rigid_rod_load(rod, drag).free_velocity.y() / U;
        }
        std::printf(" | %6s %+8.5f %+8.5f %+8.5f", "", v[0], v[1], v[2]);
      }
      std::printf("\n");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hsrod_passage_drift: %s\n", e.what());
    return 1;
  }
  return 0;
}

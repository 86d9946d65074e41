// fix rod/bonds through LIGGGHTS: a bonded rod against Euler-Bernoulli
// theory (static cantilever, axial stiffness, lowest bending frequency),
// energy conservation without damping and decay with it, and restarts.
// Reference constants: ../drag-models/rod/euler_bernoulli_reference.txt.
#include "common/math_constants.h"
#include "liggghts_session.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using hsrod_test::LiggghtsSession;
using hsrod_test::num;

namespace {


using hsrod::kPi;
constexpr double kDiameter = 3e-6;      // [m], the pore scene's spheres
constexpr double kDensity = 1170.0;     // [kg/m3]
constexpr double kModulus = 15e6;       // [Pa]
constexpr int kSpheres = 20;
constexpr double kTimestep = 1e-8;      // [s], ~0.46 of the explicit bond limit
const double kSecondMoment = kPi * std::pow(kDiameter, 4) / 64.0;  // [m^4]
const double kMass = kDensity * kPi * std::pow(kDiameter, 3) / 6.0;  // [kg]

std::map<std::string, double> reference() {
  std::ifstream in(std::string(HSROD_TEST_DATA_DIR) + "/../drag-models/rod/euler_bernoulli_reference.txt");
  std::map<std::string, double> values;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream w(line);
    std::string name;
    double value;
    if (w >> name >> value) values[name] = value;
  }
  return values;
}

// A cantilever along x: sphere 1 clamped (never integrated), the others free.
void make_cantilever(LiggghtsSession &s, double damping, const std::string &extra_fix = "") {
  s.commands(hsrod_test::rod_box_header(1e-4));
  s.command("create_rod spheres " + std::to_string(kSpheres) + " diameter 3e-6 type 1 density 1170 "
            "centre 0 0 0 angle 90");
  s.command("group clamp id 1");
  s.command("group free subtract all clamp");
  s.command("group tip id " + std::to_string(kSpheres));
  s.command("fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3 damping " + num(damping));
  s.command("fix integrate free nve/sphere");
  if (!extra_fix.empty()) s.command(extra_fix);
  s.command("timestep " + num(kTimestep));
}

double total_energy(LiggghtsSession &s) {
  const auto v = s.gather("v");
  const auto w = s.gather("omega");
  double kinetic = 0.0;
  for (size_t i = 0; i < v.size(); i++)
    kinetic += 0.5 * kMass * v[i].squaredNorm() + 0.5 * (kMass * kDiameter * kDiameter / 10.0) * w[i].squaredNorm();
  return kinetic + s.fix("bonds")->compute_scalar();
}

}  // namespace

TEST(FixRodBonds, CantileverTipDeflectionMatchesEulerBernoulli) {
  LiggghtsSession s;
  const double length = (kSpheres - 1) * kDiameter;  // clamp centre to tip centre [m]
  const double ei = kModulus * kSecondMoment;
  const double tip_load = 3.0 * ei * 1e-3 / (length * length);  // deflection = 1e-3 L: linear regime [N]
  // Critical viscous damping of the lowest mode settles the rod quickly.
  make_cantilever(s, 0.3, "fix settle free viscous 3.5e-9");
  s.command("fix load tip addforce 0 " + num(tip_load) + " 0");
  s.command("run 30000");
  const auto x = s.gather("x");
  const double deflection = x[kSpheres - 1].y();
  const double expected = reference()["cantilever_tip_factor"] * tip_load * std::pow(length, 3) / ei;
  std::printf("cantilever N=%d: tip deflection %.6g m, Euler-Bernoulli %.6g m (%.3f %%)\n", kSpheres, deflection,
              expected, 100 * (deflection / expected - 1));
  EXPECT_NEAR(deflection / expected, 1.0, 0.02);
}

TEST(FixRodBonds, AxialStiffnessIsEA) {
  LiggghtsSession s;
  const double length = (kSpheres - 1) * kDiameter;
  const double ea = kModulus * kPi * kDiameter * kDiameter / 4.0;
  const double pull = 1e-3 * ea;  // strain 1e-3 [N]
  make_cantilever(s, 0.3, "fix settle free viscous 3.5e-9");
  // create_rod puts sphere 1 (end 1) at +x for angle 90: pull the tip towards -x.
  s.command("fix load tip addforce " + num(-pull) + " 0 0");
  s.command("run 30000");
  const auto x = s.gather("x");
  const double extension = (x[kSpheres - 1] - x[0]).norm() - length;
  const double measured_ea = pull * length / extension;
  std::printf("axial: EA measured %.6g N, E A %.6g N (%.3f %%)\n", measured_ea, ea, 100 * (measured_ea / ea - 1));
  EXPECT_NEAR(measured_ea / ea, 1.0, 0.01);
}

TEST(FixRodBonds, CantileverFrequencyAndEnergyConservation) {
  LiggghtsSession s;
  const double length = (kSpheres - 1) * kDiameter;
  const double ei = kModulus * kSecondMoment;
  const double tip_load = 3.0 * ei * 1e-3 / (length * length);
  make_cantilever(s, 0.0, "fix settle free viscous 3.5e-9");
  s.command("fix load tip addforce 0 " + num(tip_load) + " 0");
  s.command("run 30000");
  // Release from the static deflection: the motion is almost pure mode 1.
  s.command("unfix load");
  s.command("unfix settle");
  s.command("run 0");
  const double energy0 = total_energy(s);
  const int chunk = 20;
  double previous = s.gather("x")[kSpheres - 1].y(), time = 0.0;
  std::vector<double> crossings;
  double worst_drift = 0.0;
  while (crossings.size() < 11 && time < 2e-3) {
    s.command("run " + std::to_string(chunk) + " pre no post no");
    time += chunk * kTimestep;
    const double y = s.gather("x")[kSpheres - 1].y();
    if ((previous > 0.0) != (y > 0.0)) crossings.push_back(time - chunk * kTimestep * y / (y - previous));
    previous = y;
    worst_drift = std::max(worst_drift, std::fabs(total_energy(s) / energy0 - 1.0));
  }
  ASSERT_GE(crossings.size(), 11u);
  const double period = (crossings[10] - crossings[0]) / 5.0;  // 10 half periods
  const double omega = 2 * kPi / period;
  // Lumped masses: each free sphere carries one diameter of rod, so the
  // beam reaches half a diameter beyond the tip centre.
  const double beam_length = length + 0.5 * kDiameter;
  const double root = reference()["clamped_free_first_root"];
  const double expected = root * root * std::sqrt(ei / ((kMass / kDiameter) * std::pow(beam_length, 4)));
  std::printf("cantilever N=%d: omega_1 %.6g rad/s, Euler-Bernoulli %.6g rad/s (%.3f %%); energy drift %.2e over 5 periods\n",
              kSpheres, omega, expected, 100 * (omega / expected - 1), worst_drift);
  EXPECT_NEAR(omega / expected, 1.0, 0.03);
  // Velocity Verlet at 0.46 of the stability limit: bounded energy error of
  // order (omega_max dt)^2 on the (weakly excited) fastest modes.
  EXPECT_LT(worst_drift, 1e-3);
}

TEST(FixRodBonds, DampingDissipatesEnergy) {
  LiggghtsSession s;
  make_cantilever(s, 0.1);
  s.command("velocity tip set 0 0.01 0");
  s.command("run 0");
  const double energy0 = total_energy(s);
  // The energy never grows (beyond the integrator's 1e-6 oscillation seen
  // without damping) and has lost at least half after 2e-4 s: the bond
  // dashpots damp the fast modes hard and the lowest mode weakly
  // (its modal damping ratio is ~ 0.1 omega_1 / omega_bond).
  double energy = energy0;
  for (int k = 0; k < 20; k++) {
    s.command("run 1000 pre no post no");
    const double next = total_energy(s);
    EXPECT_LT(next, energy * (1 + 1e-6)) << "energy grew at chunk " << k;
    energy = next;
  }
  std::printf("damping 0.1: energy %.4g J -> %.4g J\n", energy0, energy);
  EXPECT_LT(energy, 0.5 * energy0);
}

TEST(FixRodBonds, RestartContinuesTheSameTrajectory) {
  const auto dir = std::filesystem::temp_directory_path() / "hsrod_restart_test";
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "rod.restart").string();
  auto prepare = [](LiggghtsSession &s) {
    make_cantilever(s, 0.1);
    s.command("velocity tip set 0 0.02 0.01");
    s.command("run 1000");
  };
  LiggghtsSession straight;
  prepare(straight);
  straight.command("run 1000");
  const auto expected = straight.gather("x");

  {
    LiggghtsSession first;
    prepare(first);
    first.command("write_restart " + file);
  }
  LiggghtsSession second;
  second.commands({"atom_style hybrid granular molecular", "atom_modify map array sort 0 0",
                   "communicate single cutoff 1e-5 vel yes", "read_restart " + file,
                   "group clamp id 1", "group free subtract all clamp",
                   "fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3 damping 0.1",
                   "fix integrate free nve/sphere", "run 1000"});
  const auto restarted = second.gather("x");
  double worst = 0.0;
  for (size_t i = 0; i < expected.size(); i++) worst = std::max(worst, (restarted[i] - expected[i]).norm());
  std::printf("restart: largest position difference %.3g m\n", worst);
  EXPECT_LT(worst, 1e-12 * kDiameter);
}

TEST(FixRodBonds, PrintedStabilityLimitSeparatesStableFromUnstableSteps) {
  // The limit fix rod/bonds computes (velocity Verlet with damped bonds)
  // must be the real one: 3 % below it a kicked rod stays bounded, 3 %
  // above it the same rod blows up.
  auto run = [](double fraction, double &limit) {
    LiggghtsSession s;
    s.commands(hsrod_test::rod_box_header(1e-4));
    s.commands({"create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 0 0 0 angle 90",
                "fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3 damping 0.1 timestep_check no",
                "fix integrate all nve/sphere", "group odd id 1 3 5 7 9", "velocity odd set 0 0 1e-3",
                "timestep 1e-9", "run 0"});
    limit = s.fix("bonds")->compute_vector(2);
    s.command("timestep " + num(fraction * limit));
    // A blown-up rod carries huge/NaN speeds and then leaves the box, which
    // stops the run (fix rod/bonds: a bond partner lost) within a few steps
    // of the speed passing 1e3 m/s: the 2000 steps are run 2 at a time and
    // stop at the first speed above 1e3 m/s (the largest speed at the end).
    double local = 0.0;
    s.command("run 0");
    for (int chunk = 0; chunk < 1000 && local <= 1e3; chunk++) {
      s.command("run 2 pre no post no");
      local = 0.0;  // the speed now
      for (int i = 0; i < s.lammps()->atom->nlocal; i++) {
        const double *v = s.lammps()->atom->v[i];
        const double speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        local = std::max(local, std::isfinite(speed) ? speed : 1e300);
      }
      if (s.lammps()->atom->nlocal < 10) local = 1e300;
    }
    return local;
  };
  double limit = 0.0;
  const double below = run(0.97, limit);
  const double above = run(1.03, limit);
  std::printf("explicit limit %.4g s: largest speed after 2000 steps %.3g m/s at 0.97x, %.3g m/s at 1.03x\n", limit,
              below, above);
  EXPECT_LT(below, 1e-3);   // the kick decays or stays bounded
  EXPECT_GT(above, 1e3);    // exponential growth
}

// The fitting step of the confinement calibration (calibration/core/
// confinement_fit.h): synthetic resolved "runs" made from known
// coefficients must give those coefficients back.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "common/math_constants.h"
#include "confinement_fit.h"

using namespace hsrod::calib;

namespace {
using hsrod::kPi;
const double d = 3e-6, mu = 1e-3;

struct Known {
  double beta, sf, sd, pf, qf, pd, qd;  // sphere/parallel/perpendicular friction and driving
};
const Known kKnown[] = {{0.15, 1.19, 1.4888, 0.52, 0.71, 1.47, 1.52}, {0.3, 1.41, 1.455, 0.47, 0.66, 1.43, 1.49},
                        {0.45, 1.68, 1.399, 0.43, 0.61, 1.38, 1.47}};

// F/n = zeta (lambda u - v) for a body, with a relative perturbation
// `noise` alternating in sign between runs.
std::string synthetic_csv(double noise) {
  std::ostringstream os;
  os << "# synthetic runs\nbeta,body,n_spheres,d,mu,u_mean,v,force\n";
  const double zeta0 = 3.0 * kPi * mu * d;
  int k = 0;
  for (const auto& c : kKnown) {
    struct Body { const char* name; int n; double zeta, lambda; };
    const Body bodies[] = {{"sphere", 1, c.sf * zeta0, c.sd},
                           {"rod_parallel", 10, c.pf * c.sf * zeta0, c.pd},
                           {"rod_perpendicular", 10, c.qf * c.sf * zeta0, c.qd}};
    for (const auto& b : bodies) {
      // held in flows, dragged through still fluid, and one mixed run
      const double runs[][2] = {{1e-3, 0.0}, {2e-3, 0.0}, {0.0, 1e-3}, {0.0, -5e-4}, {1e-3, 4e-4}};
      for (const auto& r : runs) {
        const double sign = (k++ % 2) ? 1.0 : -1.0;
        const double F = b.n * b.zeta * (b.lambda * r[0] - r[1]) * (1.0 + sign * noise);
        char line[256];
        std::snprintf(line, sizeof line, "%.4f,%s,%d,%.6e,%.6e,%.6e,%.6e,%.12e\n", c.beta, b.name, b.n, d, mu, r[0],
                      r[1], F);
        os << line;
      }
    }
  }
  return os.str();
}
}  // namespace

TEST(calibration_ConfinementFit, RecoversKnownCoefficientsFromSyntheticRuns) {
  const auto samples = parse_force_samples(synthetic_csv(0.0), "synthetic");
  ASSERT_EQ(samples.size(), 45u);
  const auto table = fit_table(samples, "test");
  ASSERT_EQ(table.rows().size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& r = table.rows()[i];
    const auto& k = kKnown[i];
    EXPECT_DOUBLE_EQ(r.beta, k.beta);
    EXPECT_NEAR(r.c.sphere_friction, k.sf, 1e-9 * k.sf);
    EXPECT_NEAR(r.c.sphere_driving, k.sd, 1e-9);
    EXPECT_NEAR(r.c.parallel_friction, k.pf, 1e-9);
    EXPECT_NEAR(r.c.perpendicular_friction, k.qf, 1e-9);
    EXPECT_NEAR(r.c.parallel_driving, k.pd, 1e-9);
    EXPECT_NEAR(r.c.perpendicular_driving, k.qd, 1e-9);
  }
  // written in hsrod's format and read back by the reader fix hele_shaw/drag uses
  const std::string path = ::testing::TempDir() + "hsrod_fit_test.txt";
  table.write(path);
  const auto back = hsrod::ConfinementTable::read(path);
  EXPECT_NEAR(back.at(0.3).sphere_friction, 1.41, 1e-8);
  EXPECT_NEAR(back.at(0.225).parallel_friction, 0.5 * (0.52 + 0.47), 1e-8);
  EXPECT_NE(back.source().find("fitted columns: rod_parallel rod_perpendicular sphere"), std::string::npos);
  std::remove(path.c_str());
}

TEST(calibration_ConfinementFit, NoisyRunsGiveCoefficientsWithinTheNoise) {
  // +-1 % alternating error on the forces: coefficients within 1 %
  const auto table = fit_table(parse_force_samples(synthetic_csv(0.01), "noisy"), "test");
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& r = table.rows()[i];
    EXPECT_NEAR(r.c.sphere_friction / kKnown[i].sf, 1.0, 0.01);
    EXPECT_NEAR(r.c.sphere_driving / kKnown[i].sd, 1.0, 0.01);
    EXPECT_NEAR(r.c.parallel_friction / kKnown[i].pf, 1.0, 0.02);  // ratio of two fits
  }
}

TEST(calibration_ConfinementFit, MissingColumnsKeepDefaultsAndBadInputIsRefused) {
  // sphere runs only: the rod columns are the default table's
  const std::string one_beta =
      "beta,body,n_spheres,d,mu,u_mean,v,force\n0.3,sphere,1,3e-6,1e-3,1e-3,0,5e-11\n"
      "0.3,sphere,1,3e-6,1e-3,0,1e-3,-4e-11\n";
  // one beta cannot make a table (it interpolates in beta)
  EXPECT_THROW(fit_table(parse_force_samples(one_beta, "x"), "test"), std::invalid_argument);
  const auto samples = parse_force_samples(one_beta + "0.15,sphere,1,3e-6,1e-3,1e-3,0,5e-11\n"
                                                      "0.15,sphere,1,3e-6,1e-3,0,1e-3,-4e-11\n",
                                           "four runs");
  const auto t = fit_table(samples, "test");
  const auto def = hsrod::ConfinementTable::default_table().at(0.3);
  EXPECT_DOUBLE_EQ(t.rows()[1].c.parallel_friction, def.parallel_friction);
  EXPECT_NEAR(t.rows()[1].c.sphere_driving, 5.0 / 4.0, 1e-12);
  // only held runs: b undetermined
  EXPECT_THROW(fit_linear(parse_force_samples("beta,body,n_spheres,d,mu,u_mean,v,force\n"
                                              "0.3,sphere,1,3e-6,1e-3,1e-3,0,5e-11\n", "x")),
               std::invalid_argument);
  EXPECT_THROW(parse_force_samples("beta,body,n_spheres,d,mu,u_mean,v\n", "x"), std::runtime_error);
  EXPECT_THROW(parse_force_samples("beta,body,n_spheres,d,mu,u_mean,v,force\n0.3,cube,1,3e-6,1e-3,0,0,0\n", "x"),
               std::runtime_error);
  EXPECT_THROW(parse_force_samples("beta,body,n_spheres,d,mu,u_mean,v,force\n1.2,sphere,1,3e-6,1e-3,0,0,0\n", "x"),
               std::runtime_error);
}

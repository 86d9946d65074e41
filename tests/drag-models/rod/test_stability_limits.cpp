// Stability limits against values worked out by hand for the pore
// scene (d = 3 um, rho = 1170 kg/m3, mu = 1 mPa s) and against the exact
// limit of a two-sphere axial oscillator.
#include "rod/stability_limits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace hsrod;

namespace {
hsrod::RodStabilityLimits limits(double youngs_modulus, int n) {
  RodSpec spec;
  spec.number_of_sections = n;
  spec.sphere_diameter = 3e-6;
  BeamBondMaterial bond{youngs_modulus, 0.3, 3e-6, 0.0};
  return compute_stability_limits(make_rod_layout(spec), {3e-6, 1170.0, youngs_modulus, 0.3}, bond, 1e-3);
}
}  // namespace

TEST(StabilityLimits, MatchDesignTableForThePoreScene) {
  // m / (3 pi mu d), sqrt(m / k_n) with k_n = E A / d, sqrt(I_s / k_b) with
  // k_b = E I / d, and Hertz's Rayleigh time (2 significant digits).
  const auto soft = limits(15e3, 10);
  EXPECT_NEAR(soft.stokes_relaxation_time, 0.6e-6, 0.05e-6);
  EXPECT_NEAR(soft.axial_bond_time, 0.7e-6, 0.05e-6);
  EXPECT_NEAR(soft.bending_bond_time, 0.9e-6, 0.05e-6);
  EXPECT_NEAR(soft.rayleigh_time, 2.3e-6, 0.1e-6);
  const auto stiff = limits(15e6, 10);
  EXPECT_NEAR(stiff.axial_bond_time, 22e-9, 1e-9);
  EXPECT_NEAR(stiff.bending_bond_time, 27e-9, 1e-9);
  EXPECT_NEAR(stiff.rayleigh_time, 73e-9, 2e-9);
  // Limits scale as 1/sqrt(E).
  EXPECT_NEAR(soft.explicit_bond_limit / stiff.explicit_bond_limit, std::sqrt(1000.0), 1e-6 * std::sqrt(1000.0));
}

TEST(StabilityLimits, TwoSphereAxialModeIsExact) {
  // Two free spheres: the axial mode has omega^2 = 2 k_n / m; the explicit
  // limit can only be lower (other modes may be faster).
  const auto lim = limits(15e6, 2);
  const double axial_omega = std::sqrt(2.0) / lim.axial_bond_time;
  EXPECT_GE(lim.highest_bond_frequency, axial_omega * (1 - 1e-6));
  EXPECT_LE(lim.explicit_bond_limit, std::sqrt(2.0) * lim.axial_bond_time * (1 + 1e-6));
}

// fix rod/bonds (no viscosity) must not print a "Stokes relaxation 0"
// row. The row appears only with a viscosity, with the value and dt/value.
TEST(StabilityLimits, TableShowsTheStokesRowOnlyWithAViscosity) {
  RodSpec spec;
  spec.number_of_sections = 10;
  spec.sphere_diameter = 3e-6;
  const BeamBondMaterial bond{15e6, 0.3, 3e-6, 0.0};
  const SphereMaterial sphere{3e-6, 1170.0, 15e6, 0.3};
  const std::string without = compute_stability_limits(make_rod_layout(spec), sphere, bond, 0.0).table(1e-8);
  EXPECT_EQ(without.find("Stokes"), std::string::npos) << without;
  EXPECT_NE(without.find("explicit bond limit 2/omega_max"), std::string::npos) << without;
  const auto with_fluid = compute_stability_limits(make_rod_layout(spec), sphere, bond, 1e-3);
  const std::string table = with_fluid.table(1e-8);
  char row[128];
  std::snprintf(row, sizeof(row), "Stokes relaxation m/(3 pi mu d)    %-12.4g  %.3g", with_fluid.stokes_relaxation_time,
                1e-8 / with_fluid.stokes_relaxation_time);
  EXPECT_NE(table.find(row), std::string::npos) << table;
  EXPECT_NEAR(with_fluid.stokes_relaxation_time, 0.6e-6, 0.05e-6);
}

// Bond damping lowers the velocity-Verlet limit below 2/omega_max; without
// with_damping (bonds integrated implicitly) the limit is 2/omega_max
// exactly and says so, with the same omega_max (measured: 1.741e-8 s with
// damping 0.1 against 2.17e-8 s without, ratio 0.80).
TEST(StabilityLimits, DampingReductionIsSkippedOnlyWhenAsked) {
  RodSpec spec;
  spec.number_of_sections = 20;
  spec.sphere_diameter = 3e-6;
  const BeamBondMaterial bond{15e6, 0.3, 3e-6, 0.1};
  const SphereMaterial sphere{3e-6, 1170.0, 15e6, 0.3};
  const auto damped = compute_stability_limits(make_rod_layout(spec), sphere, bond, 0.0);
  const auto undamped = compute_stability_limits(make_rod_layout(spec), sphere, bond, 0.0, false);
  EXPECT_TRUE(damped.damping_included);
  EXPECT_FALSE(undamped.damping_included);
  EXPECT_DOUBLE_EQ(undamped.explicit_bond_limit, 2.0 / undamped.highest_bond_frequency);
  EXPECT_DOUBLE_EQ(damped.highest_bond_frequency, undamped.highest_bond_frequency);
  EXPECT_LT(damped.explicit_bond_limit, undamped.explicit_bond_limit);
  std::printf("explicit bond limit 20 spheres E 15 MPa: %.4g s with damping 0.1, %.4g s without (ratio %.4f)\n",
              damped.explicit_bond_limit, undamped.explicit_bond_limit,
              damped.explicit_bond_limit / undamped.explicit_bond_limit);
}

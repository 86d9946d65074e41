// The depth-averaged Brinkman Green's function: incompressible, symmetric,
// and the Hele-Shaw potential dipole F H (2 rr - I) / (24 pi mu r^2) far away.
#include "hydro/brinkman_green.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

using namespace hsrod;

namespace {
constexpr double kMu = 1e-3, kH = 20e-6;
}

TEST(BrinkmanGreen, IsDivergenceFree) {
  const Eigen::Vector2d force(1e-9, 0.4e-9);
  for (double r : {0.05 * kH, 0.3 * kH, 1.0 * kH, 4.0 * kH}) {
    const Eigen::Vector2d p(0.6 * r, 0.8 * r);
    const double h = 1e-4 * r;
    auto u = [&](const Eigen::Vector2d& x) { return Eigen::Vector2d(brinkman_green_function(x, kMu, kH) * force); };
    const double div = (u(p + Eigen::Vector2d(h, 0)).x() - u(p - Eigen::Vector2d(h, 0)).x()) / (2 * h) +
                       (u(p + Eigen::Vector2d(0, h)).y() - u(p - Eigen::Vector2d(0, h)).y()) / (2 * h);
    const double scale = u(p).norm() / r;
    EXPECT_LT(std::fabs(div), 1e-5 * scale) << "r/H = " << r / kH;
  }
}

TEST(BrinkmanGreen, FarFieldIsTheHeleShawDipole) {
  const double r = 20 * kH;
  for (double angle : {0.0, 0.7, 1.5707963267948966}) {
    const Eigen::Vector2d rhat(std::cos(angle), std::sin(angle));
    const Eigen::Matrix2d g = brinkman_green_function(r * rhat, kMu, kH);
    const Eigen::Matrix2d dipole =
        kH * (2 * rhat * rhat.transpose() - Eigen::Matrix2d::Identity()) / (24 * 3.14159265358979323846 * kMu * r * r);
    EXPECT_LT((g - dipole).norm(), 1e-3 * dipole.norm());
  }
}

TEST(BrinkmanGreen, SymmetricAndSmoothAtSmallDistance) {
  const Eigen::Vector2d a(1e-7, 2e-8);
  const Eigen::Matrix2d g = brinkman_green_function(a, kMu, kH);
  EXPECT_NEAR(g(0, 1), g(1, 0), 1e-12 * g.norm());
  EXPECT_LT((g - brinkman_green_function(-a, kMu, kH)).norm(), 1e-12 * g.norm());
  // Continuity across the small-R switch of the implementation.
  const double l = kH / std::sqrt(12.0);
  const Eigen::Vector2d e(1, 0);
  const Eigen::Matrix2d below = brinkman_green_function(0.999e-3 * l * e, kMu, kH);
  const Eigen::Matrix2d above = brinkman_green_function(1.001e-3 * l * e, kMu, kH);
  EXPECT_LT((below - above).norm(), 1e-3 * below.norm());
}

// The tabulated kernels A(R), B(R) (what every sphere pair of level 3 uses)
// against the Bessel form they replace, on 200 000 random separations spread
// evenly in ln R over the table (1e-3 <= R < 40) and beyond it (far field up
// to R = 100): within the stated bound, relative to |A| + |B|.
TEST(BrinkmanGreen, KernelTableEqualsTheBesselFormToItsStatedError) {
  std::mt19937_64 random(20261202);
  std::uniform_real_distribution<double> log_r(std::log(1e-3), std::log(100.0));
  double worst_ratio = 0.0;  // largest |table - Bessel| / (bound * (|A| + |B|))
  for (int trial = 0; trial < 200000; ++trial) {
    const double R = std::exp(log_r(random));
    const BrinkmanKernels exact = brinkman_green_kernels_bessel(R), table = brinkman_green_kernels(R);
    const double bound = brinkman_kernel_table_error(R) * (std::fabs(exact.a) + std::fabs(exact.b));
    worst_ratio = std::max({worst_ratio, std::fabs(table.a - exact.a) / bound, std::fabs(table.b - exact.b) / bound});
    ASSERT_LE(std::fabs(table.a - exact.a), bound) << "R = " << R;
    ASSERT_LE(std::fabs(table.b - exact.b), bound) << "R = " << R;
  }
  RecordProperty("worst_error_over_bound", std::to_string(worst_ratio));
}

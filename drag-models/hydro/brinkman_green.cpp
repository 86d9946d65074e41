#include "hydro/brinkman_green.h"
#include "common/math_constants.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace hsrod {

namespace {

constexpr double kSmallR = 1e-3;  // below: small-R expansion [-]
constexpr double kLargeR = 40.0;  // from here: far field, K0, K1 ~ e^-R negligible [-]
constexpr int kIntervals = 256;   // table intervals in ln R (spacing 0.041)

// Small-R expansions (the 1/R^2 terms cancel): the 2-D Stokeslet,
// A ~ -(ln(R/2) + gamma + 1/2) / 2, B ~ 1/2.
BrinkmanKernels small_separation(double R) {
  const double euler_gamma = 0.57721566490153286;
  return {-0.5 * (std::log(0.5 * R) + euler_gamma + 0.5), 0.5};
}

// A, B and their first two derivatives in t = ln R, from K0' = -K1,
// K1' = -K0 - K1/R:
//   A'  = -K1 - K0/R - 2K1/R^2 + 2/R^3,
//   A'' =  K0 + 2K1/R + 3K0/R^2 + 6K1/R^3 - 6/R^4,
//   B'  =  K1 + 2K0/R + 4K1/R^2 - 4/R^3,
//   B'' = -K0 - 3K1/R - 6K0/R^2 - 12K1/R^3 + 12/R^4,
// and d/dt = R d/dR, d2/dt2 = R d/dR + R^2 d2/dR2.
struct KernelJet {
  double a, da, dda, b, db, ddb;
};

KernelJet kernel_jet(double R) {
  const double k0 = std::cyl_bessel_k(0.0, R), k1 = std::cyl_bessel_k(1.0, R);
  const double r1 = 1.0 / R, r2 = r1 * r1, r3 = r2 * r1, r4 = r2 * r2;
  const double a = k0 + k1 * r1 - r2;
  const double a1 = -k1 - k0 * r1 - 2.0 * k1 * r2 + 2.0 * r3;
  const double a2 = k0 + 2.0 * k1 * r1 + 3.0 * k0 * r2 + 6.0 * k1 * r3 - 6.0 * r4;
  const double b = -k0 - 2.0 * k1 * r1 + 2.0 * r2;
  const double b1 = k1 + 2.0 * k0 * r1 + 4.0 * k1 * r2 - 4.0 * r3;
  const double b2 = -k0 - 3.0 * k1 * r1 - 6.0 * k0 * r2 - 12.0 * k1 * r3 + 12.0 * r4;
  return {a, R * a1, R * a1 + R * R * a2, b, R * b1, R * b1 + R * R * b2};
}

// Monomial coefficients in s in [0, 1] of the quintic Hermite interpolant of
// values f, first derivatives d = h f', second derivatives c = h^2 f''.
std::array<double, 6> quintic_hermite(double f0, double f1, double d0, double d1, double c0, double c1) {
  return {f0,
          d0,
          0.5 * c0,
          -10.0 * f0 + 10.0 * f1 - 6.0 * d0 - 4.0 * d1 - 1.5 * c0 + 0.5 * c1,
          15.0 * f0 - 15.0 * f1 + 8.0 * d0 + 7.0 * d1 + 1.5 * c0 - c1,
          -6.0 * f0 + 6.0 * f1 - 3.0 * d0 - 3.0 * d1 - 0.5 * c0 + 0.5 * c1};
}

double horner(const double* c, double s) {
  return c[0] + s * (c[1] + s * (c[2] + s * (c[3] + s * (c[4] + s * c[5]))));
}

class KernelTable {
 public:
  KernelTable() : t0_(std::log(kSmallR)), h_((std::log(kLargeR) - t0_) / kIntervals) {
    std::vector<KernelJet> jets(kIntervals + 1);
    for (int j = 0; j <= kIntervals; ++j) jets[j] = kernel_jet(std::exp(t0_ + j * h_));
    coefficients_.resize(kIntervals);
    for (int j = 0; j < kIntervals; ++j) {
      const KernelJet &p = jets[j], &q = jets[j + 1];
      const double h2 = h_ * h_;
      const auto a = quintic_hermite(p.a, q.a, h_ * p.da, h_ * q.da, h2 * p.dda, h2 * q.dda);
      const auto b = quintic_hermite(p.b, q.b, h_ * p.db, h_ * q.db, h2 * p.ddb, h2 * q.ddb);
      std::copy(a.begin(), a.end(), coefficients_[j].begin());
      std::copy(b.begin(), b.end(), coefficients_[j].begin() + 6);
    }
    // Self-check on the mid-points (where the interpolation error peaks):
    // a table that misses its stated bound is a bug, not a run-time condition.
    for (int j = 0; j < kIntervals; ++j) {
      const double R = std::exp(t0_ + (j + 0.5) * h_);
      const BrinkmanKernels exact = brinkman_green_kernels_bessel(R), table = evaluate(R);
      const double scale = std::fabs(exact.a) + std::fabs(exact.b);
      const double bound = brinkman_kernel_table_error(R) * scale;
      if (std::fabs(table.a - exact.a) > bound || std::fabs(table.b - exact.b) > bound)
        throw std::logic_error("brinkman_green: kernel table misses its stated error bound");
    }
  }

  BrinkmanKernels evaluate(double R) const {
    const double u = (std::log(R) - t0_) / h_;
    const int j = std::min(std::max(static_cast<int>(u), 0), kIntervals - 1);
    const double s = u - j;
    const double* c = coefficients_[j].data();
    return {horner(c, s), horner(c + 6, s)};
  }

 private:
  double t0_;  // ln of the table's first R [-]
  double h_;   // spacing in ln R [-]
  std::vector<std::array<double, 12>> coefficients_;  // per interval: A's then B's
};

}  // namespace

BrinkmanKernels brinkman_green_kernels_bessel(double R) {
  if (R < kSmallR) return small_separation(R);
  const double k0 = std::cyl_bessel_k(0.0, R);
  const double k1 = std::cyl_bessel_k(1.0, R);
  return {k0 + k1 / R - 1.0 / (R * R), -k0 - 2.0 * k1 / R + 2.0 / (R * R)};
}

BrinkmanKernels brinkman_green_kernels(double R) {
  if (R < kSmallR) return small_separation(R);
  if (R >= kLargeR) {
    const double r2 = 1.0 / (R * R);
    return {-r2, 2.0 * r2};
  }
  static const KernelTable table;  // built on first use, thread-safe (C++11)
  return table.evaluate(R);
}

Eigen::Matrix2d brinkman_green_function(const Eigen::Vector2d& offset, double viscosity, double gap_height) {
  const double screening_length = gap_height / std::sqrt(12.0);  // l [m]
  const double r = offset.norm();
  const BrinkmanKernels k = brinkman_green_kernels(r / screening_length);
  const Eigen::Vector2d rhat = offset / r;
  return (k.a * Eigen::Matrix2d::Identity() + k.b * rhat * rhat.transpose()) / (2.0 * kPi * viscosity * gap_height);
}

}  // namespace hsrod

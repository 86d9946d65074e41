// The bonded sphere chain against Euler-Bernoulli beam theory, in the
// small-displacement limit (linearised bond law). The stiffnesses come from
// E, nu and d alone: no per-test tuning. The same checks are repeated
// through LIGGGHTS (dynamic runs) in tests/liggghts.
#include "common/math_constants.h"
#include "reference_data.h"
#include "rod/rod_linearisation.h"
#include "rod/stability_limits.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace hsrod;

namespace {
using hsrod::kPi;

struct Beam {
  RodLayout layout;
  BeamBondMaterial bond;
  SphereMaterial sphere;
  double ei() const { return bond.youngs_modulus * bond.second_moment(); }
};

Beam make_beam(int n) {
  Beam b;
  RodSpec spec;
  spec.number_of_sections = n;
  spec.sphere_diameter = 3e-6;
  spec.angle = kPi / 2;  // along x
  b.layout = make_rod_layout(spec);
  b.bond.youngs_modulus = 15e6;
  b.bond.poisson_ratio = 0.3;
  b.bond.bond_diameter = 3e-6;
  b.sphere = {3e-6, 1170.0, 15e6, 0.3};
  return b;
}

std::map<std::string, double> reference() {
  return read_reference_values(std::string(HSROD_TEST_DATA_DIR) + "/euler_bernoulli_reference.txt");
}

// Index of a sphere's dof after removing the clamped sphere's 6 dof.
Eigen::MatrixXd clamp_first_sphere(const Eigen::MatrixXd& full) {
  const int n = static_cast<int>(full.rows()) - 6;
  return full.bottomRightCorner(n, n);
}

}  // namespace

TEST(EulerBernoulli, CantileverTipDeflectionWithinTwoPercent) {
  for (int n : {20, 40}) {
    const Beam beam = make_beam(n);
    // Sphere 0 clamped (position and rotation); tip load P along y at the last sphere.
    const Eigen::MatrixXd k = clamp_first_sphere(linearised_bond_stiffness(beam.layout, beam.bond));
    Eigen::VectorXd load = Eigen::VectorXd::Zero(k.rows());
    const double tip_load = 1e-9;  // [N]
    load[k.rows() - 6 + 1] = tip_load;
    const Eigen::VectorXd u = k.ldlt().solve(load);
    const double length = (n - 1) * 3e-6;  // clamp centre to load centre [m]
    const double expected = reference()["cantilever_tip_factor"] * tip_load * std::pow(length, 3) / beam.ei();
    const double tip = u[k.rows() - 6 + 1];
    std::printf("N = %d: tip deflection %.6g m, Euler-Bernoulli %.6g m, error %.3f %%\n", n, tip, expected,
                100 * (tip / expected - 1));
    EXPECT_NEAR(tip / expected, 1.0, 0.02);
  }
}

TEST(EulerBernoulli, AxialStiffnessWithinOnePercent) {
  const int n = 20;
  const Beam beam = make_beam(n);
  const Eigen::MatrixXd k = clamp_first_sphere(linearised_bond_stiffness(beam.layout, beam.bond));
  Eigen::VectorXd load = Eigen::VectorXd::Zero(k.rows());
  const double pull = 1e-6;  // [N] along the axis (x)
  load[k.rows() - 6] = pull;
  const Eigen::VectorXd u = k.ldlt().solve(load);
  const double length = (n - 1) * 3e-6;
  const double ea = beam.bond.youngs_modulus * beam.bond.area();
  const double measured_ea = pull * length / u[k.rows() - 6];
  EXPECT_NEAR(measured_ea / ea, 1.0, 0.01);
}

TEST(EulerBernoulli, FreeFreeBendingFrequencyWithinThreePercent) {
  auto ref = reference();
  for (int n : {20, 40}) {
    const Beam beam = make_beam(n);
    const Eigen::MatrixXd k = linearised_bond_stiffness(beam.layout, beam.bond);
    const Eigen::VectorXd m = rod_mass_diagonal(beam.layout, beam.sphere);
    const Eigen::VectorXd s = m.cwiseSqrt().cwiseInverse();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(s.asDiagonal() * k * s.asDiagonal());
    // Skip the 6 rigid-body modes; the lowest elastic mode of a slender rod is bending.
    const double omega = std::sqrt(eig.eigenvalues()[6]);
    const double length = n * 3e-6;                        // each sphere carries one diameter of rod
    const double mass_per_length = beam.sphere.mass() / 3e-6;  // [kg/m]
    const double root = ref["free_free_first_root"];
    const double expected = root * root * std::sqrt(beam.ei() / (mass_per_length * std::pow(length, 4)));
    std::printf("N = %d: lowest bending omega %.6g rad/s, Euler-Bernoulli %.6g, error %.3f %%\n", n, omega,
                expected, 100 * (omega / expected - 1));
    EXPECT_NEAR(omega / expected, 1.0, 0.03);
  }
}

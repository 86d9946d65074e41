// Position update with finite bond rotations (dynamics/finite_rotation_update.h):
// a rigid rotation across (or along) the bonds given as the step's
// linear displacements dx_i = Omega x (x_i - c), dphi_i = Omega must move the
// rod to its exactly rotated configuration (no stretched bonds), for a chain (running sum) and
// for 2x2 sections (the bond graph's least-squares solve); a pure translation
// stays a translation.
#include "dynamics/overdamped_rod_step.h"
#include "rod/rod_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace hsrod;

namespace {

OverdampedRod rod_of(int sections, int rows, int layers) {
  RodSpec spec;
  spec.number_of_sections = sections;
  spec.sphere_diameter = 3e-6;
  spec.angle = 0.4;
  spec.centre = Eigen::Vector3d(1e-4, 5e-5, 1e-5);
  spec.section_rows = rows;
  spec.section_layers = layers;
  return make_overdamped_rod(make_rod_layout(spec), {15e6, 0.3, 3e-6, 0.0}, 3e-6);
}

Eigen::Vector3d centroid(const OverdampedRod& rod) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : rod.positions) c += p / rod.size();
  return c;
}

void expect_rigid_rotation(int sections, int rows, int layers, const Eigen::Vector3d& omega) {
  OverdampedRod rod = rod_of(sections, rows, layers);
  const int n = rod.size();
  const Eigen::Vector3d c = centroid(rod);
  const Eigen::Vector3d shift(2e-6, -1e-6, 0.0);   // [m]
  Eigen::VectorXd dy(6 * n);
  for (int i = 0; i < n; ++i) {
    dy.segment<3>(6 * i) = shift + omega.cross(rod.positions[i] - c);
    dy.segment<3>(6 * i + 3) = omega;
  }
  const OverdampedRod before = rod;
  OverdampedRodSolver solver;
  solver.displace(rod, dy);
  const Eigen::Quaterniond q = quaternion_from_rotation_vector(omega);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d exact = c + shift + q * (before.positions[i] - c);
    worst = std::max(worst, (rod.positions[i] - exact).norm() / 3e-6);
    EXPECT_LT(q.angularDistance(rod.orientations[i]), 1e-12);
  }
  // The tangent update x + dx misses by (Exp(Omega) - 1 - [Omega]x) r, up
  // to |Omega|^2 / 2 |r| = 0.05 rod half-lengths here.
  std::printf("%d sections of %dx%d: largest miss of the rigid rotation %.2e d\n", sections, rows, layers, worst);
  EXPECT_LT(worst, 1e-12);
  for (const RodBond& b : rod.bonds)
    EXPECT_NEAR((rod.positions[b.j] - rod.positions[b.i]).norm() / b.rest.rest_length(), 1.0, 1e-13);
}

}  // namespace

// Large steps [rad]: a chain turned about an axis across it, out of the
// plane; 2x2 sections turned in the plane (about z: across the axial and
// row bonds, along the layer bonds).
TEST(FiniteRotationUpdate, ChainEndsExactlyRotated) {
  expect_rigid_rotation(10, 1, 1, 0.3 * Eigen::Vector3d(std::cos(0.4), -std::sin(0.4), 0.0) + Eigen::Vector3d(0, 0, 0.2));
}

TEST(FiniteRotationUpdate, TwoByTwoSectionsEndExactlyRotated) {
  expect_rigid_rotation(8, 2, 2, Eigen::Vector3d(0.0, 0.0, 0.3));
}

TEST(FiniteRotationUpdate, TranslationWithRollingSpheresStaysATranslation) {
  // Spheres that roll (each turning about its own axis, as on a wall with
  // friction) while the rod translates: no bond turns, so the update is
  // x + dx. (Taking the spheres' rotations for the bonds' moved them by
  // |dphi|^2 / 2 |r| and cost a rod buckling against the pore 40x the
  // substeps: examples/clogging, E = 1.5 MPa.)
  OverdampedRod rod = rod_of(6, 2, 2);
  const int n = rod.size();
  Eigen::VectorXd dy = Eigen::VectorXd::Zero(6 * n);
  for (int i = 0; i < n; ++i) {
    dy.segment<3>(6 * i) = Eigen::Vector3d(3e-7, -1e-7, 0.0);
    dy.segment<3>(6 * i + 3) = Eigen::Vector3d(0.1, 0.3 * (i % 3), -0.2);
  }
  const OverdampedRod before = rod;
  OverdampedRodSolver solver;
  solver.displace(rod, dy);
  for (int i = 0; i < n; ++i)
    EXPECT_LT((rod.positions[i] - before.positions[i] - dy.segment<3>(6 * i)).norm(), 1e-18);
}

// The walls' images of a point force (hydro/wall_images.h) and level 3 with
// them (WallReflection::images): the analytic facts of the images (no normal
// velocity through a plane wall or a cylinder, vanishing for a far force,
// reciprocity) and a symmetric positive definite resistance of a rod
// close to a side wall and to a pore cylinder.
#include "hydro/wall_images.h"

#include "common/math_constants.h"
#include "flow/uniform_flow.h"
#include "hydro/brinkman_green.h"
#include "hydro/nonlocal_model.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>

using namespace hsrod;

namespace {
constexpr double kMu = 1e-3, kH = 10e-6, kD = 3e-6;  // Pa s, m (beta 0.3), m

// A channel far wider than the distances tested (W = 2000 H): the opposite
// wall's image is ~(h / 2 W)^2 of the near one's.
ChannelGeometry wide_channel(std::vector<ZCylinder> cylinders = {}) {
  return ChannelGeometry(2000.0 * kH, 2000.0 * kH, kH, -1000.0 * kH, 0.0, std::move(cylinders));
}
}  // namespace

TEST(WallImages, PlaneWallImageCancelsTheNormalVelocity) {
  // free-space G plus its mirror image: zero normal velocity on y = 0 (the
  // pair is symmetric about the wall; exact for the full Brinkman G)
  const ChannelGeometry walls = wide_channel();
  const Eigen::Vector2d source(0.0, 1.5 * kD), force(0.7e-9, -1.1e-9);
  for (double x : {-3.0 * kH, -0.4 * kH, 0.0, 0.2 * kH, 5.0 * kH}) {
    const Eigen::Vector2d on_wall(x, 0.0);
    const Eigen::Vector2d u = (brinkman_green_function(on_wall - source, kMu, kH) +
                               image_mobility(walls, on_wall, source, kMu, kH)) *
                              force;
    const Eigen::Vector2d free = brinkman_green_function(on_wall - source, kMu, kH) * force;
    // the upper wall's image at y ~ 2 W, relative to the field at distance
    // r <= 5 H: ~(r / 2 W)^2 <= 2e-6
    EXPECT_LT(std::abs(u.y()), 1e-5 * free.norm()) << "x = " << x;
    EXPECT_GT(std::abs(u.x()), 0.5 * std::abs(free.x()));  // the tangential slip stays
  }
}

TEST(WallImages, CircleTheoremImageCancelsTheDipoleNormalVelocityOnTheCylinder) {
  // Milne-Thomson: the potential dipole plus its circle image has no normal
  // velocity on the cylinder |z - c| = a
  const double a = 1.5 * kH;
  const ZCylinder pore{0.0, 1000.0 * kH, a};
  const ChannelGeometry walls = wide_channel({pore});
  const Eigen::Vector2d c(pore.center_x, pore.center_y);
  const Eigen::Vector2d source = c + Eigen::Vector2d(0.4 * a, 1.3 * a), force(0.3e-9, 1.0e-9);
  for (double phi : {0.0, 0.7, 1.6, 2.9, 4.4, 5.8}) {
    const Eigen::Vector2d n(std::cos(phi), std::sin(phi)), on_surface = c + a * n;
    const Eigen::Vector2d primary = hele_shaw_dipole(on_surface - source, kMu, kH) * force;
    const Eigen::Vector2d u = primary + image_mobility(walls, on_surface, source, kMu, kH) * force;
    // side walls' mirrors ~1000 H away: ~(2 a / 1000 H)^2 ~ 1e-5 of the field
    EXPECT_LT(std::abs(u.dot(n)), 1e-4 * primary.norm()) << "phi = " << phi;
  }
}

TEST(WallImages, ImageOfAFarForceVanishesAsTheMirroredDipole) {
  // at distance D from the wall the self-image is the Hele-Shaw dipole at
  // 2 D of the mirrored force: |M| = H / (24 pi mu (2 D)^2) -> 0
  const ChannelGeometry walls = wide_channel();
  for (double D : {20.0 * kH, 100.0 * kH}) {
    const Eigen::Vector2d x(0.0, D);
    const Eigen::Matrix2d self = image_mobility(walls, x, x, kMu, kH);
    const Eigen::Matrix2d mirrored =
        hele_shaw_dipole(Eigen::Vector2d(0.0, 2.0 * D), kMu, kH) * Eigen::Vector2d(1.0, -1.0).asDiagonal();
    // the opposite wall's image at 2 (W - D): (D / (W - D))^2 <= 2.8e-3 of it
    EXPECT_LT((self - mirrored).norm(), 2.9e-3 * mirrored.norm()) << "D/H = " << D / kH;
    EXPECT_NEAR(mirrored.norm(), std::sqrt(2.0) * kH / (24.0 * kPi * kMu * 4.0 * D * D), 1e-9 * mirrored.norm());
  }
}

TEST(WallImages, ImageMobilityIsReciprocal) {
  // M_ik = M_ki^T: exact for the plane mirror (G(S r) = S G(r) S), and for
  // the circle images (the reflected part of the Neumann Green's function)
  const ZCylinder pore{0.0, 0.0, 1.5 * kH};  // centred on the side wall, as the campaign's pores
  const ChannelGeometry walls(24.0 * kH, 6.0 * kH, kH, -12.0 * kH, 0.0, {pore, {0.0, 6.0 * kH, 1.5 * kH}});
  const Eigen::Vector2d a(0.3 * kH, 2.0 * kH), b(-0.8 * kH, 2.6 * kH);
  const Eigen::Matrix2d mab = image_mobility(walls, a, b, kMu, kH), mba = image_mobility(walls, b, a, kMu, kH);
  EXPECT_LT((mab - mba.transpose()).norm(), 1e-10 * mab.norm());
}

namespace {
// Level 3's resistance of a 5-sphere row parallel to the wall at surface gap g [m].
Eigen::MatrixXd resistance_near(const ChannelGeometry& walls, double y_centre, WallReflection reflection) {
  NonlocalRodModel model(HydrodynamicParameters{kMu, kH, kD}, ConfinementTable::default_table());
  model.set_wall_reflection(reflection);
  RodGeometry rod;
  rod.sphere_diameter = kD;
  for (int k = 0; k < 5; ++k) rod.positions.emplace_back((k - 2) * kD, y_centre, 0.5 * kH);
  const UniformFlow still(walls, Eigen::Vector2d::Zero());
  RodDrag drag;
  model.evaluate(rod, still, drag);
  return drag.coupled_resistance;
}
}  // namespace

TEST(WallImages, LevelThreeResistanceStaysSymmetricPositiveDefiniteAndGrowsNearTheWall) {
  const ChannelGeometry side(40.0 * kH, 5.0 * kH, kH, -20.0 * kH, 0.0);
  const ChannelGeometry pores(40.0 * kH, 6.0 * kH, kH, -20.0 * kH, 0.0, {{0.0, 0.0, 1.5 * kH}, {0.0, 6.0 * kH, 1.5 * kH}});
  for (const auto& [walls, wall_y] : {std::make_pair(side, 0.0), std::make_pair(pores, 1.5 * kH)}) {
    // the campaign's closest gap, 0.25 d (for the pore: beside its top, 0.25 d off it at the row's middle)
    const double y = wall_y + 0.75 * kD;
    const Eigen::MatrixXd with = resistance_near(walls, y, WallReflection::images);
    const Eigen::MatrixXd without = resistance_near(walls, y, WallReflection::none);
    EXPECT_LT((with - with.transpose()).norm(), 1e-12 * with.norm());
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(with);
    EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
    // the walls' reflection opposes the motion: the row's total friction towards the wall grows
    Eigen::VectorXd towards = Eigen::VectorXd::Zero(with.rows());
    for (int i = 0; i < 5; ++i) towards(3 * i + 1) = -1.0;
    EXPECT_GT(towards.dot(with * towards), towards.dot(without * towards));
  }
}

TEST(WallImages, UnknownReflectionNameIsRejected) {
  EXPECT_EQ(wall_reflection_from_name("images"), WallReflection::images);
  EXPECT_EQ(wall_reflection_from_name("none"), WallReflection::none);
  EXPECT_EQ(wall_reflection_from_name("self_images"), WallReflection::self_images);
  EXPECT_THROW(wall_reflection_from_name("mirror"), std::invalid_argument);
}

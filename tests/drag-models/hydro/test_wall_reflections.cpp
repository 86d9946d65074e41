// The multiple reflections of a point force between the side walls and the
// pore cylinders (hydro/wall_images.h, reflected_force_images;
// WallReflection::reflections): the closed-form strip lattice against its
// direct sum, no normal velocity through either throat cylinder or the side
// walls at sample points, convergence of the series, reciprocity, and level
// 3's resistance in the throat.
#include "hydro/wall_images.h"

#include "common/math_constants.h"
#include "flow/uniform_flow.h"
#include "hydro/brinkman_green.h"
#include "hydro/nonlocal_model.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

using namespace hsrod;

namespace {
constexpr double kMu = 1e-3;  // Pa s
constexpr double kUm = 1e-6;  // m

// The pore passage's planform (calibration/validation/pore_passage: W = 36 um,
// two cylinders R = 9 um on the side walls at x = 42 um) with a gap height
// small enough that the Brinkman G equals its dipole far field at the
// distances sampled (>= 2 um: the correction ~exp(-r sqrt(12) / H) < 1e-15),
// so the potential-flow images must cancel the normal velocity exactly.
constexpr double kThinGap = 0.2 * kUm;
ChannelGeometry throat(double gap_height) {
  return ChannelGeometry(84.0 * kUm, 36.0 * kUm, gap_height, 0.0, 0.0,
                         {{42.0 * kUm, 0.0, 9.0 * kUm}, {42.0 * kUm, 36.0 * kUm, 9.0 * kUm}});
}

struct Sample {
  Eigen::Vector2d point, normal;  // on a wall [m], unit normal into the fluid
};

// Points on both cylinders' arcs in the fluid and on both side walls.
std::vector<Sample> boundary_samples() {
  std::vector<Sample> s;
  for (int c = 0; c < 2; ++c)
    for (int k = 1; k < 12; ++k) {
      const double t = (c == 0 ? 0.0 : kPi) + kPi * k / 12.0;
      const Eigen::Vector2d n(std::cos(t), std::sin(t));
      s.push_back({Eigen::Vector2d(42.0 * kUm, c == 0 ? 0.0 : 36.0 * kUm) + 9.0 * kUm * n, n});
    }
  for (double x : {14.0, 24.0, 30.0, 54.0, 60.0, 70.0}) {
    s.push_back({Eigen::Vector2d(x * kUm, 0.0), Eigen::Vector2d(0.0, 1.0)});
    s.push_back({Eigen::Vector2d(x * kUm, 36.0 * kUm), Eigen::Vector2d(0.0, -1.0)});
  }
  return s;
}

// Largest |n . u| on the walls of the source's field plus `images`, over the
// largest |n . u| of the source's field alone [-], for both force directions.
template <class Images>
double normal_velocity_residual(const Eigen::Vector2d& source, Images&& images) {
  double residual = 0.0, scale = 0.0;
  for (const Sample& s : boundary_samples()) {
    const Eigen::Matrix2d free = brinkman_green_function(s.point - source, kMu, kThinGap);
    const Eigen::Matrix2d total = free + images(s.point);
    residual = std::max(residual, (s.normal.transpose() * total).cwiseAbs().maxCoeff());
    scale = std::max(scale, (s.normal.transpose() * free).cwiseAbs().maxCoeff());
  }
  return residual / scale;
}
}  // namespace

TEST(WallReflections, StripLatticeRemainderEqualsTheDirectLatticeSum) {
  // sum over k = -K..K of the dipoles at z0 + 2kWi and z0' + 2kWi without the
  // source and its two first mirrors; the omitted tail, ~sum_{|k|>K} 1 / (2kW)^2
  // per side, is ~1 / (2K) = 2.5e-5 of the nearest lattice term's W^-2 scale
  const double y_lo = 1.0 * kUm, W = 36.0 * kUm, H = 10.0 * kUm;
  const Eigen::Vector2d x0(3.0 * kUm, 9.0 * kUm), x(5.5 * kUm, 20.0 * kUm);
  const Eigen::Matrix2d flip = Eigen::Vector2d(1.0, -1.0).asDiagonal();
  Eigen::Matrix2d direct = Eigen::Matrix2d::Zero();
  const int K = 20000;
  for (int k = -K; k <= K; ++k) {
    const Eigen::Vector2d own(x0.x(), x0.y() + 2.0 * k * W), mirrored(x0.x(), 2.0 * y_lo - x0.y() + 2.0 * k * W);
    if (k != 0) direct += hele_shaw_dipole(x - own, kMu, H);
    if (k != 0 && k != 1) direct += hele_shaw_dipole(x - mirrored, kMu, H) * flip;
  }
  const Eigen::Matrix2d closed = strip_lattice_remainder(y_lo, W, x, x0, kMu, H);
  EXPECT_LT((closed - direct).norm(), 1e-4 * closed.norm());
  // at the source itself (the self-image) the Laurent branch: continuous with the sinh form
  const Eigen::Matrix2d at = strip_lattice_remainder(y_lo, W, x0, x0, kMu, H);
  const Eigen::Matrix2d near = strip_lattice_remainder(y_lo, W, x0 + Eigen::Vector2d(0.0, 0.2 * kUm), x0, kMu, H);
  EXPECT_LT((at - near).norm(), 1e-3 * at.norm());
}

TEST(WallReflections, NoNormalVelocityThroughEitherThroatCylinderOrTheSideWalls) {
  const ChannelGeometry walls = throat(kThinGap);
  for (const Eigen::Vector2d& source : {Eigen::Vector2d(36.0 * kUm, 14.0 * kUm), Eigen::Vector2d(42.0 * kUm, 18.0 * kUm),
                                        Eigen::Vector2d(47.0 * kUm, 25.0 * kUm)}) {
    const ImageSeries series = reflected_force_images(walls, source);
    ReflectionControl fine;
    fine.prune = 1e-5;
    const ImageSeries finer = reflected_force_images(walls, source, fine);
    const auto residual = [&](const ImageSeries& images) {
      return normal_velocity_residual(
          source, [&](const Eigen::Vector2d& p) { return image_mobility(images, p, kMu, kThinGap); });
    };
    const double with = residual(series), with_finer = residual(finer);
    const double first = normal_velocity_residual(
        source, [&](const Eigen::Vector2d& p) { return image_mobility(walls, p, source, kMu, kThinGap); });
    // the side walls exactly (the strip lattice is their exact image system)
    // and the cylinders to what the cut series leaves: images lighter than
    // prune = 1e-3 of a unit force one width away are dropped, and the
    // samples on the cylinders lie ~W / 4 from the heaviest ones, so up to
    // ~16x that: 2 %; at prune 1e-5 a tenth of it
    EXPECT_LT(with, 2e-2) << source.transpose();
    EXPECT_LT(with_finer, 2e-3) << source.transpose();
    // the first images leave the other cylinder's and the opposite wall's reflection out
    EXPECT_GT(first, 2.0 * with) << source.transpose();
    EXPECT_GT(first, 8.0 * with_finer) << source.transpose();
  }
}

TEST(WallReflections, SeriesConvergesAsTheCutIsLowered) {
  const ChannelGeometry walls = throat(10.0 * kUm);
  const Eigen::Vector2d source(40.0 * kUm, 12.0 * kUm), target(44.0 * kUm, 13.0 * kUm);
  const ImageSeries series = reflected_force_images(walls, source);
  EXPECT_TRUE(series.converged);
  EXPECT_LT(series.last_weight, ReflectionControl{}.tolerance);
  EXPECT_GT(series.generations, 2);  // images of images were made
  const auto mobility = [&](double prune) {
    ReflectionControl c;
    c.tolerance = 1e-7;
    c.prune = prune;
    const ImageSeries s = reflected_force_images(walls, source, c);
    EXPECT_TRUE(s.converged) << prune;
    return image_mobility(s, target, kMu, 10.0 * kUm);
  };
  const Eigen::Matrix2d coarse = mobility(1e-3), middle = mobility(1e-5), fine = mobility(1e-7);
  // each factor 100 in the cut shrinks the change by more than 3 (a converging series) ...
  EXPECT_LT((middle - fine).norm(), 0.3 * (coarse - fine).norm());
  // ... and the default cut is within 2 % of the converged series (its ~1 % cut error, doubled)
  const Eigen::Matrix2d m = image_mobility(series, target, kMu, 10.0 * kUm);
  EXPECT_LT((m - fine).norm(), 2e-2 * fine.norm());
}

TEST(WallReflections, ReflectedMobilityIsReciprocalToTheSeriesCut) {
  // the Neumann Green's function is symmetric; the default cut series to its ~1 % cut error
  const ChannelGeometry walls = throat(10.0 * kUm);
  const Eigen::Vector2d a(38.0 * kUm, 15.0 * kUm), b(45.0 * kUm, 21.0 * kUm);
  const Eigen::Matrix2d mab = image_mobility(reflected_force_images(walls, b), a, kMu, 10.0 * kUm);
  const Eigen::Matrix2d mba = image_mobility(reflected_force_images(walls, a), b, kMu, 10.0 * kUm);
  EXPECT_LT((mab - mba.transpose()).norm(), 1e-2 * mab.norm());
}

TEST(WallReflections, StraightChannelReflectionsAreTheStripLatticeOnly) {
  // no cylinders: the two first mirrors and the closed-form lattice, nothing else
  const ChannelGeometry walls(40.0 * kUm, 36.0 * kUm, 10.0 * kUm);
  const ImageSeries series = reflected_force_images(walls, Eigen::Vector2d(20.0 * kUm, 6.0 * kUm));
  EXPECT_EQ(series.images.size(), 2u);
  EXPECT_TRUE(series.converged);
}

TEST(WallReflections, LevelThreeResistanceInTheThroatIsSymmetricPositiveDefiniteAndAboveTheFirstImages) {
  const double H = 10.0 * kUm, d = 3.0 * kUm;
  const ChannelGeometry walls = throat(H);
  RodGeometry rod;
  rod.sphere_diameter = d;
  // the passage's rod across the throat, tilted 10 deg
  for (int k = 0; k < 4; ++k)
    rod.positions.emplace_back(42.0 * kUm + (k - 1.5) * d * std::sin(0.17), 18.0 * kUm + (k - 1.5) * d * std::cos(0.17),
                               0.5 * H);
  const UniformFlow still(walls, Eigen::Vector2d::Zero());
  auto resistance = [&](WallReflection reflection) {
    NonlocalRodModel model(HydrodynamicParameters{kMu, H, d}, ConfinementTable::default_table());
    model.set_wall_reflection(reflection);
    RodDrag drag;
    model.evaluate(rod, still, drag);
    return drag.coupled_resistance;
  };
  const Eigen::MatrixXd with = resistance(WallReflection::reflections), first = resistance(WallReflection::images);
  EXPECT_LT((with - with.transpose()).norm(), 1e-12 * with.norm());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(with);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
  // both cylinders push the fluid back: translating along the throat (x),
  // the reflections off the second cylinder add to the friction
  Eigen::VectorXd along = Eigen::VectorXd::Zero(with.rows());
  for (int i = 0; i < 4; ++i) along(3 * i) = 1.0;
  EXPECT_NE(along.dot(with * along), along.dot(first * along));
  EXPECT_EQ(wall_reflection_from_name("reflections"), WallReflection::reflections);
}

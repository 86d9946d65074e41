#include "hydro/wall_images.h"

#include "common/math_constants.h"
#include "hydro/brinkman_green.h"

#include <cmath>
#include <algorithm>
#include <complex>

namespace hsrod {

namespace {

using Complex = std::complex<double>;

// Mirror in the line y = y_wall: (F_t, F_n) -> (F_t, -F_n); the field keeps
// its kind (G(S r) = S G(r) S for the full Brinkman G too).
ForceImage mirror(const Eigen::Vector2d& x, const Eigen::Matrix2d& map, double y_wall, bool full_brinkman = true) {
  const Eigen::Matrix2d flip = Eigen::Vector2d(1.0, -1.0).asDiagonal();
  return {Eigen::Vector2d(x.x(), 2.0 * y_wall - x.y()), flip * map, full_brinkman};
}

// Circle-theorem image of a force (map `map`) at x in the cylinder c.
ForceImage circle_image(const Eigen::Vector2d& x, const Eigen::Matrix2d& map, const ZCylinder& c) {
  const Complex z0(x.x() - c.center_x, x.y() - c.center_y);
  const double a2 = c.radius * c.radius;
  const Complex z1 = a2 / std::conj(z0);
  const Complex q = -a2 / (std::conj(z0) * std::conj(z0));
  Eigen::Matrix2d t;
  t << q.real(), q.imag(), q.imag(), -q.real();
  return {Eigen::Vector2d(c.center_x + z1.real(), c.center_y + z1.imag()), t * map, false};
}

// One reflector of the method of reflections: a side wall (wall 0: y_lo,
// 1: y_hi) with the cylinders centred on it, or one other cylinder (wall -1).
struct Reflector {
  int wall = -1;
  std::vector<ZCylinder> circles;
};

std::vector<Reflector> reflectors_of(const ChannelGeometry& walls) {
  std::vector<Reflector> r = {{0, {}}, {1, {}}};
  const double on_wall = 1e-9 * walls.width();  // a centre on a side wall [m]
  for (const ZCylinder& c : walls.cylinders()) {
    if (c.radius <= 0.0) continue;
    if (std::abs(c.center_y - walls.y_lo()) <= on_wall)
      r[0].circles.push_back(c);
    else if (std::abs(c.center_y - walls.y_hi()) <= on_wall)
      r[1].circles.push_back(c);
    else
      r.push_back({-1, {c}});
  }
  return r;
}

// |map| (W / |image - source|)^2: the image's far field at the source per
// that of a unit force one channel width away [-] (the maps are |q| times
// an orthogonal matrix, so |map| = Frobenius / sqrt 2).
double weight(const ForceImage& image, const Eigen::Vector2d& source, double width) {
  const double r2 = (image.position - source).squaredNorm();
  return image.map.norm() / std::sqrt(2.0) * width * width / r2;
}

// The force map of a circle image, f' = q conj(f).
Eigen::Matrix2d circle_map(Complex q) {
  Eigen::Matrix2d t;
  t << q.real(), q.imag(), q.imag(), -q.real();
  return t;
}

// 1 / sinh^2(s), s = a + i b, in real arithmetic from E = exp(-2|a|),
// 1 - E and sin b, cos b (given, so that a caller can form them by angle
// addition from per-point phases):
//     1 / sinh^2 s = 4E [(1-E)^2 cos 2b - 4E sin^2 b - i sgn(a) (1-E^2) sin 2b] / [(1-E)^2 + 4E sin^2 b]^2,
// from sinh^2 s = (cosh 2s - 1) / 2 and |sinh s|^2 = (cosh 2a - cos 2b) / 2.
// Both brackets are sums of terms of one sign near s = 0 (no cancellation),
// and E -> 0 far from the origin (no overflow), so it holds for every s != 0.
struct Decay {
  double e, one_minus_e;  // E = exp(-2|a|) and 1 - E [-]
  explicit Decay(double a) {
    const double two_a = 2.0 * std::abs(a);
    // 1 - E without cancellation for small |a|
    one_minus_e = two_a < 0.5 ? -std::expm1(-two_a) : 1.0 - std::exp(-two_a);
    e = 1.0 - one_minus_e;
  }
};

Complex inverse_sinh_squared(double a, const Decay& d, double sin_b, double cos_b) {
  const double e = d.e, ome2 = d.one_minus_e * d.one_minus_e;
  const double sin2_b = sin_b * sin_b, sin_2b = 2.0 * sin_b * cos_b, cos_2b = 1.0 - 2.0 * sin2_b;
  const double den = ome2 + 4.0 * e * sin2_b;
  const double f = 4.0 * e / (den * den);
  const double im = f * d.one_minus_e * (1.0 + e) * sin_2b;
  return {f * (ome2 * cos_2b - 4.0 * e * sin2_b), a < 0.0 ? im : -im};
}

// 1 / w^2 without the library's complex division [1/m^2].
Complex inverse_square(Complex w) {
  const double n = std::norm(w);
  const Complex c = std::conj(w);
  return c * c / (n * n);
}

// (pi / 2W)^2 / sinh^2(pi w / 2W) - 1 / w^2 [1/m^2], the lattice sum of
// 1 / (w - 2 k W i)^2 over k without k = 0 (Laurent series near w = 0,
// where the two terms cancel).
Complex lattice_without_origin(Complex w, double width) {
  const double k = kPi / (2.0 * width);
  const Complex s = k * w;
  if (std::norm(s) < 1e-4) {
    const Complex s2 = s * s;
    return k * k * (-1.0 / 3.0 + s2 / 15.0 - 2.0 * s2 * s2 / 189.0);
  }
  return k * k * inverse_sinh_squared(s.real(), Decay(s.real()), std::sin(s.imag()), std::cos(s.imag())) -
         inverse_square(w);
}

// u - i v = c (A f + B conj f) as a 2x2 tensor per unit (F_x, F_y), c = H / (24 pi mu).
Eigen::Matrix2d complex_tensor(Complex a, Complex b, double viscosity, double gap_height) {
  const double c = gap_height / (24.0 * kPi * viscosity);
  const Complex fx = c * (a + b), fy = c * Complex(0.0, 1.0) * (a - b);
  Eigen::Matrix2d m;
  m << fx.real(), fy.real(), -fx.imag(), -fy.imag();
  return m;
}

// (cos, sin) of pi (y - y_lo) / (2W): the phase of a point in the strip's
// lattice, from which the lattice's field between two points is formed by
// angle addition (no transcendental function per pair but one exponential).
LatticePhase lattice_phase(double y, double y_lo, double width) {
  const double b = kPi / (2.0 * width) * (y - y_lo);
  return {std::cos(b), std::sin(b)};
}

// The dipoles of an image at `at` [m] (phase p) and of all its mirror images
// in the strip's walls, per unit image force [m/(N s)], at x_target (phase t):
// sum_k 1 / (w - 2kWi)^2 = (pi / 2W)^2 / sinh^2(pi w / 2W) for the image's
// lattice (w = z - z0) and its mirror's (w' = z - z0', z0' mirrored in y_lo),
// whose imaginary parts pi Im(w) / 2W are t - p and t + p.
Eigen::Matrix2d strip_lattice(double width, const Eigen::Vector2d& x_target, const LatticePhase& t,
                              const Eigen::Vector2d& at, const LatticePhase& p, double viscosity, double gap_height) {
  const double k = kPi / (2.0 * width), a = k * (x_target.x() - at.x());
  const Decay d(a);
  const double cc = t.cos * p.cos, ss = t.sin * p.sin, sc = t.sin * p.cos, cs = t.cos * p.sin;
  return complex_tensor(k * k * inverse_sinh_squared(a, d, sc - cs, cc + ss),
                        k * k * inverse_sinh_squared(a, d, sc + cs, cc - ss), viscosity, gap_height);
}

}  // namespace

Eigen::Matrix2d strip_lattice_remainder(double y_lo, double width, const Eigen::Vector2d& x_target,
                                        const Eigen::Vector2d& x_source, double viscosity, double gap_height) {
  // u - i v = c (A f + B conj f), c = H / (24 pi mu): A the source's lattice
  // z0 + 2kWi (k != 0), B its mirror's z0' + 2kWi without the first mirrors
  // k = 0 (in y_lo) and k = 1 (in y_hi), which are explicit images.
  const Complex z(x_target.x(), x_target.y()), z0(x_source.x(), x_source.y());
  const Complex z0m(x_source.x(), 2.0 * y_lo - x_source.y());
  const Complex hi = z0m + Complex(0.0, 2.0 * width);
  const Complex a = lattice_without_origin(z - z0, width);
  Complex b = lattice_without_origin(z - z0m, width);
  b -= inverse_square(z - hi);
  return complex_tensor(a, b, viscosity, gap_height);
}

namespace {

// A head of the series: an image evaluated with its whole strip lattice.
struct Head {
  ForceImage image;
  int reflector = -1;  // the reflector that made it (-1: the source)
};

// Copies of a lattice farther than this many radii from a cylinder's centre
// have their circle images gathered into one dipole at the centre: the
// image of copy k sits a^2 / |z_k| <= a / 12 from it, which moves its field
// on the cylinder by <= 2 a / |z_k| = 1/6 of the gathered part (at 6 radii
// the throat's normal-velocity residual stalled at 5e-3; at 12 it falls
// with `prune`, test_wall_reflections.cpp).
constexpr double kGatherRadii = 12.0;

// The series' cut of light images: a child lighter than `prune` (weight())
// is dropped. |circle_map(q) t| = |q| |t| (circle_map(q) / |q| is
// orthogonal), so a child's weight is known before its map is formed; only
// those certainly below the cut (by a margin far above round-off) are not
// formed, the rest are weighed exactly by the caller.
struct Cut {
  Eigen::Vector2d source;  // the series' source [m]
  double width, prune;     // the strip's width [m], ReflectionControl::prune [-]
  bool below(double q_abs, double t_norm, const Eigen::Vector2d& at) const {
    constexpr double kMargin = 1.0 - 1e-9;  // round-off of weight() is ~1e-15
    return q_abs * t_norm * width * width < kMargin * prune * (at - source).squaredNorm();
  }
};

// The circle images in cylinder c of the lattice copies z + 2 k W i (map t)
// of a head: the near copies one by one, the far ones gathered (closed-form
// lattice sum minus the near terms). `skip_own`: the copy k = 0 is (the
// mirror partner of) the head's own maker and is not reflected again.
void circle_images_of_lattice(Complex z, const Eigen::Matrix2d& t, const ZCylinder& c, double width, bool skip_own,
                              int reflector, const Cut& cut, std::vector<Head>& out) {
  const Complex w0 = z - Complex(c.center_x, c.center_y);
  const double a2 = c.radius * c.radius, reach = kGatherRadii * c.radius;
  const double t_norm = t.norm() / std::sqrt(2.0);  // as in weight()
  Complex far = lattice_without_origin(w0, width);  // sum over k != 0 of 1 / (w0 + 2kWi)^2
  const int k_lo = static_cast<int>(std::ceil((-reach - w0.imag()) / (2.0 * width)));
  const int k_hi = static_cast<int>(std::floor((reach - w0.imag()) / (2.0 * width)));
  for (int k = std::min(k_lo, 0); k <= std::max(k_hi, 0); ++k) {
    const Complex zk = w0 + Complex(0.0, 2.0 * k * width);
    if (k != 0) far -= inverse_square(zk);
    const double n = std::norm(zk);
    if ((k == 0 && skip_own) || n <= a2) continue;
    // image point a^2 / conj(zk), force map q = -a^2 / conj(zk)^2
    const Complex inv = zk / n;  // 1 / conj(zk)
    const Eigen::Vector2d at(c.center_x + a2 * inv.real(), c.center_y + a2 * inv.imag());
    if (cut.below(a2 / n, t_norm, at)) continue;
    out.push_back({{at, circle_map(-a2 * inv * inv) * t, false, true}, reflector});
  }
  const Eigen::Vector2d centre(c.center_x, c.center_y);
  if (cut.below(a2 * std::abs(far), t_norm, centre)) return;
  out.push_back({{centre, circle_map(-a2 * std::conj(far)) * t, false, true}, reflector});
}

// The series of reflected_force_images without the images' lattice phases.
ImageSeries reflection_series(const ChannelGeometry& walls, const Eigen::Vector2d& x_source,
                              const ReflectionControl& control) {
  ImageSeries series;
  series.source = x_source;
  series.y_lo = walls.y_lo();
  series.width = walls.width();
  const double W = series.width;
  const std::vector<Reflector> reflectors = reflectors_of(walls);
  // the source's first mirrors, full Brinkman (excluded from its lattice remainder)
  double first = 0.0;
  for (double y_wall : {walls.y_lo(), walls.y_hi()}) {
    series.images.push_back(mirror(x_source, Eigen::Matrix2d::Identity(), y_wall));
    first += weight(series.images.back(), x_source, W);
  }
  const Eigen::Matrix2d flip = Eigen::Vector2d(1.0, -1.0).asDiagonal();
  const Cut cut{x_source, W, control.prune};
  std::vector<Head> generation = {{{x_source, Eigen::Matrix2d::Identity(), false, true}, -1}}, next, children;
  for (int g = 1; g <= control.max_generations && !generation.empty(); ++g) {
    next.clear();
    double total = 0.0;
    for (const Head& h : generation)
      for (int r = 0; r < static_cast<int>(reflectors.size()); ++r)
        for (const ZCylinder& c : reflectors[r].circles) {
          children.clear();
          const Eigen::Vector2d& p = h.image.position;
          // a wall's cylinder: one copy of each mirror pair in that wall (the
          // other's image is its mirror, in the same lattice); another cylinder: both sets
          circle_images_of_lattice(Complex(p.x(), p.y()), h.image.map, c, W, r == h.reflector, r, cut, children);
          // (the mirror partner of a cylinder's own image is a wall's, so reflected in it)
          if (reflectors[r].wall < 0)
            circle_images_of_lattice(Complex(p.x(), 2.0 * walls.y_lo() - p.y()), flip * h.image.map, c, W, false, r,
                                     cut, children);
          for (const Head& child : children) {
            const double w = weight(child.image, x_source, W);
            if (w < control.prune) continue;
            series.images.push_back(child.image);
            total += w;
            next.push_back(child);
          }
        }
    series.generations = g;
    if (static_cast<int>(series.images.size()) > control.max_images) return series;  // not converged
    if (g == 1) first += total;
    series.last_weight = total / first;
    if (g > 1 && series.last_weight < control.tolerance) {
      series.converged = true;
      return series;
    }
    generation.swap(next);
  }
  series.converged = generation.empty();
  return series;
}

}  // namespace

ImageSeries reflected_force_images(const ChannelGeometry& walls, const Eigen::Vector2d& x_source,
                                   const ReflectionControl& control) {
  ImageSeries series = reflection_series(walls, x_source, control);
  series.phases.reserve(series.images.size());
  for (const ForceImage& image : series.images)
    series.phases.push_back(lattice_phase(image.position.y(), series.y_lo, series.width));
  return series;
}

Eigen::Matrix2d image_mobility(const ImageSeries& series, const Eigen::Vector2d& x_target, double viscosity,
                               double gap_height) {
  Eigen::Matrix2d m = strip_lattice_remainder(series.y_lo, series.width, x_target, series.source, viscosity, gap_height);
  const LatticePhase t = lattice_phase(x_target.y(), series.y_lo, series.width);
  for (std::size_t j = 0; j < series.images.size(); ++j) {
    const ForceImage& image = series.images[j];
    const Eigen::Vector2d r = x_target - image.position;
    if (r.squaredNorm() <= 0.0) continue;
    if (image.strip_lattice)
      m += strip_lattice(series.width, x_target, t, image.position, series.phases[j], viscosity, gap_height) *
           image.map;
    else
      m += (image.full_brinkman ? brinkman_green_function(r, viscosity, gap_height)
                                : hele_shaw_dipole(r, viscosity, gap_height)) *
           image.map;
  }
  return m;
}

std::vector<ForceImage> force_images(const ChannelGeometry& walls, const Eigen::Vector2d& x) {
  const Eigen::Matrix2d one = Eigen::Matrix2d::Identity();
  std::vector<ForceImage> images = {mirror(x, one, walls.y_lo()), mirror(x, one, walls.y_hi())};
  const double on_wall = 1e-9 * walls.width();  // a centre on a side wall [m]
  for (const ZCylinder& c : walls.cylinders()) {
    if (c.radius <= 0.0) continue;
    images.push_back(circle_image(x, one, c));
    // a cylinder centred on a side wall: also the image of the force's mirror there
    for (int w = 0; w < 2; ++w)
      if (std::abs(c.center_y - (w == 0 ? walls.y_lo() : walls.y_hi())) <= on_wall) {
        const ForceImage& m = images[w];
        images.push_back(circle_image(m.position, m.map, c));
      }
  }
  return images;
}

Eigen::Matrix2d hele_shaw_dipole(const Eigen::Vector2d& offset, double viscosity, double gap_height) {
  const double r2 = offset.squaredNorm();
  const Eigen::Vector2d e = offset / std::sqrt(r2);
  return gap_height / (24.0 * kPi * viscosity * r2) * (2.0 * e * e.transpose() - Eigen::Matrix2d::Identity());
}

Eigen::Matrix2d image_mobility(const ChannelGeometry& walls, const Eigen::Vector2d& x_target,
                               const Eigen::Vector2d& x_source, double viscosity, double gap_height) {
  Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
  for (const ForceImage& image : force_images(walls, x_source)) {
    const Eigen::Vector2d r = x_target - image.position;
    if (r.squaredNorm() <= 0.0) continue;
    m += (image.full_brinkman ? brinkman_green_function(r, viscosity, gap_height)
                              : hele_shaw_dipole(r, viscosity, gap_height)) *
         image.map;
  }
  return m;
}

}  // namespace hsrod

#include "hydro/wall_images.h"

#include "common/math_constants.h"
#include "hydro/brinkman_green.h"

#include <cmath>
#include <complex>

namespace hsrod {

namespace {

using Complex = std::complex<double>;

// Mirror in the line y = y_wall: (F_t, F_n) -> (F_t, -F_n).
ForceImage mirror(const Eigen::Vector2d& x, const Eigen::Matrix2d& map, double y_wall) {
  const Eigen::Matrix2d flip = Eigen::Vector2d(1.0, -1.0).asDiagonal();
  return {Eigen::Vector2d(x.x(), 2.0 * y_wall - x.y()), flip * map, true};
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

}  // namespace

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

#include "flow/background_flow.h"

namespace hsrod {

double BackgroundFlow::gap_profile(double z, double gap_height) {
  if (z < 0.0 || z > gap_height) return 0.0;
  const double s = z / gap_height;
  return 6.0 * s * (1.0 - s);
}

Eigen::Vector3d BackgroundFlow::velocity3d(double x, double y, double z) const {
  const double f = gap_profile(z, geometry().gap_height());
  if (f == 0.0) return Eigen::Vector3d::Zero();
  const Eigen::Vector2d u = velocity(x, y);
  return Eigen::Vector3d(f * u.x(), f * u.y(), 0.0);
}

Eigen::Matrix3d BackgroundFlow::velocity_gradient3d(double x, double y, double z) const {
  const double h = geometry().gap_height();
  Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
  if (z < 0.0 || z > h) return g;
  const double f = gap_profile(z, h);
  const double df_dz = 6.0 * (1.0 - 2.0 * z / h) / h;  // [1/m]
  g.topLeftCorner<2, 2>() = f * velocity_gradient(x, y);
  const Eigen::Vector2d u = velocity(x, y);
  g(0, 2) = df_dz * u.x();
  g(1, 2) = df_dz * u.y();
  return g;
}

}  // namespace hsrod

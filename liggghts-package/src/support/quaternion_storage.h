// Per-atom orientations are stored as four doubles (w, x, y, z) in LIGGGHTS
// arrays; these two helpers convert between that storage and Eigen, in one
// place for every file of fix rod/bonds.
#pragma once

#include <Eigen/Geometry>

namespace hsrod_glue {

inline Eigen::Quaterniond to_quaternion(const double *q) { return Eigen::Quaterniond(q[0], q[1], q[2], q[3]); }

inline void store_quaternion(const Eigen::Quaterniond &q, double *out) {
  out[0] = q.w();
  out[1] = q.x();
  out[2] = q.y();
  out[3] = q.z();
}

}  // namespace hsrod_glue

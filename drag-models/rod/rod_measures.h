// The paper's rod measures (Braesel et al., Soft Matter 2024, Sec. 2.3).
#pragma once

#include <Eigen/Core>

#include <vector>

namespace hsrod {

// Eq. (1): in-plane angle of the rod from the ends' centres, Delta = end1 - end2.
// 0 = perpendicular to the flow (along y); result in radians, in (-pi, pi].
double rod_angle_eq1(const Eigen::Vector2d& end1, const Eigen::Vector2d& end2);

// Eq. (2): largest distance of a sphere centre from the line through the two
// ends, divided by the rod length L_Rod [-]. `centres` are the in-plane
// centres of the rod's sections.
double relative_deflection_eq2(const Eigen::Vector2d& end1, const Eigen::Vector2d& end2,
                               const std::vector<Eigen::Vector2d>& centres, double rod_length);

}  // namespace hsrod

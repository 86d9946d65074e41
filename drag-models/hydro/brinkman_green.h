// Depth-averaged (Brinkman / Hele-Shaw) Green's function: the gap-averaged
// velocity induced at planform offset r by a point force F [N] exerted on the
// fluid of a slit of gap H,
//     mu H (lap u - u / l^2) - grad(H p) + F delta(r) = 0,  div u = 0,
// with the Brinkman screening length l = H / sqrt(12). In 2-D:
//     u = F.(A(R) I + B(R) rhat rhat) / (2 pi mu H),   R = r / l,
//     A = K0(R) + K1(R)/R - 1/R^2,   B = -K0(R) - 2 K1(R)/R + 2/R^2,
// the screened 2-D Stokeslet: logarithmic (2-D Stokes) for r << l and the
// Hele-Shaw potential dipole F H (2 rhat rhat - I) / (24 pi mu r^2) for r >> l.
#pragma once

#include <Eigen/Core>

namespace hsrod {

// 2x2 tensor G with u = G F [m/(N s)]; offset r != 0 [m].
Eigen::Matrix2d brinkman_green_function(const Eigen::Vector2d& offset, double viscosity, double gap_height);

}  // namespace hsrod

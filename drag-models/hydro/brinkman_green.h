// Depth-averaged (Brinkman / Hele-Shaw) Green's function: the gap-averaged
// velocity induced at planform offset r by a point force F [N] exerted on the
// fluid of a slit of gap H,
//     mu H (lap u - u / l^2) - grad(H p) + F delta(r) = 0,  div u = 0,
// with the Brinkman screening length l = H / sqrt(12). In 2-D:
//     u = F.(A(R) I + B(R) rhat rhat) / (2 pi mu H),   R = r / l,
//     A = K0(R) + K1(R)/R - 1/R^2,   B = -K0(R) - 2 K1(R)/R + 2/R^2,
// the screened 2-D Stokeslet: logarithmic (2-D Stokes) for r << l and the
// Hele-Shaw potential dipole F H (2 rhat rhat - I) / (24 pi mu r^2) for r >> l.
//
// The scalar kernels A(R), B(R) are evaluated from a table built once per
// process (quintic Hermite in ln R from the Bessel form and its first two
// derivatives, 1e-3 <= R < 40): a sphere pair then costs a logarithm and two
// degree-5 polynomials instead of two modified Bessel functions (~3 us each
// in libstdc++). Its difference from the Bessel form, relative to |A| + |B|
// (the size of the tensor; A alone changes sign), is below
// brinkman_kernel_table_error(R) = 1e-10 + 4.4e-16 / R^2: the interpolation
// error is <= 2e-11 over the whole range, the second term is the Bessel
// form's own rounding, K1/R cancelling 1/R^2 at small R (2 ulp of 1/R^2).
// Checked at setup on every interval's mid-point and in
// test_brinkman_green.cpp on random separations.
#pragma once

#include <Eigen/Core>

namespace hsrod {

// Scalar kernels of G at reduced separation R = r / l [-].
struct BrinkmanKernels {
  double a;  // coefficient of I [-]
  double b;  // coefficient of rhat rhat [-]
};

// Stated bound of |table - Bessel form| relative to |A| + |B| at R [-].
inline double brinkman_kernel_table_error(double reduced_separation) {
  return 1e-10 + 4.4e-16 / (reduced_separation * reduced_separation);
}

// A, B from the table (R > 0 [-]); below R = 1e-3 the small-R expansion,
// from R = 40 the far field -1/R^2, 2/R^2 (the Bessel terms are < 1e-15 of it).
BrinkmanKernels brinkman_green_kernels(double reduced_separation);

// A, B from std::cyl_bessel_k (the reference the table is built from and
// tested against; same small-R expansion below R = 1e-3).
BrinkmanKernels brinkman_green_kernels_bessel(double reduced_separation);

// 2x2 tensor G with u = G F [m/(N s)]; offset r != 0 [m].
Eigen::Matrix2d brinkman_green_function(const Eigen::Vector2d& offset, double viscosity, double gap_height);

}  // namespace hsrod

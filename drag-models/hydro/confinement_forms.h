// Functional forms of the confinement coefficients in beta = d / H and the
// rod's sphere count n, shared by the built-in table
// (default_coefficients.cpp) and the calibration fit that determines their
// parameters (calibration/core/confinement_fit.h, hsrod_fit_campaign).
// Each form has its known limit built in.
#pragma once

#include <cmath>
#include <vector>

namespace hsrod::confinement_form {

// Lone sphere's friction over 3 pi mu d: Faxen's mid-plane series (Happel &
// Brenner 1965, eq. 7-4.28) with its leading coefficient p0, its beta^3
// coefficient p3 and its beta^5 coefficient p5 free (Faxen: 1.004, 0.418,
// 0.169): 1 / (1 - p0 beta + p3 beta^3 + 0.21 beta^4 - p5 beta^5); 1 as
// beta -> 0. (p5 free since the campaign reached beta 0.75: with p0, p3
// alone the resolved lone spheres of beta 0.1-0.75 were met within 1.4 %,
// with p5 within 0.7 %.)
inline double sphere_friction(double beta, double p0, double p3 = 0.418, double p5 = 0.169) {
  const double b3 = beta * beta * beta;
  return 1.0 / (1.0 - p0 * beta + p3 * b3 + 0.21 * b3 * beta - p5 * b3 * beta * beta);
}

// Lone sphere's force-free velocity over the gap-mean velocity:
// 3/2 (1 - p0 beta^2 - p2 beta^4) (Faxen's law in the parabolic gap
// profile: p0 = 1/3, p2 = 0); the mid-plane velocity 3/2 as beta -> 0.
inline double sphere_driving(double beta, double p0, double p2 = 0.0) {
  const double b2 = beta * beta;
  return 1.5 * (1.0 - p0 * b2 - p2 * b2 * b2);
}

inline double polynomial(const double* p, int np, double beta) {
  double v = 0.0, b = 1.0;
  for (int k = 0; k < np; ++k, b *= beta) v += p[k] * b;
  return v;
}

// n-law of a straight rod of n spheres: the per-sphere coefficient is the
// infinite rod's c_inf plus two ends that carry the lone sphere's excess
// (resistive-force theory with end corrections), plus a term growing with
// the rod's length for a rod moving across its axis (the depth-averaged
// pressure build-up in front of the chain, Bhattacharya et al. 2005), plus
// the 3-D shielding of neighbours closer than ~H (slender-body theory: the
// disturbance of a sphere decays like 1/r up to ~H, so the shielding of a
// sphere sums to ~ln n and the ends' excess fades like ln(n)/n, not 1/n):
//     c(n) = c_inf + (c_1 - c_inf - g)/n + g n + e ln(n)/n,   c(1) = c_1,
// g = growth coefficient (0 along the axis), e = shielding coefficient (the
// resolved rods need it along the axis: without it the per-sphere friction
// of N = 2, 5, 10 missed by -3, -2, +3 % at every beta and N = 15, 20 were
// predicted +3.1, +4.1 % high; with it -0.0, -0.1 %).
inline double rod_n_law(double c_inf, double c_1, double g, int n, double e = 0.0) {
  return c_inf + (c_1 - c_inf - g) / n + g * n + e * std::log(static_cast<double>(n)) / n;
}
// c_inf from the coefficient c_m of a rod of m spheres (inverse of rod_n_law).
inline double rod_n_law_asymptote(double c_m, double c_1, double g, int m, double e = 0.0) {
  return (m * c_m - c_1 + g - m * m * g - e * std::log(static_cast<double>(m))) / (m - 1);
}
// Growth coefficient across the axis: g = beta^2 (k_0 + k_1 beta + ...)
// (k fitted, see perpendicular_growth in confinement_coefficients.h; one
// term k_0 is the constant-k form).
inline double rod_growth(double beta, const double* k, int nk) { return beta * beta * polynomial(k, nk, beta); }

// Force-free velocity of a straight rod of n spheres (over the gap-mean
// velocity): its held load per sphere over its friction per sphere, both
// with the n-law, the held load about the infinite rod's c_inf lambda_inf
// with the lone sphere's lambda_s at n = 1, its own growth g_held lambda_s
// (the pressure build-up in front of a chain held across the flow need not
// be that of the chain dragged through fluid at rest, g) and the friction's
// shielding e carried at the lone sphere's velocity (e lambda_s):
//   lambda(n) = rod_n_law(c_inf lambda_inf, lambda_s, g_held lambda_s, n, e lambda_s)
//               / rod_n_law(c_inf, 1, g, n, e);
// lambda(1) = lambda_s, lambda(n -> inf) = lambda_inf when g = g_held = 0.
inline double rod_velocity(double c_inf, double lambda_inf, double lambda_s, double g, double g_held, int n,
                           double e = 0.0) {
  return rod_n_law(c_inf * lambda_inf, lambda_s, g_held * lambda_s, n, e * lambda_s) / rod_n_law(c_inf, 1.0, g, n, e);
}

// Infinite rod's force-free velocity over the gap-mean velocity:
// 3/2 (1 - beta (q0 + q1 beta + ...)); 3/2 as beta -> 0 (Berthet et al. 2013).
inline double rod_driving_inf(double beta, const double* q, int nq) { return 1.5 * (1.0 - beta * polynomial(q, nq, beta)); }

}  // namespace hsrod::confinement_form

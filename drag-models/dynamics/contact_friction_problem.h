// The friction forces of a step's rubbing contact points at the step's end
// velocities (backward Euler; OverdampedRodSolver::step).
//
// The step was taken with each point's friction linearised as a secant
// -c s about a previous slip s. Its own matrix answers extra tangential
// loads g at the points with slips v = w0 + M g, where w0 are the slips of
// the step as taken and M the contacts' Delassus operator (the mobility
// between the points' tangent directions, from the kept factorisation).
// The friction is right where the applied correction equals the law minus
// the secant:  g = f(v) + c v,  with f the regularised Coulomb law
// (wall_contact.h: -F v / max(|v|, v_s), F = mu F_n). With g0 the
// correction already in the step, the slips solve
//     v = w0 + M (f(v) + c v - g0),
// the stationary point of the convex
//     Q(v) = 1/2 (v - w0)^T M^-1 (v - w0) - 1/2 sum c_p |v_p|^2 + g0 . v + sum Psi_p(v_p)
// (Psi the law's potential: F |v|^2 / (2 v_s) below v_s, F (|v| - v_s / 2)
// above; convex while the frictionless mobility M^-1 - c I is positive
// definite). Newton's method with an Armijo line search on Q converges from
// any start, also across the law's kink at v_s where plain (semi-smooth)
// Newton on the equation cycles.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace hsrod {

// One rubbing point of the problem (two tangent unknowns).
struct FrictionPointLaw {
  double sliding = 0.0;  // F = mu F_n, the sliding friction [N]
  double secant = 0.0;   // c, the step's linearisation of the law [N s/m]
};

// The correction loads g (2 per point, in the points' tangent bases) [N]
// that make each point's friction the law at its slip v. `delassus` M
// [m/(N s)] (2k x 2k, symmetrised here), `slips` w0 [m/s] and `applied` g0
// [N] (2k each), `slip_velocity` v_s [m/s]; Newton stops when the gradient
// of Q is below `force_tolerance` [N]. `slips_out`: the solved v (optional).
Eigen::VectorXd contact_friction_correction(const Eigen::MatrixXd& delassus, const Eigen::VectorXd& slips,
                                            const Eigen::VectorXd& applied, const std::vector<FrictionPointLaw>& points,
                                            double slip_velocity, double force_tolerance,
                                            Eigen::VectorXd* slips_out = nullptr);

}  // namespace hsrod

#include "dynamics/contact_friction_problem.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace hsrod {

Eigen::VectorXd contact_friction_correction(const Eigen::MatrixXd& delassus, const Eigen::VectorXd& w0,
                                            const Eigen::VectorXd& g0, const std::vector<FrictionPointLaw>& points,
                                            double v_s, double force_tolerance, Eigen::VectorXd* slips_out) {
  const int count = static_cast<int>(points.size());
  // M is symmetrised: the step's matrix is symmetric up to the bonds'
  // finite-rotation terms.
  Eigen::MatrixXd inverse = delassus.partialPivLu().inverse();
  inverse = (0.5 * (inverse + inverse.transpose())).eval();
  const auto potential = [&](const Eigen::VectorXd& x) {
    const Eigen::VectorXd d = x - w0;
    double q = 0.5 * d.dot(inverse * d) + g0.dot(x);
    for (int p = 0; p < count; ++p) {
      const double speed = x.segment<2>(2 * p).norm(), F = points[p].sliding;
      q += -0.5 * points[p].secant * speed * speed +
           (speed <= v_s ? F * speed * speed / (2.0 * v_s) : F * (speed - 0.5 * v_s));
    }
    return q;
  };
  const auto gradient = [&](const Eigen::VectorXd& x, Eigen::VectorXd& out, Eigen::MatrixXd& hessian) {
    out = inverse * (x - w0) + g0;
    hessian = inverse;
    for (int p = 0; p < count; ++p) {
      const Eigen::Vector2d s = x.segment<2>(2 * p);
      const double speed = s.norm(), F = points[p].sliding;
      out.segment<2>(2 * p) += (F / std::max(speed, v_s) - points[p].secant) * s;
      Eigen::Matrix2d d = (F / std::max(speed, v_s) - points[p].secant) * Eigen::Matrix2d::Identity();
      if (speed > v_s) d -= F / (speed * speed * speed) * s * s.transpose();
      hessian.block<2, 2>(2 * p, 2 * p) += d;
    }
  };
  Eigen::VectorXd v = w0, grad, trial, step;
  Eigen::MatrixXd hessian;
  double q = potential(v);
  for (int newton = 0; newton < 100; ++newton) {
    gradient(v, grad, hessian);
    if (grad.norm() <= force_tolerance) break;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(hessian);
    step = ldlt.info() == Eigen::Success ? Eigen::VectorXd(ldlt.solve(-grad)) : Eigen::VectorXd(-grad);
    if (!(step.dot(grad) < 0.0) || !step.allFinite()) step = -grad / std::max(hessian.diagonal().maxCoeff(), 1e-300);
    double lambda = 1.0, trial_q = HUGE_VAL;
    for (; lambda > 1e-12; lambda *= 0.5) {
      trial = v + lambda * step;
      trial_q = potential(trial);
      if (trial_q <= q + 1e-4 * lambda * step.dot(grad)) break;
    }
    if (!(trial_q < q)) break;
    v = trial;
    q = trial_q;
  }
  Eigen::VectorXd force(2 * count);
  for (int p = 0; p < count; ++p) {
    const Eigen::Vector2d s = v.segment<2>(2 * p);
    force.segment<2>(2 * p) = (points[p].secant - points[p].sliding / std::max(s.norm(), v_s)) * s;
  }
  if (slips_out) *slips_out = v;
  return force;
}

}  // namespace hsrod

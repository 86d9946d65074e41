#include "rod/stability_limits.h"
#include "common/math_constants.h"

#include "rod/rod_linearisation.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace hsrod {

double SphereMaterial::mass() const { return density * kPi * diameter * diameter * diameter / 6.0; }

double SphereMaterial::moment_of_inertia() const { return mass() * diameter * diameter / 10.0; }

RodStabilityLimits compute_stability_limits(const RodLayout& layout, const SphereMaterial& sphere,
                                            const BeamBondMaterial& bond, double viscosity, bool with_damping) {
  RodStabilityLimits lim;
  const double m = sphere.mass();
  const double inertia = sphere.moment_of_inertia();
  const double shear_modulus = sphere.youngs_modulus / (2.0 * (1.0 + sphere.poisson_ratio));
  lim.rayleigh_time = kPi * 0.5 * sphere.diameter * std::sqrt(sphere.density / shear_modulus) /
                      (0.1631 * sphere.poisson_ratio + 0.8766);
  const double spacing = layout.bonds.empty()
                             ? sphere.diameter
                             : (layout.spheres[layout.bonds[0].second].position -
                                layout.spheres[layout.bonds[0].first].position).norm();
  const auto k = BeamBondStiffness::from_material(bond, spacing);
  lim.axial_bond_time = std::sqrt(m / k.axial);
  lim.bending_bond_time = std::sqrt(inertia / k.bending);
  if (viscosity > 0.0) lim.stokes_relaxation_time = m / (3.0 * kPi * viscosity * sphere.diameter);

  const Eigen::MatrixXd stiffness = linearised_bond_stiffness(layout, bond);
  const Eigen::VectorXd mass_diagonal = rod_mass_diagonal(layout, sphere);
  // Symmetric scaling M^-1/2 K M^-1/2 turns the generalised problem into a standard one.
  const Eigen::VectorXd inv_sqrt_mass = mass_diagonal.cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd scaled = inv_sqrt_mass.asDiagonal() * stiffness * inv_sqrt_mass.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(scaled, Eigen::EigenvaluesOnly);
  const double omega2 = eig.eigenvalues().maxCoeff();
  // E ~ 1e300 Pa overflows k / m: every limit would read 0 s and the run
  // would go on with nonsense. Physical moduli are < ~1e12 Pa.
  if (!(std::isfinite(omega2) && omega2 > 0.0 && std::isfinite(std::sqrt(omega2)))) {
    char msg[384];
    std::snprintf(msg, sizeof(msg),
                  "youngs_modulus %g Pa gives bonds whose highest frequency sqrt(k/m) is not representable in double "
                  "precision (spheres of d = %g m, rho = %g kg/m3); physical moduli are below ~1e12 Pa",
                  sphere.youngs_modulus, sphere.diameter, sphere.density);
    throw std::invalid_argument(msg);
  }
  lim.highest_bond_frequency = std::sqrt(std::max(omega2, 0.0));
  lim.explicit_bond_limit = lim.highest_bond_frequency > 0.0 ? 2.0 / lim.highest_bond_frequency : 0.0;
  lim.damping_included = with_damping || !(bond.damping_ratio > 0.0);
  if (with_damping && bond.damping_ratio > 0.0 && lim.explicit_bond_limit > 0.0) {
    // Bond dashpots, evaluated at LIGGGHTS' half-step velocities, lower the
    // limit. The reduction factor converges fast with rod length: take it
    // from the first (up to) 8 spheres' worth of rod, where the dense
    // one-step map stays small.
    RodLayout shorter = layout;
    if (layout.spheres.size() > 8) {
      shorter.spheres.resize(8);
      shorter.bonds.clear();
      for (const auto& b : layout.bonds)
        if (b.first < 8 && b.second < 8) shorter.bonds.push_back(b);
    }
    const Eigen::MatrixXd k8 = linearised_bond_stiffness(shorter, bond);
    const Eigen::VectorXd m8 = rod_mass_diagonal(shorter, sphere);
    const Eigen::MatrixXd c8 = linearised_bond_damping(shorter, bond, sphere);
    const double damped = velocity_verlet_limit(k8, c8, m8);
    const double undamped = velocity_verlet_limit(k8, Eigen::MatrixXd::Zero(k8.rows(), k8.cols()), m8);
    lim.explicit_bond_limit *= damped / undamped;
  }
  return lim;
}

std::string RodStabilityLimits::table(double timestep) const {
  auto ratio = [timestep](double t) { return t > 0.0 ? timestep / t : 0.0; };
  auto row = [&ratio](const char* name, double t) {
    char line[128];
    std::snprintf(line, sizeof(line), "  %-35s%-12.4g  %.3g\n", name, t, ratio(t));
    return std::string(line);
  };
  std::string out = "  time scale                         value [s]     dt/value\n";
  out += row("Rayleigh (Hertz contact)", rayleigh_time);
  out += row("axial bond sqrt(m/k_n)", axial_bond_time);
  out += row("bending bond sqrt(I_s/k_b)", bending_bond_time);
  // Without a viscosity there is no Stokes relaxation time: no row (a
  // "Stokes relaxation 0" row would read as a zero time scale).
  if (stokes_relaxation_time > 0.0) out += row("Stokes relaxation m/(3 pi mu d)", stokes_relaxation_time);
  out += row("explicit bond limit 2/omega_max", explicit_bond_limit);
  return out;
}

}  // namespace hsrod

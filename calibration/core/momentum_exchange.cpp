// hsrod calibration: momentum exchange of coupled runs (see momentum_exchange.h).
#include "common/math_constants.h"
#include "momentum_exchange.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <utility>

namespace hsrod::calib {

namespace {
using hsrod::kPi;
}

namespace {
// roots of z^2 - A z + B = 0 of the recurrence (momentum_exchange.h)
std::pair<std::complex<double>, std::complex<double>> exchange_roots(const ExchangeModel& m) {
  if (!(m.mass > 0.0) || !(m.dt_couple > 0.0) || m.drag < 0.0 || m.ksl < 0.0 ||
      m.virtual_mass < 0.0 || m.added_mass < 0.0)
    throw std::invalid_argument("exchange_spectral_radius: need m_p, dt_c > 0 and zeta, Ksl, m_a, m_v >= 0");
  const double mstar = m.mass + m.virtual_mass;  // DEM mass [kg]
  // phi = integral over the interval of exp(-Ksl t/m*)/m* dt  [s/kg]
  const double x = m.ksl * m.dt_couple / mstar;
  const double phi = x > 1e-12 ? -std::expm1(-x) / m.ksl : m.dt_couple / mstar;
  const double D = (m.virtual_mass - m.added_mass) / m.dt_couple;  // [kg/s]
  const double A = 1.0 - phi * m.drag + phi * D;
  const double B = phi * D;
  const std::complex<double> disc = std::sqrt(std::complex<double>(A * A - 4.0 * B, 0.0));
  return {0.5 * (A + disc), 0.5 * (A - disc)};
}

bool oscillatory(const std::complex<double>& z) {
  return std::abs(z.imag()) > 1e-12 * std::abs(z) || z.real() < 0.0;
}
}  // namespace

double exchange_spectral_radius(const ExchangeModel& m) {
  const auto [z1, z2] = exchange_roots(m);
  return std::max(std::abs(z1), std::abs(z2));
}

double exchange_oscillation(const ExchangeModel& m) {
  const auto [z1, z2] = exchange_roots(m);
  double o = 0.0;
  if (oscillatory(z1)) o = std::max(o, std::abs(z1));
  if (oscillatory(z2)) o = std::max(o, std::abs(z2));
  return o;
}

double acceleration_reaction_coeff(double d, double h, double nu, double dt_couple) {
  if (!(d > 0.0) || h < 0.0 || nu < 0.0 || dt_couple < 0.0)
    throw std::invalid_argument("acceleration_reaction_coeff: need d > 0 and h, nu, dt_c >= 0");
  const double shell = std::pow(1.0 + h / d, 3) - 1.0;
  const double basset = 9.0 * std::sqrt(nu * dt_couple / kPi) / (0.5 * d);
  return 0.5 + shell + basset;
}

ExchangeGain exchange_worst_gain(double mass, double fluid_mass, double zeta0, double reaction_coeff,
                                 double ksl, double virtual_mass, double dt_couple) {
  ExchangeGain worst;
  const int n = 6;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      ExchangeModel m;
      m.mass = mass;
      m.drag = zeta0 * (1.0 + 0.5 * i / n);
      m.added_mass = fluid_mass * reaction_coeff * (0.5 + 1.0 * j / n);
      m.ksl = ksl;
      m.virtual_mass = virtual_mass;
      m.dt_couple = dt_couple;
      worst.radius = std::max(worst.radius, exchange_spectral_radius(m));
      worst.oscillation = std::max(worst.oscillation, exchange_oscillation(m));
    }
  }
  return worst;
}

MomentumExchange::MomentumExchange(const ExchangeSettings& s) : s_(s) {
  if (s_.semi_implicit && (!(s_.mu > 0.0) || !(s_.dt_couple > 0.0) || !(s_.drag_factor > 0.0)))
    throw std::invalid_argument("semi-implicit exchange needs mu > 0, dt_couple > 0, dragFactor > 0");
  if (s_.virtual_mass_coeff < 0.0 || s_.rho_f < 0.0)
    throw std::invalid_argument("virtualMassCoeff and rho_f must be >= 0");
}

double MomentumExchange::virtual_mass(double d) const {
  return s_.virtual_mass_coeff * s_.rho_f * kPi * d * d * d / 6.0;
}

std::vector<DemLoad> MomentumExchange::loads(const std::vector<Sphere>& spheres) {
  std::vector<DemLoad> out;
  out.reserve(spheres.size());
  for (const auto& s : spheres) {
    DemLoad l;
    l.id = s.id;
    l.force = s.force;
    l.torque = s.torque;
    if (s_.semi_implicit) {
      const double a = s.radius();
      l.ksl = s_.drag_factor * 3.0 * kPi * s_.mu * s.d;          // [kg/s]
      const double krot = s_.drag_factor * 8.0 * kPi * s_.mu * a * a * a;  // [kg m^2/s]
      const double mv = virtual_mass(s.d);
      auto it = prev_v_.find(s.id);
      for (int k = 0; k < 3; ++k) {
        l.uf[k] = s.v[k];  // F^n - Ksl (v - v^n)
        l.krot[k] = krot;
        l.torque[k] += krot * s.omega[k];  // T^n - Krot (omega - omega^n)
        if (it != prev_v_.end()) l.force[k] += mv * (s.v[k] - it->second[k]) / s_.dt_couple;
      }
    }
    prev_v_[s.id] = s.v;
    out.push_back(l);
  }
  return out;
}

}  // namespace hsrod::calib

// Newtonian carrier fluid of a scene: viscosity mu and density rho_f.
#pragma once

namespace hsrod {

struct FluidProperties {
  double dynamic_viscosity = 1.0e-3;  // mu [Pa s]
  double density = 1000.0;            // rho_f [kg/m^3]

  // Throws std::invalid_argument unless mu > 0 and rho_f >= 0 (both finite).
  void validate() const;
};

}  // namespace hsrod

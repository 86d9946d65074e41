#include "flow/fluid_properties.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hsrod {

void FluidProperties::validate() const {
  if (!std::isfinite(dynamic_viscosity) || dynamic_viscosity <= 0.0) {
    std::ostringstream msg;
    msg << "FluidProperties: dynamic_viscosity mu must be a finite number > 0 Pa s (got "
        << dynamic_viscosity << ")";
    throw std::invalid_argument(msg.str());
  }
  if (!std::isfinite(density) || density < 0.0) {
    std::ostringstream msg;
    msg << "FluidProperties: density rho_f must be a finite number >= 0 kg/m^3 (got " << density
        << ")";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace hsrod

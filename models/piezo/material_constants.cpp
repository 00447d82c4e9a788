#include "models/piezo/material_constants.hpp"

#include <cmath>

#include "assembly/error.hpp"

namespace pc {

void set_material_constants(Model& model, const PiezoTensors& tensors, double viscosity_time) {
  require(std::isfinite(viscosity_time) && viscosity_time >= 0, "set_material_constants: tau_v = ", viscosity_time,
          " must be finite and >= 0");
  model.set_constant("rho", tensors.rho);
  model.set_constant("B", tensors.B);
  model.set_constant("E", tensors.E);
  model.set_constant("beta", tensors.beta);
  if (viscosity_time > 0) model.set_constant("A", Eigen::MatrixXd(viscosity_time * tensors.B));
}

}  // namespace pc

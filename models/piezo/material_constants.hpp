#pragma once
// A piezoelectric material's tensors written into a model's constants under the names the bulk bricks
// read: rho, B (c^E), E (e), beta (eps^S) and, with a Kelvin-Voigt relaxation time tau_v > 0, A = tau_v B.
//   set_material_constants(model, piezo_material("PZT-5H").tensors(2, Axis::y), 0.01);
#include "bricks/piezo_materials.hpp"
#include "models/model.hpp"

namespace pc {

void set_material_constants(Model& model, const PiezoTensors& tensors, double viscosity_time = 0);

}  // namespace pc

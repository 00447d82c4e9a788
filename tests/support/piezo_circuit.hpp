#pragma once
// Setting up a piezoelectric test body's spec: its tensors, and an electrode pair in short or open circuit.
#include <string>

#include "bricks/piezo_materials.hpp"
#include "models/piezo/piezo_contact_recipe.hpp"

namespace pc::testing {

// B, E, beta from a preset's tensors, and rho with_mass (quasi-static without).
inline void set_piezo_tensors(PiezoContactSpec& spec, const PiezoTensors& t, bool with_mass) {
  spec.rho = with_mass ? t.rho : 0.0;
  spec.B = t.B;
  spec.E = t.E;
  spec.beta = t.beta;
}

// `ground` grounded and `far` either grounded too (short circuit) or a floating electrode holding no
// charge (open circuit).
inline void set_circuit(PiezoContactSpec& spec, const std::string& ground, const std::string& far, bool open_circuit) {
  spec.grounded = {ground};
  if (open_circuit)
    spec.electrodes = {floating_electrode(far, far)};
  else
    spec.grounded.push_back(far);
}

}  // namespace pc::testing

#pragma once
// A PZT-5H plate 4 x 1 mm (plane strain, poled along y), clamped on every side, grounded at the bottom and
// driven through its top electrode by a voltage ramp: a capacitor whose charge is C V exactly (no strain,
// D = -eps^S grad phi), C = eps^S_yy L / h per unit depth.
#include <memory>

#include "assembly/mesh_generators.hpp"
#include "bricks/piezo_materials.hpp"
#include "models/piezo/piezo_contact_recipe.hpp"

namespace pc::testing {

struct ClampedCapacitor {
  static constexpr double length = 4e-3, thickness = 1e-3;
  PiezoTensors tensors = piezo_material("PZT-5H").tensors(2, Axis::y);

  double capacitance() const { return tensors.beta(1, 1) * length / thickness; }
  // with_inertia: the material's density (a dynamic model), else quasi-static.
  PiezoContactSpec spec(double volts, double ramp, bool with_inertia) const {
    PiezoContactSpec s;
    s.mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {length, thickness}, 6, 3));
    s.rho = with_inertia ? tensors.rho : 0.0;
    s.B = tensors.B;
    s.E = tensors.E;
    s.beta = tensors.beta;
    s.clamped = {"left", "right", "top", "bottom"};
    s.grounded = {"bottom"};
    s.electrodes = {{"drive", "top", TimeFunction::ramp(volts, ramp)}};
    return s;
  }
};

}  // namespace pc::testing

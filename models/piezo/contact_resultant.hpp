#pragma once
// What the foundation does to the body, summed over the contact surface: the resultant force of the
// normal and friction bricks (the opposite of their residuals, summed over the velocity's dofs: exact for
// the discrete solution) and its power on the body, F . v integrated, which is minus the contact's
// dissipation for a foundation at rest. For a motor, the tangential component is the thrust the rotor
// feels reversed.
#include <array>

#include "models/piezo/piezo_contact_recipe.hpp"

namespace pc {

struct ContactResultant {
  std::array<double, 3> force{};  // x, y, z (z 0 in 2D), on the body
  double power = 0;               // of the contact tractions on the body's velocity
};

// From the model's last assembly; zeros without contact.
ContactResultant contact_resultant(const PiezoContactModel& built);

}  // namespace pc

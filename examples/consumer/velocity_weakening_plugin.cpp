// The plugin: one line makes the law a friction law that scenes name ("law_tangential":
// "velocity_weakening"), listed and documented by `piezocontact list --plugin ...` and `describe`.
#include "bricks/law_registry.hpp"
#include "velocity_weakening.hpp"

PC_REGISTER_FRICTION_LAW(VelocityWeakeningCoulomb, "velocity_weakening",
                         "p_tau = mu(|v_tau|) |p_nu| v_tau / sqrt(|v_tau|^2 + eps^2), mu falling from mu_s to mu_k")

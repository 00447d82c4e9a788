// The friction laws a scene can name (contact.law_tangential).
#include "bricks/laws/friction_laws.hpp"

#include "bricks/alart_curnier_friction_brick.hpp"
#include "bricks/law_registry.hpp"

PC_REGISTER(pc::friction_law_registry(), pc::no_brick_entry("none", "frictionless: no friction brick"))
PC_REGISTER_FRICTION_LAW(pc::ViscousFriction, "viscous", "p_tau = c_tau v_tau: the paper's law (13)")
PC_REGISTER_FRICTION_LAW(pc::RegularizedCoulomb, "coulomb",
                         "p_tau = mu |p_nu| v_tau / sqrt(|v_tau|^2 + eps^2), p_nu from the normal law")
PC_REGISTER_FRICTION_LAW(pc::RegularizedTresca, "tresca", "p_tau = g v_tau / sqrt(|v_tau|^2 + eps^2)")
PC_REGISTER(pc::friction_law_registry(),
            (pc::paired_law_entry<pc::AlartCurnierFrictionBrick, pc::AugmentedCoulomb>(
                "coulomb_exact",
                "Coulomb's law without regularisation: a friction multiplier on the contact surface, "
                "lambda = P_B(lambda + r v_tau), |B| = mu |p_nu| (Alart-Curnier, semismooth Newton)")))

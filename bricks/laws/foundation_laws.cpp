// The foundation laws a scene can name (foundation.<name>.type).
#include "bricks/laws/foundation_laws.hpp"

#include "bricks/law_registry.hpp"

PC_REGISTER(pc::foundation_law_registry(),
            pc::no_brick_entry("insulated", "D.n = 0 on the contact surface: no foundation brick"))
PC_REGISTER_FOUNDATION_LAW(pc::LinearConductance, "conductive", "D.n = k_e (phi - phi_f): the paper's law (10)")
PC_REGISTER_FOUNDATION_LAW(pc::PressureActivatedConductance, "pressure_activated",
                           "D.n = k_e s(p_nu) (phi - phi_f), s(p) = p+^2 / (p+^2 + p_ref^2), p_nu from the normal law")

// The normal laws a scene can name (contact.law_normal).
#include "bricks/laws/normal_laws.hpp"

#include "bricks/law_registry.hpp"

PC_REGISTER_NORMAL_LAW(pc::LinearDampedResponse, "linear_damped",
                       "p_nu = c_nu max(v_nu, 0): the paper's damped response (12)")
PC_REGISTER_NORMAL_LAW(pc::PowerDampedResponse, "power_damped", "p_nu = c_nu max(v_nu, 0)^m")
PC_REGISTER_NORMAL_LAW(pc::NormalCompliance, "normal_compliance",
                       "p_nu = c_nu max(u_nu - gap, 0)^m: a deformable foundation (reads the displacement)")

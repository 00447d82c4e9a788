// A plugin that registers a name the library already has: loading it must be refused.
#include "bricks/law_registry.hpp"
#include "bricks/laws/normal_laws.hpp"

PC_REGISTER_NORMAL_LAW(pc::LinearDampedResponse, "linear_damped", "a second linear_damped")

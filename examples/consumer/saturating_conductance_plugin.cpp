// The plugin of the foundation law: one line makes it a foundation law that a scene names as a foundation's
// type ("foundation": {"<name>": {"type": "saturating", ...}}), listed by `piezocontact list --plugin ...`.
// [snippet plugin]
#include "bricks/law_registry.hpp"
#include "saturating_conductance.hpp"
PC_REGISTER_FOUNDATION_LAW(SaturatingConductance, "saturating",
                           "D.n = k_e phi_s tanh((phi - phi_f) / phi_s): conduction that saturates")
// [snippet plugin end]

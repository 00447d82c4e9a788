#include "assembly/version.hpp"

namespace pc {

const char* library_version() { return PIEZOCONTACT_VERSION; }

}  // namespace pc

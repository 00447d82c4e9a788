// The entry points of a piezocontact plugin, compiled into every plugin by piezocontact_add_plugin():
// the loader (models/scene/plugins.hpp) reads the version the plugin was built against, and only when it
// matches the running library's asks the plugin to run its registrations.
#include "assembly/registry.hpp"
#include "assembly/version.hpp"

extern "C" __attribute__((visibility("default"))) const char* piezocontact_plugin_version() {
  return PIEZOCONTACT_VERSION;
}

extern "C" __attribute__((visibility("default"))) void piezocontact_plugin_register() {
  for (const auto& registration : pc::plugin_detail::pending_registrations()) registration();
  pc::plugin_detail::pending_registrations().clear();
}

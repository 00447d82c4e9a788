// A plugin's entry points as another version of piezocontact would have built them: loading it must be
// refused before it registers anything.
extern "C" __attribute__((visibility("default"))) const char* piezocontact_plugin_version() { return "9.9.9"; }
extern "C" __attribute__((visibility("default"))) void piezocontact_plugin_register() {}

#include "models/scene/plugins.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>

#include "assembly/error.hpp"
#include "assembly/version.hpp"

namespace pc {
namespace {

std::vector<std::string>& loaded() {
  static std::vector<std::string> paths;
  return paths;
}

}  // namespace

const std::vector<std::string>& loaded_plugins() { return loaded(); }

void load_plugin(const std::string& path) {
  std::error_code error;
  require(std::filesystem::is_regular_file(path, error), "plugin '", path, "': no such file");
  const std::string canonical = std::filesystem::canonical(path).string();
  if (std::find(loaded().begin(), loaded().end(), canonical) != loaded().end()) return;

  // RTLD_LOCAL: the plugin's symbols stay its own; it reaches the registries through the libraries it links.
  void* handle = dlopen(canonical.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) fail("plugin '", path, "': cannot be loaded: ", dlerror());
  using VersionFunction = const char* (*)();
  using RegisterFunction = void (*)();
  const auto version = reinterpret_cast<VersionFunction>(dlsym(handle, "piezocontact_plugin_version"));
  const auto registrations = reinterpret_cast<RegisterFunction>(dlsym(handle, "piezocontact_plugin_register"));
  if (!version || !registrations) {
    dlclose(handle);
    fail("plugin '", path,
         "': not a piezocontact plugin (it has no piezocontact_plugin_version and "
         "piezocontact_plugin_register; build it with piezocontact_add_plugin())");
  }
  const std::string built_against = version();
  if (built_against != library_version()) {
    dlclose(handle);
    fail("plugin '", path, "' was built against piezocontact ", built_against, ", but this is piezocontact ",
         library_version(), ": rebuild the plugin against this version");
  }
  // The plugin stays loaded for the life of the process: its laws live in the registries from now on.
  try {
    registrations();
  } catch (const Error& e) {
    fail("plugin '", path, "': ", e.what());
  }
  loaded().push_back(canonical);
}

}  // namespace pc

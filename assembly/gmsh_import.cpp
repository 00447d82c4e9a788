#include "assembly/gmsh_import.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <optional>

#include "assembly/error.hpp"

namespace pc {
namespace {

using ImportFunction = void (*)(const std::string&, const GmshOptions&, std::optional<Mesh>&);

// The module sits beside this library, in the build tree and in an installed prefix alike.
std::filesystem::path module_path() {
  Dl_info info{};
  require(dladdr(reinterpret_cast<void*>(&import_gmsh), &info) != 0 && info.dli_fname != nullptr,
          "gmsh: cannot locate the piezocontact library to find its gmsh module");
  return std::filesystem::path(info.dli_fname).parent_path() / "libpiezocontact_gmsh.so";
}

// Opened once, on the first import, and kept for the life of the process (gmsh's globals live in it).
ImportFunction import_function() {
  static std::mutex mutex;
  static ImportFunction function = nullptr;
  const std::lock_guard lock(mutex);
  if (function) return function;
  const std::filesystem::path path = module_path();
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) fail("gmsh: cannot load piezocontact's gmsh module '", path.string(), "': ", dlerror());
  function = reinterpret_cast<ImportFunction>(dlsym(handle, "piezocontact_gmsh_import"));
  require(function != nullptr, "gmsh: '", path.string(), "' has no piezocontact_gmsh_import");
  return function;
}

}  // namespace

Mesh import_gmsh(const std::string& path, const GmshOptions& options) {
  std::optional<Mesh> mesh;
  import_function()(path, options, mesh);
  return std::move(*mesh);
}

}  // namespace pc

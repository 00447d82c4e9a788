// Fuzz target: a gmsh .msh file through import_gmsh. gmsh itself parses the file (libgmsh's reader, not
// ours); what is ours is everything import_gmsh makes of what gmsh read: cell shapes, node numbering,
// orientation, cell and face regions, and the Mesh's own checks.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "assembly/gmsh_import.hpp"
#include "fuzz_support.hpp"

namespace {

// gmsh reads files only: one per process, rewritten for every input and removed at exit.
struct InputFile {
  std::string path =
      (std::filesystem::temp_directory_path() / ("piezocontact_fuzz_" + std::to_string(::getpid()) + ".msh")).string();
  ~InputFile() {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const InputFile file;
  const std::string& path = file.path;
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  return pc::fuzz::run_contract("gmsh_msh", [&] { static_cast<void>(pc::import_gmsh(path)); });
}

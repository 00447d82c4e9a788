#include "assembly/atomic_file.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "assembly/error.hpp"

namespace pc {

void write_atomically(const std::string& path, const std::string& what,
                      const std::function<void(std::ostream&)>& write_content) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    require(bool(out), what, ": cannot open '", temporary, "' for writing (does the directory of '", path,
            "' exist and is it writable?)");
    write_content(out);
    out.close();
    if (!out) {
      std::remove(temporary.c_str());
      fail(what, ": writing '", temporary, "' failed (disk full?)");
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::remove(temporary.c_str());
    fail(what, ": cannot rename '", temporary, "' to '", path, "': ", error.message());
  }
}

}  // namespace pc

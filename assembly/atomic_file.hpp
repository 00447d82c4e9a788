#pragma once
// Writes a file through path + ".tmp" renamed over path, so that an interrupted run never leaves a
// truncated file where a reader (or a restarted run) expects a complete one.
#include <functional>
#include <ostream>
#include <string>

namespace pc {

// write_content fills the stream; `what` names the caller in error messages.
void write_atomically(const std::string& path, const std::string& what,
                      const std::function<void(std::ostream&)>& write_content);

}  // namespace pc

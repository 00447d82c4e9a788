#pragma once
// The one exception type of the library. Every message names the offending field or value, so that a
// user reading it knows what to change without opening the source.
#include <sstream>
#include <stdexcept>
#include <string>

namespace pc {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Concatenates anything streamable into one message: fail("cell ", c, " is inverted (det J = ", d, ")").
template <class... Parts>
std::string message(const Parts&... parts) {
  std::ostringstream out;
  out.precision(10);
  (out << ... << parts);
  return out.str();
}

template <class... Parts>
[[noreturn]] void fail(const Parts&... parts) {
  throw Error(message(parts...));
}

// Throws with the message when the condition is false; the message is only built on failure.
template <class... Parts>
void require(bool condition, const Parts&... parts) {
  if (!condition) fail(parts...);
}

}  // namespace pc

#pragma once
// The one exception type of the library. Every message names the offending field or value, so that a
// user reading it knows what to change without opening the source.
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>

namespace pc {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Memory ran out where a library reports it by a status (a sparse factorisation): a std::bad_alloc,
// so that it is not taken for a numerical failure (no step cut-back retries it), with what ran out of
// memory. The runner names the phase it happened in.
class OutOfMemory : public std::bad_alloc {
 public:
  explicit OutOfMemory(std::string what) : what_(std::move(what)) {}
  const char* what() const noexcept override { return what_.c_str(); }

 private:
  std::string what_;
};

// Concatenates anything streamable into one message: fail("cell ", c, " is inverted (det J = ", d, ")").
template <class... Parts> std::string message(const Parts&... parts) {
  std::ostringstream out;
  out.precision(10);
  (out << ... << parts);
  return out.str();
}

template <class... Parts> [[noreturn]] void fail(const Parts&... parts) { throw Error(message(parts...)); }

// Throws with the message when the condition is false; the message is only built on failure.
template <class... Parts> void require(bool condition, const Parts&... parts) {
  if (!condition) fail(parts...);
}

}  // namespace pc

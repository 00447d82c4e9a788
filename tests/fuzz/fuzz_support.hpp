#pragma once
// What every fuzz target checks (tests/fuzz/README.md): an input either loads or is refused with a
// pc::Error whose message is not empty. Any other exception, a crash, a sanitizer report or a hang is a
// finding: the target prints it and aborts, and the driver (libFuzzer or tests/fuzz/fuzz_driver.cpp)
// keeps the input that caused it.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <new>
#include <string>
#include <typeinfo>

#include "assembly/error.hpp"
#include "models/scene/json.hpp"

namespace pc::fuzz {

// How the last input ended, for the driver's --expect-refusal mode.
struct Outcome {
  bool refused = false;
  std::string message;  // the pc::Error's message when refused
};
Outcome& last_outcome();

// Aborts after printing "fuzz finding in <target>: <what>".
[[noreturn]] void finding(const char* target, const std::string& what);

// Runs `action` on the input under the contract above; `target` names the finding. Returns 0, as
// LLVMFuzzerTestOneInput must.
template <class Action> int run_contract(const char* target, Action&& action) {
  Outcome& outcome = last_outcome();
  outcome = Outcome{};
  try {
    action();
  } catch (const Error& e) {
    outcome.refused = true;
    outcome.message = e.what();
    if (outcome.message.empty()) finding(target, "a pc::Error with an empty message");
  } catch (const std::bad_alloc&) {
    finding(target, "uncaught std::bad_alloc (the work was not bounded before allocating)");
  } catch (const std::exception& e) {
    finding(target, std::string("uncaught ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    finding(target, "an uncaught exception that is no std::exception");
  }
  return 0;
}

// The scene with what would reach outside the reader bounded: plugins (dlopen of arbitrary code) are
// dropped, a gmsh file becomes one that does not exist (gmsh is fuzzed by its own target), and
// solver.max_memory_gib is capped so that no large mesh is built (the scene's own limit, refused with
// its estimate named). Everything else is left as the input has it, wrong types included.
Json bounded_for_fuzzing(Json scene);

// What `piezocontact check` does with a scene: load it (load_scene) and build each foundation's model.
void check_scene(const Json& scene);

// The bytes as text.
inline std::string text_of(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

}  // namespace pc::fuzz

// Fuzz target: a scene file's text through the JSON reader (parse_json) and the scene's validation
// (load_scene and each foundation's model, as `piezocontact check` does).
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pc::fuzz::run_contract(
      "scene_json", [&] { pc::fuzz::check_scene(pc::parse_json(pc::fuzz::text_of(data, size), "fuzz.json")); });
}

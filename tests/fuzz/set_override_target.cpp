// Fuzz target: `--set key=value` overrides, one per line of the input, applied to a small valid scene
// (tests/fuzz/set_base_scene.json) by apply_overrides as the command line does (the path parser of
// Json::set_path, the value parser parse_json_value_from_cli), then the scene checked as by
// `piezocontact check`.
#include <sstream>
#include <vector>

#include "fuzz_support.hpp"
#include "models/scene/scene.hpp"

#ifndef PIEZOCONTACT_FUZZ_BASE_SCENE
#error "PIEZOCONTACT_FUZZ_BASE_SCENE must name the scene the overrides apply to"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const pc::Json base = pc::read_json_file(PIEZOCONTACT_FUZZ_BASE_SCENE);
  return pc::fuzz::run_contract("set_override", [&] {
    std::vector<std::string> overrides;
    std::istringstream lines(pc::fuzz::text_of(data, size));
    for (std::string line; std::getline(lines, line);) overrides.push_back(line);
    pc::Json scene = base;
    pc::apply_overrides(scene, overrides);
    pc::fuzz::check_scene(scene);
  });
}

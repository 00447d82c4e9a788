// The scene reader against bad output counts and missing sections (issue 11, cases 10 and 11): a grid count
// that cannot be is refused when the scene is read, naming the key and the value, and each problem of a
// scene is reported once.
#include <gtest/gtest.h>

#include "models/scene/scene.hpp"
#include "support/error_and_temp_dir.hpp"

namespace pc {
namespace {

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";

// Case 10: an output grid count that cannot be is refused when the scene is read, naming key and value.
TEST(SceneOutputGrid, ImpossibleCountsAreRefusedNamingTheKeyAndValue) {
  testing::expect_error_containing([] { load_scene_file(kScene, {"output.grid.x=[0,0.03,1e12]"}); },
                                   {"output.grid.x[2]", "1e+12"});
  testing::expect_error_containing([] { load_scene_file(kScene, {"output.grid.y=[0,0.01,2.5]"}); },
                                   {"output.grid.y[2]", "2.5"});
  testing::expect_error_containing([] { load_scene_file(kScene, {"output.grid.x=[0,0.03,0]"}); }, {"output.grid.x[2]"});
  testing::expect_error_containing(
      [] {
        load_scene_file(kScene, {"output.grid.x=[0,0.03,100000]", "output.grid.y=[0,0.01,1000]"});
      },
      {"output.grid", "limit"});
}

// Case 11: a scene without a mesh reports "missing key 'mesh'" once.
TEST(SceneProblems, EachProblemIsReportedOnce) {
  const Json full = read_json_file(kScene);
  Json json = Json::object();
  for (const auto& [key, value] : full.members())
    if (key != "mesh") json.set(key, value);
  try {
    load_scene(json, PIEZOCONTACT_SCENES);
    ADD_FAILURE() << "a scene without a mesh was accepted";
  } catch (const Error& e) {
    const std::string what = e.what();
    const size_t first = what.find("missing key 'mesh'");
    ASSERT_NE(first, std::string::npos) << what;
    EXPECT_EQ(what.find("missing key 'mesh'", first + 1), std::string::npos) << what;
  }
}

// A mesh whose run cannot fit is refused before it is built, with the estimate and the key named, in
// well under a second (nx = 1e9 used to grow to 8 GB and abort); so is a scene "file" without an end.
TEST(SceneLimits, WhatCannotFitIsRefusedBeforeItIsBuilt) {
  testing::expect_error_containing([] { load_scene_file(kScene, {"mesh.nx=1000000000"}); },
                                   {"'mesh' (1000000000 x 20 cells, P1) has about", "GiB available to this run"});
  // The paper's mesh needs about 3843 dofs x 8 KiB = 30 MiB: under a limit of 0.01 GiB it is refused ...
  testing::expect_error_containing([] { load_scene_file(kScene, {"solver.max_memory_gib=0.01"}); },
                                   {"more than the 0.01 GiB allowed by 'solver.max_memory_gib'"});
  // ... and under 1 GiB it is not.
  EXPECT_NO_THROW(load_scene_file(kScene, {"solver.max_memory_gib=1"}));
  testing::expect_error_containing([] { read_json_file("/dev/zero"); }, {"'/dev/zero' is larger than 64 MiB"});
}

}  // namespace
}  // namespace pc

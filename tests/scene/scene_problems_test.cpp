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
  testing::expect_error_containing([] { load_scene_file(kScene, {"output.grid.x=[0,0.03,0]"}); },
                                   {"output.grid.x[2]"});
  testing::expect_error_containing(
      [] { load_scene_file(kScene, {"output.grid.x=[0,0.03,100000]", "output.grid.y=[0,0.01,1000]"}); },
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

}  // namespace
}  // namespace pc

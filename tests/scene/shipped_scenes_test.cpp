// Every shipped scene (scenes/*.json) loads and runs a few steps of each of its foundations. Two of them
// mesh a gmsh .geo file: this test is labelled "gmsh" (see tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "models/scene/scene_runner.hpp"

namespace pc {
namespace {

// Every shipped scene loads, and runs a few steps of each foundation with every Newton solve converged.
TEST(ShippedScenes, LoadAndRunAFewSteps) {
  for (const char* name : {"paper2d.json", "strip2d.json", "box3d.json"}) {
    std::vector<std::string> coarse = {"time.steps=2", "time.T=0.002"};
    if (std::string(name) != "paper2d.json") coarse.push_back("mesh.size_factor=2");
    const Scene scene = load_scene_file(std::string(PIEZOCONTACT_SCENES) + "/" + name, coarse);
    for (const SceneFoundation& f : scene.foundations) {
      const FoundationRunResult r = run_foundation(scene, f, "", false);
      EXPECT_TRUE(r.completed) << name << " / " << f.name << ": " << r.message;
      EXPECT_EQ(r.steps, 2) << name << " / " << f.name;
    }
  }
}

}  // namespace
}  // namespace pc

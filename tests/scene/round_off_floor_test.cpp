// Newton and the residual's round-off floor, on the paper's scene (issue 11 case 9): a problem whose forces
// cancel to round-off converges.
#include <gtest/gtest.h>

#include "models/scene/scene_runner.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";

// Every side clamped, conductive foundation: the potential is linear in y, so its uniform piezoelectric
// stress has no net force on any free (interior) node, and the velocity block's residual and every brick's
// net contribution to it are round-off. The relative test against them never passed: 500 Newton iterations
// at t = 0, then the step fell below its floor. Measured against the gross size of the terms (|K| |x|),
// the block is at its round-off floor from the start.
TEST(RoundOffFloor, AnAllClampedConductiveSceneConvergesAtEveryStep) {
  const Scene scene = load_scene_file(
      kScene, {"mesh.nx=12", "mesh.ny=4", "time.steps=5", R"(regions.clamped=["left","right","top","bottom"])"});
  const FoundationRunResult r = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
  ASSERT_TRUE(r.completed) << r.message;
  EXPECT_EQ(r.steps, 5);
  EXPECT_LE(r.newton_iterations_max_per_step, 2);
  EXPECT_NEAR(r.max_abs_ux, 0.0, 1e-20);
  EXPECT_NEAR(r.phi_min, -48.0, 1.0);
}

}  // namespace
}  // namespace pc

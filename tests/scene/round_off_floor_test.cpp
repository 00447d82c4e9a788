// Newton and the residual's round-off floor, on the paper's scene (issue 11 case 9, issue 16): a problem
// whose forces cancel to round-off converges, and a tolerance below the floor is refused when the scene is
// read, or, given through the API, stops the run with the floor named, without cut-backs.
#include <gtest/gtest.h>

#include "models/scene/scene_runner.hpp"
#include "support/error_and_temp_dir.hpp"
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

// The smallest meaningful tolerance is a few machine epsilons (min_relative_tolerance()): a smaller one is
// refused when the scene is read, naming the key, the value and that limit; one just above it is accepted.
TEST(RoundOffFloor, AToleranceBelowTheFloorIsRefusedWhenTheSceneIsRead) {
  testing::expect_error_containing([] { load_scene_file(kScene, {"solver.relative_tolerance=1e-15"}); },
                                   {"'solver.relative_tolerance' = 1e-15", "round-off floor", "1.776356839e-15"});
  EXPECT_NO_THROW(load_scene_file(kScene, {"solver.relative_tolerance=2e-15"}));
  EXPECT_NO_THROW(load_scene_file(kScene, {"solver.relative_tolerance=1e-14"}));
}

// Given through the API, the same tolerance ran for ever (cut-back after cut-back, dt / 1024 after ten
// minutes, silently). Newton now stops the step when the residual stagnates at its floor above the
// tolerance, and the run stops there with that message, without a cut-back. Which step that is is not
// asserted: a step may still meet the tolerance by chance, or pass by the increment test, and which ones
// do moves with the last digits of the Newton corrections, that is with the BLAS kernels of the machine
// (2 or 3 steps on the whole system and 4 on the contact dofs under OpenBLAS's Haswell kernels, 5 on the
// contact dofs under its Prescott ones, issue 44). What does not move: the run stops before its end, no
// step is cut back, no step takes more than max_iterations, and the message names the floor.
TEST(RoundOffFloor, AnUnreachableToleranceStopsTheRunWithoutCutBacksNamingTheFloor) {
  for (const bool contact_newton : {false, true}) {
    // (time.max_attempts bounds the run that cut back for ever.)
    Scene scene = load_scene_file(kScene, {"time.steps=20", "time.max_attempts=100"});
    scene.newton.relative_tolerance = 1e-15;
    scene.newton.contact_newton = contact_newton;
    const FoundationRunResult r = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
    EXPECT_FALSE(r.completed);
    EXPECT_LT(r.steps, 20) << r.message;
    EXPECT_EQ(r.cutbacks, 0) << r.message;
    EXPECT_LE(r.newton_iterations_total, (r.steps + 1) * scene.newton.max_iterations) << r.message;
    EXPECT_CONTAINS(r.message, "failed (round_off_floor: the residual of block 'v'");
    EXPECT_CONTAINS(r.message, "stagnates at its round-off floor");
    EXPECT_CONTAINS(r.message, "relative_tolerance 1e-15");
    EXPECT_CONTAINS(r.message, "without cutting the step back");
  }
}

// At the limit the floor counts as convergence: the shipped scene with the smallest tolerance completes.
TEST(RoundOffFloor, TheSmallestAcceptedToleranceConverges) {
  const Scene scene =
      load_scene_file(kScene, {"mesh.nx=15", "mesh.ny=5", "time.steps=10", "solver.relative_tolerance=2e-15"});
  const FoundationRunResult r = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
  ASSERT_TRUE(r.completed) << r.message;
  EXPECT_LE(r.newton_iterations_max_per_step, 12);
}

}  // namespace
}  // namespace pc

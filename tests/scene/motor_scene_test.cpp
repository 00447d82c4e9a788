// The motor scene (scenes/motor2d.json) with what issue "A real device" added to it: its open-circuit
// modes, and the exact Coulomb law. It meshes a gmsh .geo file: this test is labelled "gmsh" (see
// tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "models/scene/json.hpp"
#include "models/scene/scene.hpp"
#include "models/scene/scene_modes.hpp"
#include "models/scene/scene_runner.hpp"
#include "support/csv_table.hpp"
#include "support/error_and_temp_dir.hpp"

namespace pc {
namespace {

class MotorScene : public testing::TemporaryDirectoryTest {};

TEST_F(MotorScene, OpenCircuitLowersNoModeAndItsElectrodesFloatAsOne) {
  ModalOptions options;
  options.modes = 4;
  const Scene motor = load_scene_file(std::string(PIEZOCONTACT_SCENES) + "/motor2d.json", {"mesh.order=1"});
  const ModalResult shorted = write_scene_modes(motor, "", options);
  const ModalResult open = write_scene_modes(motor, directory_.string(), options, true);
  // Opening an electrode frees its potential, which the condensed stiffness K + C^T P^-1 C takes as a
  // maximum: by Courant-Fischer, no mode is lower. These are bending modes of a stator electroded through
  // its thickness, whose charge cancels about the mid-plane: opening barely moves them (the strong
  // open-circuit stiffening of an extensional rod is tests/models/modal_analysis_test.cpp's).
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_GE(open.frequencies_hz[k], shorted.frequencies_hz[k] * (1 - 1e-12)) << k;
    EXPECT_LT(open.frequencies_hz[k], shorted.frequencies_hz[k] * (1 + 1e-3)) << k;
  }
  EXPECT_EQ(testing::read_csv(directory_ / "modes.csv").rows.size(), 4u);
  FoundationRun run(motor, motor.foundations.front());
  const std::vector<int> e1 = run.model().space("phi").dofs_on("e1");
  for (int k = 0; k < 4; ++k)
    for (int d : e1) EXPECT_EQ(open.potential_shapes(d, k), open.potential_shapes(e1.front(), k)) << k;
}

// The motor scene with the exact law, its first steps through the Schur condensation ("auto" picks it): P2,
// an electric body, clamped ends at the contact's corners. Its S_c, singular in the multiplier's rows, once
// passed the condition estimate and gave a NaN step.
TEST_F(MotorScene, RunsItsFirstStepsWithExactCoulombThroughTheSchurCondensation) {
  std::ifstream file(std::string(PIEZOCONTACT_SCENES) + "/motor2d.json");
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const auto replace = [&](const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("\"law_tangential\": \"coulomb\"", "\"law_tangential\": \"coulomb_exact\"");
  replace("\"eps\": 0.002", "\"r\": 3e6");
  replace("\"time\": {\"T\": 6e-4, \"steps\": 1200}", "\"time\": {\"T\": 6e-6, \"steps\": 12}");
  const Scene scene = load_scene(parse_json(text, "motor2d (exact)"), PIEZOCONTACT_SCENES);
  FoundationRun run(scene, scene.foundations.front());
  const FoundationRunResult result = run.run("", false);
  ASSERT_TRUE(result.completed) << result.message;
  EXPECT_EQ(result.cutbacks, 0);
  EXPECT_NE(result.linear_strategy.find(": schur"), std::string::npos) << result.linear_strategy;
  EXPECT_TRUE(run.model().values("lambda_tau").allFinite());
}

}  // namespace
}  // namespace pc

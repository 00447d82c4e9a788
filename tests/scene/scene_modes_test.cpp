// `piezocontact modes`: a scene's modes written as a table and one VTU shape per mode, ascending; the
// same frequencies from P1 and P2 within the discretisation error; a massless scene, and --open-circuit
// without electrodes, refused. (The motor's open-circuit modes: motor_scene_test.cpp.)
#include <gtest/gtest.h>

#include <filesystem>

#include "models/scene/scene_modes.hpp"
#include "support/csv_table.hpp"
#include "support/error_and_temp_dir.hpp"
#include "support/shipped_scenes.hpp"
#include "support/test_helpers.hpp"
#include "support/vtu_reader.hpp"

namespace pc {
namespace {

class SceneModes : public testing::TemporaryDirectoryTest {};

TEST_F(SceneModes, TableAndShapesAreWrittenAndP1AndP2Agree) {
  ModalOptions options;
  options.modes = 4;
  const Scene p1 = load_scene_file(testing::kPaperScene, {"mesh.nx=24", "mesh.ny=8"});
  const ModalResult coarse = write_scene_modes(p1, directory_.string(), options);
  const testing::Table table = testing::read_csv(directory_ / "modes.csv");
  ASSERT_EQ(table.rows.size(), 4u);
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(table.rows[k][1], coarse.frequencies_hz[k]);
    if (k > 0) {
      EXPECT_GT(table.rows[k][1], table.rows[k - 1][1]);
    }
    const std::string vtu = testing::read_text(directory_ / ("mode_" + std::to_string(k + 1) + ".vtu"));
    EXPECT_EQ(testing::array_names(vtu, "PointData"), (std::vector<std::string>{"v", "phi"}));
  }
  EXPECT_NE(testing::read_text(directory_ / "modes.pvd").find("file=\"mode_4.vtu\""), std::string::npos);
  // P2 on the same mesh: each frequency within 4 % of P1's (P1 triangles are stiff in bending), and below it
  // (Rayleigh-Ritz: both from above).
  const Scene p2 = load_scene_file(testing::kPaperScene, {"mesh.nx=24", "mesh.ny=8", "mesh.order=2"});
  const ModalResult fine = write_scene_modes(p2, "", options);
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_LT(fine.frequencies_hz[k], coarse.frequencies_hz[k]) << k;
    EXPECT_NEAR(fine.frequencies_hz[k] / coarse.frequencies_hz[k], 1, 0.04) << k;
  }
}

TEST_F(SceneModes, OpenCircuitWithoutElectrodesIsRefused) {
  const Scene scene = load_scene_file(testing::kPaperScene, {"mesh.nx=6", "mesh.ny=2"});
  testing::expect_error_containing([&] { write_scene_modes(scene, "", {}, true); },
                                   {"--open-circuit", "no electrodes"});
}

TEST_F(SceneModes, AMasslessSceneIsRefused) {
  const Scene scene = load_scene_file(testing::kPaperScene, {"mesh.nx=6", "mesh.ny=2", "material.rho=0"});
  testing::expect_error_containing([&] { write_scene_modes(scene, "", {}); },
                                   {"material.rho = 0", "no vibration modes"});
}

}  // namespace
}  // namespace pc

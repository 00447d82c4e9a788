// Every shipped scene (scenes/*.json) loads and runs a few steps of each of its foundations. Three of them
// mesh a gmsh .geo file: this test is labelled "gmsh" (see tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "models/piezo/energy_books.hpp"
#include "models/scene/json.hpp"
#include "models/scene/scene_runner.hpp"
#include "support/error_and_temp_dir.hpp"
#include "support/run_model.hpp"
#include "support/simplex_edges.hpp"

namespace pc {
namespace {

// Every shipped scene loads, and runs a few steps of each foundation with every Newton solve converged.
TEST(ShippedScenes, LoadAndRunAFewSteps) {
  for (const char* name : {"paper2d.json", "strip2d.json", "box3d.json", "motor2d.json"}) {
    std::vector<std::string> coarse = {"time.steps=2", "time.T=0.002"};
    if (std::string(name) != "paper2d.json") coarse.push_back("mesh.size_factor=2");
    if (std::string(name) == "motor2d.json") coarse = {"time.steps=2", "time.T=4e-6"};  // a fifth of a period
    const Scene scene = load_scene_file(std::string(PIEZOCONTACT_SCENES) + "/" + name, coarse);
    for (const SceneFoundation& f : scene.foundations) {
      const FoundationRunResult r = run_foundation(scene, f, "", false);
      EXPECT_TRUE(r.completed) << name << " / " << f.name << ": " << r.message;
      EXPECT_EQ(r.steps, 2) << name << " / " << f.name;
    }
  }
}

// The motor's energy books balance at every step of its first two periods: the drive through four
// electrodes, the slider's approach (a moving foundation doing work through the contact) and Coulomb
// friction, every entry read from its brick's residual.
TEST(ShippedScenes, MotorEnergyBooksBalanceEveryStep) {
  const Scene scene =
      load_scene_file(std::string(PIEZOCONTACT_SCENES) + "/motor2d.json", {"time.steps=80", "time.T=4e-5"});
  PiezoContactSpec spec = scene.spec;
  spec.foundation = scene.foundations.front().law;
  PiezoContactModel built = build_piezo_contact_model(spec);
  EnergyBooks books(built);
  int records = 0;
  testing::run(built, scene.end_time, scene.steps, [&](const Model& m) {
    if (records++ == 0) return books.start(m);
    const EnergyBalance& b = books.record(m);
    EXPECT_LE(std::abs(b.balance), 1e-8 * b.scale()) << "t = " << m.time();
    EXPECT_LE(std::abs(b.coupling), 1e-10 * b.scale()) << "t = " << m.time();
    EXPECT_GE(b.viscous_dissipation, 0);
    EXPECT_GE(b.numerical_dissipation, 0);
  });
  EXPECT_EQ(records, 81);
  // The electrodes did the work that the stator stores and dissipates.
  EXPECT_GT(books.totals().boundary_work, 0);
  EXPECT_GT(books.totals().stored(), 0);
}

// A gmsh mesh's summary says what the mesh is (issue 16): the file, its nodes and cells as the mesh has them,
// the cell type and the shortest and longest edge; no structured counts (they were written as 0).
using ShippedSceneResults = testing::TemporaryDirectoryTest;

TEST_F(ShippedSceneResults, AGmshMeshIsDescribedInTheSummary) {
  for (const auto& [name, file, cell_type] :
       {std::tuple{"strip2d.json", "strip2d.geo", "triangle"}, std::tuple{"box3d.json", "box3d.geo", "tetrahedron"}}) {
    const Scene scene = load_scene_file(std::string(PIEZOCONTACT_SCENES) + "/" + name,
                                        {"time.steps=1", "time.T=0.001", "mesh.size_factor=2"});
    const std::string dir = (directory_ / scene.name).string();
    ASSERT_TRUE(run_foundation(scene, find_foundation(scene, "insulated"), dir, false).completed) << name;
    const Json summary = read_json_file(dir + "/summary.json");
    const Mesh& mesh = *scene.spec.mesh;
    const Json m = summary.at("mesh");
    EXPECT_EQ(m.at("source").as_string(), "gmsh") << name;
    EXPECT_EQ(m.at("file").as_string(), file) << name;
    EXPECT_EQ(m.at("size_factor").as_number(), 2.0) << name;
    EXPECT_EQ(m.at("dim").as_int(), mesh.dim()) << name;
    EXPECT_EQ(m.at("nodes").as_int(), mesh.num_nodes()) << name;
    EXPECT_EQ(m.at("cells").as_int(), mesh.num_cells()) << name;
    EXPECT_EQ(m.at("cell_type").as_string(), cell_type) << name;
    const auto [h_min, h_max] = testing::simplex_edge_range(mesh);
    EXPECT_EQ(m.at("h_min").as_number(), h_min) << name;
    EXPECT_EQ(m.at("h_max").as_number(), h_max) << name;
    for (const char* key : {"nx", "ny", "nz", "generator"}) {
      EXPECT_FALSE(summary.contains(key)) << name << ": " << key;
      EXPECT_FALSE(m.contains(key)) << name << ": " << key;
    }
    EXPECT_EQ(summary.contains("max_abs_uz"), mesh.dim() == 3) << name;
    EXPECT_EQ(summary.contains("uz_corner"), mesh.dim() == 3) << name;
  }
}

}  // namespace
}  // namespace pc

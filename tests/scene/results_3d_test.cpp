// A 3D run's results carry the third dimension (issue 16): summary.json has max|u_z| and u_z at the
// corner and says what the mesh is, grid.csv samples the volume output.grid gives (a z column, u_z and
// v_z), history.csv has u_z at the corner, and gamma_c.csv holds the contact nodes' own dof values (a
// clamped node reads exact zeros). 2D results keep their columns and keys. Generated meshes only (no gmsh).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "assembly/blas_info.hpp"
#include "models/scene/json.hpp"
#include "models/scene/scene_runner.hpp"
#include "support/csv_table.hpp"
#include "support/error_and_temp_dir.hpp"
#include "support/shipped_scenes.hpp"
#include "support/simplex_edges.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

using testing::error_of;
using testing::simplex_edge_range;

const std::string& kPaper = testing::kPaperScene;
const std::string& kBox = testing::kBoxScene;

// box3d.json on a generated 6 x 2 x 2 tetrahedral mesh (cells of 5 mm), 4 steps to T, with a grid whose
// points are the mesh's nodes.
const std::vector<std::string> kCoarseBox = [] {
  std::vector<std::string> overrides = testing::generated_box(6, 2, 2, "tetrahedron");
  overrides.insert(overrides.end(),
                   {R"(output.grid={"x": [0, 0.03, 7], "y": [0, 0.01, 3], "z": [0, 0.01, 3]})", "time.steps=4"});
  return overrides;
}();

const std::vector<std::string> kCoarsePaper = {"mesh.nx=6", "mesh.ny=2", "time.steps=4",
                                               R"(output.grid={"x": [0, 0.03, 7], "y": [0, 0.01, 3]})"};

using testing::read_csv;
using testing::Table;

// One foundation's run into a fresh directory, its model kept for the nodal values.
class RunFixture : public testing::TemporaryDirectoryTest {
 protected:
  void run(const std::string& scene_file, const std::vector<std::string>& overrides, const std::string& foundation) {
    scene_ = std::make_unique<Scene>(load_scene_file(scene_file, overrides));
    run_ = std::make_unique<FoundationRun>(*scene_, find_foundation(*scene_, foundation));
    result_ = run_->run(directory_.string(), false);
    ASSERT_TRUE(result_.completed) << result_.message;
    summary_ = read_json_file((directory_ / "summary.json").string());
  }
  const Model& model() const { return run_->model(); }
  // The scalar dof of the velocity space at a point (a mesh node of a P1 space), or -1.
  int dof_at(const std::array<double, 3>& x) const {
    const FESpace& space = model().space("v");
    for (int s = 0; s < space.num_scalar_dofs(); ++s) {
      const auto p = space.scalar_dof_point(s);
      if (std::abs(p[0] - x[0]) + std::abs(p[1] - x[1]) + std::abs(p[2] - x[2]) < 1e-12) return s;
    }
    return -1;
  }
  double nodal(const std::string& field, int scalar_dof, int component) const {
    return model().values(field)[model().space(field).dof(scalar_dof, component)];
  }

  std::unique_ptr<Scene> scene_;
  std::unique_ptr<FoundationRun> run_;
  FoundationRunResult result_;
  Json summary_;
};

using Results3D = RunFixture;

TEST_F(Results3D, SummaryHasUzAndDescribesTheGeneratedMesh) {
  run(kBox, kCoarseBox, "conductive");
  double max_uz = 0;
  const FESpace& space = model().space("u");
  for (int s = 0; s < space.num_scalar_dofs(); ++s) max_uz = std::max(max_uz, std::abs(nodal("u", s, 2)));
  EXPECT_GT(max_uz, 0);
  EXPECT_EQ(summary_.at("max_abs_uz").as_number(), max_uz);
  EXPECT_EQ(summary_.at("uz_corner").as_number(), result_.uz_corner);
  EXPECT_NE(result_.uz_corner, 0.0);  // the probe (0.03, 0.01, 0.005) reads u_z, not a missing component

  const Json mesh = summary_.at("mesh");
  EXPECT_EQ(mesh.at("source").as_string(), "generated");
  EXPECT_EQ(mesh.at("generator").as_string(), "box");
  EXPECT_EQ(mesh.at("nx").as_int(), 6);
  EXPECT_EQ(mesh.at("ny").as_int(), 2);
  EXPECT_EQ(mesh.at("nz").as_int(), 2);
  EXPECT_EQ(mesh.at("dim").as_int(), 3);
  EXPECT_EQ(mesh.at("nodes").as_int(), 7 * 3 * 3);
  EXPECT_EQ(mesh.at("cells").as_int(), model().mesh().num_cells());
  EXPECT_EQ(mesh.at("cell_type").as_string(), "tetrahedron");
  for (double h : mesh.at("h").as_vector(3)) EXPECT_DOUBLE_EQ(h, 0.005);
  const auto [h_min, h_max] = simplex_edge_range(model().mesh());
  EXPECT_EQ(mesh.at("h_min").as_number(), h_min);
  EXPECT_EQ(mesh.at("h_max").as_number(), h_max);
  EXPECT_NEAR(h_min, 0.005, 1e-15);
  EXPECT_EQ(summary_.at("nx").as_int(), 6);  // the top-level counts 2D readers know
  EXPECT_EQ(summary_.at("nz").as_int(), 2);
}

TEST_F(Results3D, GridSamplesTheVolumeWithZAndNodalValues) {
  run(kBox, kCoarseBox, "conductive");
  const Table grid = read_csv(directory_ / "grid.csv");
  EXPECT_EQ(grid.columns, (std::vector<std::string>{"x", "y", "z", "ux", "uy", "uz", "vx", "vy", "vz", "phi"}));
  ASSERT_EQ(grid.rows.size(), size_t(7 * 3 * 3));
  std::set<double> zs;
  for (const auto& row : grid.rows) zs.insert(row[2]);
  EXPECT_EQ(zs, (std::set<double>{0.0, 0.005, 0.01}));  // the z range given, both ends included
  EXPECT_EQ(grid.rows.front()[2], 0.0);                 // x fastest, z slowest
  EXPECT_EQ(grid.rows.back()[2], 0.01);
  EXPECT_EQ(grid.rows[1][0], 0.005);
  // Every grid point is a mesh node: u, v and phi there are the nodal values, to the round-off of locating
  // the point (relative to the field's largest value).
  std::map<std::string, double> scale;
  for (const char* field : {"u", "v", "phi"}) scale[field] = model().values(field).cwiseAbs().maxCoeff();
  EXPECT_GT(scale["v"], 0);
  for (const auto& row : grid.rows) {
    const int s = dof_at({row[0], row[1], row[2]});
    ASSERT_GE(s, 0);
    for (int d = 0; d < 3; ++d) {
      EXPECT_NEAR(row[3 + d], nodal("u", s, d), 1e-12 * scale["u"]);
      EXPECT_NEAR(row[6 + d], nodal("v", s, d), 1e-12 * scale["v"]);
    }
    EXPECT_NEAR(row[9], nodal("phi", s, 0), 1e-12 * scale["phi"]);
  }
  // u_z is not the zero of a missing column: it reaches max|u_z| of the summary at some node.
  double grid_max_uz = 0;
  for (const auto& row : grid.rows) grid_max_uz = std::max(grid_max_uz, std::abs(row[5]));
  EXPECT_NEAR(grid_max_uz, summary_.at("max_abs_uz").as_number(), 1e-12 * scale["u"]);
}

TEST_F(Results3D, HistoryHasUzAtTheCorner) {
  run(kBox, kCoarseBox, "conductive");
  const Table history = read_csv(directory_ / "history.csv");
  EXPECT_EQ(history.columns, (std::vector<std::string>{
                                 "t",          "uy_corner",     "uz_corner",   "phi_center",    "newton_iterations",
                                 "dt",         "err_time_step", "err_time_u",  "err_time_v",    "err_time_phi",
                                 "contact_fx", "contact_fy",    "contact_fz",  "contact_power", "E_kinetic",
                                 "E_elastic",  "E_electric",    "W_numerical", "W_viscous",     "W_contact",
                                 "W_coupling", "W_other",       "W_external",  "W_boundary",    "E_balance"}));
  ASSERT_EQ(history.rows.size(), size_t(4));  // one row per step
  EXPECT_EQ(history.rows.back()[2], summary_.at("uz_corner").as_number());
  EXPECT_EQ(history.rows.back()[1], summary_.at("uy_corner").as_number());
}

// Clamped contact nodes (x = 0) read exact zeros for v and the contact pressure, and counting v_nu > 0
// (v_nu = -v_y on y = 0) gives exactly the nodes in contact.
void expect_exact_contact_table(const Table& gamma, int dim, int n_contact_nodes) {
  const int p = gamma.column("contact_pressure"), vy = gamma.column("vy");
  int clamped = 0, pressed = 0, approaching = 0;
  for (const auto& row : gamma.rows) {
    if (row[p] > 0) ++pressed;
    if (-row[vy] > 0) ++approaching;
    if (row[0] != 0.0) continue;
    ++clamped;
    for (const char* c : {"ux", "uy", "uz", "vx", "vy", "vz"})
      if (dim == 3 || std::string(c).back() != 'z') {
        EXPECT_EQ(row[gamma.column(c)], 0.0) << c;
      }
    EXPECT_EQ(row[p], 0.0);
  }
  EXPECT_GT(clamped, 0);
  EXPECT_GT(pressed, 0);
  EXPECT_EQ(approaching, pressed);
  EXPECT_EQ(pressed, n_contact_nodes);
}

// The insulated runs are pressed onto the foundation at T (the conductive ones lift off).
TEST_F(Results3D, ContactTableHoldsNodalValuesWithExactZerosAtClampedNodes) {
  run(kBox, kCoarseBox, "insulated");
  const Table gamma = read_csv(directory_ / "gamma_c.csv");
  EXPECT_EQ(gamma.rows.size(), size_t(7 * 3));  // the nodes of y = 0
  expect_exact_contact_table(gamma, 3, summary_.at("n_contact_nodes").as_int());
}

TEST_F(Results3D, A2DContactTableHasExactZerosAtClampedNodesToo) {
  run(kPaper, kCoarsePaper, "insulated");
  const Table gamma = read_csv(directory_ / "gamma_c.csv");
  EXPECT_EQ(gamma.rows.size(), size_t(7));
  expect_exact_contact_table(gamma, 2, summary_.at("n_contact_nodes").as_int());
}

// A 2D run keeps its columns and keys, and says what its mesh is.
TEST_F(Results3D, A2DRunKeepsItsColumnsAndKeysAndDescribesItsMesh) {
  run(kPaper, kCoarsePaper, "conductive");
  EXPECT_EQ(read_csv(directory_ / "grid.csv").columns,
            (std::vector<std::string>{"x", "y", "ux", "uy", "vx", "vy", "phi"}));
  EXPECT_EQ(read_csv(directory_ / "history.csv").columns,
            (std::vector<std::string>{
                "t",          "uy_corner",  "phi_center",   "newton_iterations", "dt",         "err_time_step",
                "err_time_u", "err_time_v", "err_time_phi", "contact_fx",        "contact_fy", "contact_power",
                "E_kinetic",  "E_elastic",  "E_electric",   "W_numerical",       "W_viscous",  "W_contact",
                "W_coupling", "W_other",    "W_external",   "W_boundary",        "E_balance"}));
  EXPECT_EQ(summary_.at("nx").as_int(), 6);
  EXPECT_EQ(summary_.at("ny").as_int(), 2);
  for (const char* key : {"nz", "max_abs_uz", "uz_corner"}) EXPECT_FALSE(summary_.contains(key)) << key;
  for (const char* key : {"max_abs_ux", "max_abs_uy", "ux_corner", "uy_corner", "phi_center", "n_contact_nodes"})
    EXPECT_TRUE(summary_.contains(key)) << key;
  const Json mesh = summary_.at("mesh");
  EXPECT_EQ(mesh.at("generator").as_string(), "rectangle");
  EXPECT_EQ(mesh.at("nodes").as_int(), 7 * 3);
  EXPECT_EQ(mesh.at("cells").as_int(), 6 * 2 * 2);
  EXPECT_EQ(mesh.at("cell_type").as_string(), "triangle");
  EXPECT_FALSE(mesh.contains("nz"));
  const auto [h_min, h_max] = simplex_edge_range(model().mesh());
  EXPECT_EQ(mesh.at("h_min").as_number(), h_min);
  EXPECT_EQ(mesh.at("h_max").as_number(), h_max);
  // Which BLAS kernels rounded this run (issue 44): the same the process reports.
  const Json blas = summary_.at("blas");
  EXPECT_EQ(blas.at("vendor").as_string(), blas_info().vendor);
  EXPECT_EQ(blas.at("core").as_string(), blas_info().core);
  EXPECT_EQ(blas.at("library").as_string(), blas_info().library);
}

// A 3D grid must say which z it samples; a 2D one has no z.
TEST(Results3DGrid, A3DGridWithoutZAndA2DGridWithZAreRefusedNamingTheKey) {
  std::vector<std::string> no_z = kCoarseBox;
  no_z.push_back(R"(output.grid={"x": [0, 0.03, 7], "y": [0, 0.01, 3]})");
  EXPECT_CONTAINS(error_of([&] { load_scene_file(kBox, no_z); }), "'output.grid.z' is required in a 3D scene");
  std::vector<std::string> with_z = kCoarsePaper;
  with_z.push_back(R"(output.grid.z=[0, 0.01, 3])");
  EXPECT_CONTAINS(error_of([&] { load_scene_file(kPaper, with_z); }), "'output.grid.z' is given, but the scene is 2D");
}

// A plane of a 3D scene is a z range of one point.
TEST(Results3DGrid, APlaneIsAZRangeOfOnePoint) {
  std::vector<std::string> plane = kCoarseBox;
  plane.push_back(R"(output.grid.z=[0.005, 0.005, 1])");
  const Scene scene = load_scene_file(kBox, plane);
  const auto points = scene.output.grid.points();
  ASSERT_EQ(points.size(), size_t(7 * 3));
  for (const auto& x : points) EXPECT_EQ(x[2], 0.005);
}

}  // namespace
}  // namespace pc

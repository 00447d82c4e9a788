// Import of gmsh meshes: .geo scripts meshed on the fly, .msh files (written here from the same scripts,
// so that no generated file lives in the repository), physical groups as regions, and the errors.
#include <gmock/gmock.h>
#include <gmsh.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "assembly/error.hpp"
#include "assembly/gmsh_import.hpp"

namespace pc {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

std::string data(const std::string& name) { return std::string(PIEZOCONTACT_TEST_DATA) + "/" + name; }

// A directory of this process's own, removed at exit of the test.
class GmshImportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ = fs::temp_directory_path() / ("piezocontact_" + std::to_string(getpid()) + "_" + test->name());
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  // Meshes a .geo script with gmsh directly and saves the mesh as a .msh file in the temporary directory.
  std::string write_msh(const std::string& geo, const std::string& name, bool binary = false) const {
    const std::string path = (directory_ / name).string();
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
    gmsh::open(data(geo));
    gmsh::model::mesh::generate(gmsh::model::getDimension());
    gmsh::write(path);
    gmsh::finalize();
    return path;
  }

  fs::path directory_;
};

std::string import_error(const std::string& path) {
  try {
    import_gmsh(path);
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "importing " << path << " did not throw";
  return "";
}

void expect_outward_normals(const Mesh& mesh, const std::string& region, std::array<double, 3> expected) {
  for (const FaceRef& f : mesh.face_region(region)) {
    const auto n = mesh.face_normal(f);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(n[i], expected[i], 1e-10) << region;
  }
}

void expect_rectangle(const Mesh& mesh) {
  EXPECT_EQ(mesh.dim(), 2);
  EXPECT_EQ(mesh.cell_shape(), Shape::Triangle);
  EXPECT_GT(mesh.num_cells(), 20);
  EXPECT_EQ(mesh.region_kind("body"), RegionKind::Cells);
  EXPECT_EQ(mesh.region_kind("contact"), RegionKind::Faces);
  EXPECT_NEAR(mesh.region_measure("contact"), 0.03, 1e-14);
  EXPECT_NEAR(mesh.region_measure("top"), 0.03, 1e-14);
  EXPECT_NEAR(mesh.region_measure("clamped"), 0.01, 1e-14);
  EXPECT_NEAR(mesh.region_measure("body"), 3e-4, 1e-16);
  EXPECT_NEAR(mesh.region_measure("all"), 3e-4, 1e-16);
  EXPECT_NEAR(mesh.region_measure("boundary"), 0.08, 1e-14);
  expect_outward_normals(mesh, "contact", {0, -1, 0});
  expect_outward_normals(mesh, "top", {0, 1, 0});
  expect_outward_normals(mesh, "clamped", {-1, 0, 0});
}

void expect_box(const Mesh& mesh) {
  EXPECT_EQ(mesh.dim(), 3);
  EXPECT_EQ(mesh.cell_shape(), Shape::Tetrahedron);
  EXPECT_GT(mesh.num_cells(), 100);
  EXPECT_NEAR(mesh.region_measure("contact"), 3e-4, 1e-16);
  EXPECT_NEAR(mesh.region_measure("top"), 3e-4, 1e-16);
  EXPECT_NEAR(mesh.region_measure("clamped"), 1e-4, 1e-16);
  EXPECT_NEAR(mesh.region_measure("body"), 3e-6, 1e-18);
  EXPECT_NEAR(mesh.region_measure("all"), 3e-6, 1e-18);
  EXPECT_NEAR(mesh.region_measure("boundary"), 2 * (3e-4 + 3e-4 + 1e-4), 1e-16);
  expect_outward_normals(mesh, "contact", {0, -1, 0});
  expect_outward_normals(mesh, "top", {0, 1, 0});
  expect_outward_normals(mesh, "clamped", {-1, 0, 0});
}

TEST_F(GmshImportTest, RectangleFromGeo) { expect_rectangle(import_gmsh(data("rectangle.geo"))); }

TEST_F(GmshImportTest, BoxFromGeo) { expect_box(import_gmsh(data("box.geo"))); }

TEST_F(GmshImportTest, RectangleAndBoxFromMsh) {
  const Mesh rectangle = import_gmsh(write_msh("rectangle.geo", "rectangle.msh"));
  expect_rectangle(rectangle);
  EXPECT_EQ(rectangle.num_cells(), import_gmsh(data("rectangle.geo")).num_cells());

  const Mesh box = import_gmsh(write_msh("box.geo", "box.msh"));
  expect_box(box);
  EXPECT_EQ(box.num_cells(), import_gmsh(data("box.geo")).num_cells());
}

TEST_F(GmshImportTest, MeshSizeFactorRefines) {
  const Mesh coarse = import_gmsh(data("rectangle.geo"));
  const Mesh fine = import_gmsh(data("rectangle.geo"), {.mesh_size_factor = 0.5});
  EXPECT_GT(fine.num_cells(), 2 * coarse.num_cells());
  EXPECT_NEAR(fine.region_measure("body"), 3e-4, 1e-16);
}

TEST_F(GmshImportTest, ClockwiseSurfacesArePositivelyOriented) {
  // The Mesh constructor rejects negatively oriented cells, so importing at all shows the reordering.
  const Mesh quads = import_gmsh(data("clockwise_quads.geo"));
  EXPECT_EQ(quads.cell_shape(), Shape::Quadrilateral);
  EXPECT_EQ(quads.num_cells(), 12);
  EXPECT_EQ(quads.num_nodes(), 21);
  EXPECT_NEAR(quads.region_measure("body"), 3e-4, 1e-16);
  EXPECT_NEAR(quads.region_measure("contact"), 0.03, 1e-14);
  expect_outward_normals(quads, "contact", {0, -1, 0});

  const Mesh triangles = import_gmsh(data("clockwise_triangles.geo"));
  EXPECT_EQ(triangles.cell_shape(), Shape::Triangle);
  EXPECT_NEAR(triangles.region_measure("body"), 3e-4, 1e-16);
  expect_outward_normals(triangles, "contact", {0, -1, 0});
}

TEST_F(GmshImportTest, UnnamedPhysicalGroupsAreNamedByTag) {
  const fs::path geo = directory_ / "unnamed.geo";
  std::ofstream(geo) << "Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {0, 1, 0, 0.5};\n"
                        "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};\n"
                        "Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};\n"
                        "Physical Curve(7) = {2}; Physical Surface(3) = {1};\n";
  const Mesh mesh = import_gmsh(geo.string());
  EXPECT_NEAR(mesh.region_measure("physical_7"), std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(mesh.region_measure("physical_3"), 0.5, 1e-14);
}

TEST_F(GmshImportTest, Errors) {
  EXPECT_EQ(import_error("/nonexistent/body.msh"), "gmsh: cannot open '/nonexistent/body.msh': no such file");
  EXPECT_THAT(import_error(data("second_order.geo")), HasSubstr("second-order cells (Triangle 6)"));
  EXPECT_THAT(import_error(data("mixed_shapes.geo")), HasSubstr("mixes cell shapes"));

  const fs::path garbage = directory_ / "garbage.msh";
  std::ofstream(garbage) << "this is not a mesh\n";
  EXPECT_THAT(import_error(garbage.string()), HasSubstr("gmsh: cannot read '" + garbage.string() + "'"));

  const fs::path bad_geo = directory_ / "bad.geo";
  std::ofstream(bad_geo) << "Point(1) = {0, 0, 0};\nfoo bar;\n";
  const std::string bad_geo_error = import_error(bad_geo.string());
  EXPECT_THAT(bad_geo_error, HasSubstr("gmsh: cannot read '" + bad_geo.string() + "'"));
  EXPECT_THAT(bad_geo_error, HasSubstr("line 2"));

  // Importing still works after failures: every import has a gmsh session of its own.
  expect_rectangle(import_gmsh(data("rectangle.geo")));
}

// A .geo script is a program that gmsh runs in a child process: whatever it does is reported, and the
// caller goes on (issue 11, case 11).
TEST_F(GmshImportTest, AScriptThatEndsGmshIsReportedAndTheCallerGoesOn) {
  const fs::path script = directory_ / "exits.geo";
  std::ofstream(script) << "Point(1) = {0, 0, 0};\nExit;\n";
  EXPECT_THAT(import_error(script.string()), HasSubstr("does it call 'Exit'?"));
  expect_rectangle(import_gmsh(data("rectangle.geo")));
}

TEST_F(GmshImportTest, AStatementMissingItsSemicolonIsNamedAtItsOwnLine) {
  const fs::path script = directory_ / "semicolon.geo";
  std::ofstream(script) << "// a comment\nPoint(1) = {0, 0, 0, 1}\n\nPoint(2) = {1, 0, 0, 1};\n";
  const std::string error = import_error(script.string());
  EXPECT_THAT(error, HasSubstr("line 4: syntax error"));
  EXPECT_THAT(error, HasSubstr("line 2 above it does not end with ';': 'Point(1) = {0, 0, 0, 1}'"));
}

TEST_F(GmshImportTest, WhatAScriptPrintsStaysOutOfTheCallersOutput) {
  const fs::path script = directory_ / "prints.geo";
  std::ofstream(script) << "Printf(\"SCRIPT-OUTPUT\");\nInclude \"" << data("rectangle.geo") << "\";\n";
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  const Mesh mesh = import_gmsh(script.string());
  const std::string out = ::testing::internal::GetCapturedStdout() + ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(out.find("SCRIPT-OUTPUT"), std::string::npos) << out;
  expect_rectangle(mesh);
}

TEST_F(GmshImportTest, MeshingPastItsTimeBudgetIsStopped) {
  GmshOptions options;
  options.mesh_size_factor = 1e-6;  // some 10^12 triangles: it would mesh for hours
  options.max_seconds = 1;
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  try {
    import_gmsh(data("rectangle.geo"), options);
  } catch (const Error& e) {
    error = e.what();
  }
  EXPECT_THAT(error, HasSubstr("meshing took more than 1 s (mesh.max_seconds) and was stopped"));
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30);
}

TEST_F(GmshImportTest, AMeshFromAScriptIsTheMeshGmshMade) {
  // The child hands the mesh back as a binary .msh: the coordinates arrive bit for bit, as from gmsh
  // meshing in this process.
  const Mesh from_script = import_gmsh(data("box.geo"));
  const Mesh from_file = import_gmsh(write_msh("box.geo", "box.msh", /*binary=*/true));
  ASSERT_EQ(from_script.num_nodes(), from_file.num_nodes());
  ASSERT_EQ(from_script.num_cells(), from_file.num_cells());
  for (int n = 0; n < from_script.num_nodes(); ++n)
    for (int d = 0; d < 3; ++d) EXPECT_EQ(from_script.node(n)[d], from_file.node(n)[d]);
}

}  // namespace
}  // namespace pc

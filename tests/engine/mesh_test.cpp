// Mesh construction and validation, regions, measures and normals, the structured generators, and the
// first-order cell geometry.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "assembly/cell_geometry.hpp"
#include "assembly/error.hpp"
#include "assembly/mesh.hpp"
#include "assembly/mesh_generators.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

using ::testing::HasSubstr;

using testing::error_of;

void expect_normals(const Mesh& mesh, const std::string& region, std::array<double, 3> expected) {
  for (const FaceRef& f : mesh.face_region(region)) {
    const auto n = mesh.face_normal(f);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(n[i], expected[i], 1e-12) << region << " component " << i;
  }
}

double total_cell_measure(const Mesh& mesh) {
  double sum = 0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    EXPECT_GT(mesh.cell_measure(c), 0) << "cell " << c;
    sum += mesh.cell_measure(c);
  }
  return sum;
}

class RectangleMeshTest : public ::testing::TestWithParam<Shape> {};

TEST_P(RectangleMeshTest, CountsMeasuresAndNormals) {
  const Shape shape = GetParam();
  const Mesh mesh = rectangle_mesh({-1.0, 2.0}, {2.0, 3.0}, 3, 2, shape);
  EXPECT_EQ(mesh.dim(), 2);
  EXPECT_EQ(mesh.cell_shape(), shape);
  EXPECT_EQ(mesh.num_nodes(), 4 * 3);
  EXPECT_EQ(mesh.num_cells(), shape == Shape::Triangle ? 12 : 6);
  EXPECT_EQ(mesh.boundary_faces().size(), 10u);

  EXPECT_NEAR(mesh.region_measure("all"), 3.0, 1e-13);
  EXPECT_NEAR(total_cell_measure(mesh), 3.0, 1e-13);
  EXPECT_NEAR(mesh.region_measure("boundary"), 8.0, 1e-13);
  EXPECT_NEAR(mesh.region_measure("xmin"), 1.0, 1e-13);
  EXPECT_NEAR(mesh.region_measure("xmax"), 1.0, 1e-13);
  EXPECT_NEAR(mesh.region_measure("ymin"), 3.0, 1e-13);
  EXPECT_NEAR(mesh.region_measure("ymax"), 3.0, 1e-13);
  EXPECT_EQ(mesh.face_region("xmin").size(), 2u);
  EXPECT_EQ(mesh.face_region("ymax").size(), 3u);

  EXPECT_EQ(mesh.face_region("left"), mesh.face_region("xmin"));
  EXPECT_EQ(mesh.face_region("right"), mesh.face_region("xmax"));
  EXPECT_EQ(mesh.face_region("bottom"), mesh.face_region("ymin"));
  EXPECT_EQ(mesh.face_region("top"), mesh.face_region("ymax"));

  expect_normals(mesh, "left", {-1, 0, 0});
  expect_normals(mesh, "right", {1, 0, 0});
  expect_normals(mesh, "bottom", {0, -1, 0});
  expect_normals(mesh, "top", {0, 1, 0});
  EXPECT_EQ(mesh.region_kind("all"), RegionKind::Cells);
  EXPECT_EQ(mesh.region_kind("top"), RegionKind::Faces);
}

INSTANTIATE_TEST_SUITE_P(Shapes, RectangleMeshTest, ::testing::Values(Shape::Triangle, Shape::Quadrilateral),
                         [](const auto& info) { return to_string(info.param); });

class BoxMeshTest : public ::testing::TestWithParam<Shape> {};

TEST_P(BoxMeshTest, CountsMeasuresAndNormals) {
  const Shape shape = GetParam();
  const Mesh mesh = box_mesh({0.0, -1.0, 1.0}, {3.0, 1.0, 2.0}, 3, 2, 2, shape);
  const bool tets = shape == Shape::Tetrahedron;
  EXPECT_EQ(mesh.dim(), 3);
  EXPECT_EQ(mesh.num_nodes(), 4 * 3 * 3);
  EXPECT_EQ(mesh.num_cells(), (tets ? 6 : 1) * 12);
  // 2 * (3*2 + 2*2 + 3*2) squares on the boundary, each split into two triangles for tetrahedra. A
  // non-conforming split would leave unmatched interior faces and increase this count.
  EXPECT_EQ(mesh.boundary_faces().size(), (tets ? 2u : 1u) * 32u);

  EXPECT_NEAR(mesh.region_measure("all"), 6.0, 1e-13);
  EXPECT_NEAR(total_cell_measure(mesh), 6.0, 1e-13);
  EXPECT_NEAR(mesh.region_measure("boundary"), 2 * (6.0 + 2.0 + 3.0), 1e-13);
  EXPECT_NEAR(mesh.region_measure("xmin"), 2.0, 1e-13);
  EXPECT_NEAR(mesh.region_measure("xmax"), 2.0, 1e-13);
  EXPECT_NEAR(mesh.region_measure("ymin"), 3.0, 1e-13);
  EXPECT_NEAR(mesh.region_measure("ymax"), 3.0, 1e-13);
  EXPECT_NEAR(mesh.region_measure("zmin"), 6.0, 1e-13);
  EXPECT_NEAR(mesh.region_measure("zmax"), 6.0, 1e-13);
  EXPECT_FALSE(mesh.has_region("left"));

  expect_normals(mesh, "xmin", {-1, 0, 0});
  expect_normals(mesh, "xmax", {1, 0, 0});
  expect_normals(mesh, "ymin", {0, -1, 0});
  expect_normals(mesh, "ymax", {0, 1, 0});
  expect_normals(mesh, "zmin", {0, 0, -1});
  expect_normals(mesh, "zmax", {0, 0, 1});
}

INSTANTIATE_TEST_SUITE_P(Shapes, BoxMeshTest, ::testing::Values(Shape::Tetrahedron, Shape::Hexahedron),
                         [](const auto& info) { return to_string(info.param); });

TEST(MeshGenerators, RejectBadArguments) {
  EXPECT_THAT(error_of([] {
                rectangle_mesh({0, 0}, {1, 1}, 0, 1);
              }),
              HasSubstr("rectangle_mesh: nx must be at least 1, got 0"));
  EXPECT_THAT(error_of([] { rectangle_mesh({0, 1}, {1, 1}, 1, 1); }), HasSubstr("upper y"));
  EXPECT_THAT(error_of([] { box_mesh({0, 0, 0}, {1, 1, 1}, 1, 1, -2); }), HasSubstr("nz must be at least 1"));
  EXPECT_THAT(error_of([] { box_mesh({0, 0, 2}, {1, 1, 1}, 1, 1, 1); }), HasSubstr("upper z"));
  EXPECT_THAT(error_of([] {
                box_mesh({0, 0, 0}, {1, 1, 1}, 1, 1, 1, Shape::Triangle);
              }),
              HasSubstr("shape must be tetrahedron or hexahedron"));
}

TEST(Mesh, DistortedQuadrilateralAndHexahedronMeasures) {
  // Shoelace area of the quadrilateral (0,0) (2,0) (3,2) (0,1): 3.5.
  const Mesh quad(2, Shape::Quadrilateral, {0, 0, 2, 0, 3, 2, 0, 1}, {0, 1, 2, 3});
  EXPECT_NEAR(quad.cell_measure(0), 3.5, 1e-14);
  EXPECT_NEAR(quad.region_measure("boundary"), 2 + std::sqrt(5.0) + std::sqrt(10.0) + 1, 1e-14);

  // The parallelepiped spanned by a = (2,0,0), b = (1,1,0), c = (0,1,3): volume det[a b c] = 6.
  std::vector<double> xyz;
  const int corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int k = 0; k < 2; ++k)
    for (const auto& [i, j] : corners) xyz.insert(xyz.end(), {2.0 * i + j, 1.0 * j + k, 3.0 * k});
  const Mesh hex(3, Shape::Hexahedron, xyz, {0, 1, 2, 3, 4, 5, 6, 7});
  EXPECT_NEAR(hex.cell_measure(0), 6.0, 1e-13);
  // Faces: |a x b| = 2 (z = 0 and z = 3), |a x c| = 2 sqrt 10, |b x c| = sqrt 19.
  EXPECT_NEAR(hex.region_measure("boundary"), 2 * (2 + 2 * std::sqrt(10.0) + std::sqrt(19.0)), 1e-13);
  // The face z = 0 (local face 4) points down, whatever its vertex order.
  const auto n = hex.face_normal({0, 4});
  EXPECT_NEAR(n[2], -1, 1e-14);
}

TEST(Mesh, RegionsAreSortedAndUnique) {
  Mesh mesh = rectangle_mesh({0, 0}, {1, 1}, 2, 2);
  mesh.add_cell_region("some", {3, 1, 1, 2});
  EXPECT_EQ(mesh.cell_region("some"), (std::vector<int>{1, 2, 3}));
  mesh.add_face_region("pair", {{5, 1}, {0, 0}, {5, 1}});
  EXPECT_EQ(mesh.face_region("pair"), (std::vector<FaceRef>{{0, 0}, {5, 1}}));
  const std::vector<std::string> names = {"all",  "bottom", "boundary", "left", "pair", "right",
                                          "some", "top",    "xmax",     "xmin", "ymax", "ymin"};
  EXPECT_EQ(mesh.region_names(), names);
}

TEST(Mesh, RegionErrors) {
  Mesh mesh = rectangle_mesh({0, 0}, {1, 1}, 2, 2);
  EXPECT_THAT(error_of([&] { mesh.face_region("topp"); }),
              HasSubstr("unknown region 'topp'; the mesh has: all, bottom, boundary, left, right, top, xmax, "
                        "xmin, ymax, ymin"));
  EXPECT_THAT(error_of([&] { mesh.region_measure("topp"); }), HasSubstr("unknown region 'topp'"));
  EXPECT_THAT(error_of([&] { mesh.cell_region("left"); }),
              HasSubstr("region 'left' is a face region, not a cell region"));
  EXPECT_THAT(error_of([&] { mesh.face_region("all"); }),
              HasSubstr("region 'all' is a cell region, not a face region"));
  EXPECT_THAT(error_of([&] { mesh.add_face_region("nothing", {}); }), HasSubstr("region 'nothing' is empty"));
  EXPECT_THAT(error_of([&] { mesh.add_boundary_region_where("far", [](auto x) { return x[0] > 5; }); }),
              HasSubstr("region 'far' is empty"));
  EXPECT_THAT(error_of([&] { mesh.add_cell_region("left", {0}); }),
              HasSubstr("region 'left' already exists (a face region)"));
  EXPECT_THAT(error_of([&] {
                mesh.add_face_region("all", {{0, 0}});
              }),
              HasSubstr("region 'all' already exists (a cell region)"));
  EXPECT_THAT(error_of([&] {
                mesh.add_cell_region("bad", {0, 8});
              }),
              HasSubstr("cell region 'bad': cell 8 does not exist (the mesh has 8 cells)"));
  EXPECT_THAT(error_of([&] {
                mesh.add_face_region("bad", {{0, 3}});
              }),
              HasSubstr("face region 'bad': face (cell 0, local face 3) does not exist"));
  EXPECT_FALSE(mesh.has_region("bad"));
}

TEST(Mesh, RejectsInvalidCells) {
  const std::vector<double> square = {0, 0, 1, 0, 1, 1, 0, 1};
  EXPECT_THAT(error_of([&] {
                Mesh(2, Shape::Triangle, square, {0, 1, 2, 0, 3, 2});
              }),
              HasSubstr("cell 1 (nodes 0 3 2) is inverted: det J = -1"));
  EXPECT_THAT(error_of([&] {
                Mesh(2, Shape::Triangle, {0, 0, 1, 0, 2, 1e-14}, {0, 1, 2});
              }),
              HasSubstr("cell 0 (nodes 0 1 2) is degenerate: det J = "));
  // A self-intersecting ("bow-tie") quadrilateral has det J < 0 at two of its vertices.
  EXPECT_THAT(error_of([&] {
                Mesh(2, Shape::Quadrilateral, square, {0, 1, 3, 2});
              }),
              HasSubstr("cell 0 (nodes 0 1 3 2) is inverted: det J = "));
  EXPECT_THAT(error_of([&] {
                Mesh(2, Shape::Triangle, square, {0, 1, 2, 0, 2, 4});
              }),
              HasSubstr("cell 1 (nodes 0 2 4) refers to node 4, but the mesh has 4 nodes"));
  EXPECT_THAT(error_of([&] {
                Mesh(2, Shape::Triangle, square, {0, 1, 1});
              }),
              HasSubstr("cell 0 (nodes 0 1 1) repeats node 1"));
  EXPECT_THAT(error_of([&] {
                Mesh(3, Shape::Triangle, {0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 2});
              }),
              HasSubstr("triangle cells have dimension 2 but the mesh has dim 3"));
  EXPECT_THAT(error_of([&] { Mesh(2, Shape::Triangle, {0, 0, 1}, {0, 1, 2}); }), HasSubstr("not a multiple of dim 2"));
  EXPECT_THAT(error_of([&] { Mesh(2, Shape::Triangle, square, {}); }), HasSubstr("no cells"));

  // An inverted tetrahedron: two vertices of the reference tetrahedron swapped.
  const std::vector<double> unit_tet = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  EXPECT_THAT(error_of([&] {
                Mesh(3, Shape::Tetrahedron, unit_tet, {0, 2, 1, 3});
              }),
              HasSubstr("cell 0 (nodes 0 2 1 3) is inverted: det J = -1"));
}

TEST(Mesh, RejectsNonManifoldFaces) {
  // Three triangles on the edge 0-1.
  const std::vector<double> xyz = {0, 0, 1, 0, 0.5, 1, 0.5, -1, 0.5, 2};
  EXPECT_THAT(error_of([&] {
                Mesh(2, Shape::Triangle, xyz, {0, 1, 2, 1, 0, 3, 0, 1, 4});
              }),
              HasSubstr("non-manifold mesh: the face with nodes 0 1 is shared by 3 cells (0 1 2)"));
}

TEST(Mesh, DegeneracyIsRelativeToCellSize) {
  // A well-shaped micrometre-sized cell is not degenerate.
  const Mesh tiny(2, Shape::Triangle, {0, 0, 1e-6, 0, 0, 1e-6}, {0, 1, 2});
  EXPECT_NEAR(tiny.cell_measure(0), 0.5e-12, 1e-24);
}

TEST(CellGeometry, RoundTripsThroughTheReferenceCell) {
  const Mesh quad(2, Shape::Quadrilateral, {10, 10, 12, 10, 13, 12, 10, 11}, {0, 1, 2, 3});
  const Mesh hex = box_mesh({0, 0, 0}, {1, 2, 3}, 1, 1, 1, Shape::Hexahedron);
  const Mesh tet = box_mesh({0, 0, 0}, {1, 2, 3}, 1, 1, 1, Shape::Tetrahedron);
  for (const Mesh* mesh : {&quad, &hex, &tet}) {
    const double xi[3] = {0.3, 0.1, 0.2};
    const auto x = map_to_physical(*mesh, 0, xi);
    double back[3] = {};
    ASSERT_TRUE(map_to_reference(*mesh, 0, x.data(), back)) << to_string(mesh->cell_shape());
    for (int j = 0; j < mesh->dim(); ++j) EXPECT_NEAR(back[j], xi[j], 1e-12) << to_string(mesh->cell_shape());
    EXPECT_TRUE(inside_reference(mesh->cell_shape(), back, 1e-12));
  }
  double J[4];
  const double corner[2] = {0, 0};
  EXPECT_NEAR(cell_jacobian(quad, 0, corner, J), 2.0, 1e-14);
  EXPECT_NEAR(J[0], 2, 1e-14);  // dx/dxi along the edge 0-1
  EXPECT_NEAR(J[3], 1, 1e-14);  // dy/deta along the edge 0-3
}

// G = J^-T by cofactors: the chain rule's map from reference to physical gradients, G^T J = 1, on cells
// whose Jacobians are full (a skewed quadrilateral away from its corners, a skewed tetrahedron).
TEST(CellGeometry, TheInverseTransposeJacobianInvertsTheJacobian) {
  const Mesh quad(2, Shape::Quadrilateral, {10, 10, 12, 10.5, 13, 12, 9.5, 11}, {0, 1, 2, 3});
  const Mesh tet(3, Shape::Tetrahedron, {0, 0, 0, 2, 0.3, 0.1, 0.4, 1.5, -0.2, 0.3, 0.5, 3}, {0, 1, 2, 3});
  for (const Mesh* mesh : {&quad, &tet}) {
    const int dim = mesh->dim();
    const double xi[3] = {0.3, 0.1, 0.2};
    double J[9], G[9];
    const double det = cell_jacobian(*mesh, 0, xi, J);
    inverse_transpose_jacobian(dim, J, det, G);
    for (int k = 0; k < dim; ++k)
      for (int j = 0; j < dim; ++j) {
        double product = 0;  // (G^T J)_kj = sum_d G[d][k] J[d][j]
        for (int d = 0; d < dim; ++d) product += G[d * dim + k] * J[d * dim + j];
        EXPECT_NEAR(product, k == j ? 1.0 : 0.0, 1e-14) << to_string(mesh->cell_shape()) << " " << k << j;
        EXPECT_NE(J[k * dim + j], 0.0) << "a full Jacobian";
      }
  }
  double G = 0;
  const double J = 4;
  inverse_transpose_jacobian(1, &J, 4, &G);
  EXPECT_EQ(G, 0.25);
}

TEST(CellGeometry, InsideReference) {
  const double in_triangle[2] = {0.5, 0.5}, out_triangle[2] = {0.6, 0.5};
  EXPECT_TRUE(inside_reference(Shape::Triangle, in_triangle, 1e-12));
  EXPECT_FALSE(inside_reference(Shape::Triangle, out_triangle, 1e-12));
  EXPECT_TRUE(inside_reference(Shape::Quadrilateral, out_triangle, 1e-12));
  const double slightly_out[3] = {-1e-10, 1, 1};
  EXPECT_FALSE(inside_reference(Shape::Hexahedron, slightly_out, 1e-12));
  EXPECT_TRUE(inside_reference(Shape::Hexahedron, slightly_out, 1e-9));
  EXPECT_FALSE(inside_reference(Shape::Tetrahedron, slightly_out, 1e-9));
}

}  // namespace
}  // namespace pc

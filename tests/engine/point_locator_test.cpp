// Point location on straight and distorted meshes of every cell shape, including points on shared
// vertices, edges and faces and points outside a non-convex domain, and exact evaluation of fields.
#include "assembly/point_locator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "assembly/cell_geometry.hpp"
#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"

namespace pc {
namespace {

struct MeshCase {
  const char* name;
  Shape shape;
  bool distorted;
};

std::ostream& operator<<(std::ostream& out, const MeshCase& c) { return out << c.name; }

// The unit square or cube (shifted away from the origin) meshed with the case's shape. A distorted mesh
// moves its interior nodes, so that quadrilaterals and hexahedra have non-affine maps; the domain stays
// the same box.
Mesh make_mesh(const MeshCase& c) {
  const bool is_2d = dimension(c.shape) == 2;
  Mesh straight =
      is_2d ? rectangle_mesh({1, -1}, {2, 0}, 5, 4, c.shape) : box_mesh({1, -1, 0}, {2, 0, 1}, 3, 4, 3, c.shape);
  if (!c.distorted) return straight;
  const int dim = straight.dim();
  std::vector<double> coordinates = straight.coordinates();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> shift(-0.04, 0.04);  // below a fifth of the smallest cell edge
  const double lower[3] = {1, -1, 0}, upper[3] = {2, 0, 1};
  for (int n = 0; n < straight.num_nodes(); ++n) {
    bool interior = true;
    for (int d = 0; d < dim; ++d) {
      const double x = coordinates[n * dim + d];
      interior = interior && std::abs(x - lower[d]) > 1e-12 && std::abs(x - upper[d]) > 1e-12;
    }
    if (interior)
      for (int d = 0; d < dim; ++d) coordinates[n * dim + d] += shift(random);
  }
  return Mesh(dim, c.shape, coordinates, straight.connectivity());
}

// The point must be found, in a cell whose map reproduces it from the returned reference coordinates.
void expect_located(const PointLocator& locator, const Mesh& mesh, const std::array<double, 3>& x) {
  const auto hit = locator.locate(x.data());
  ASSERT_TRUE(hit.has_value()) << "(" << x[0] << ", " << x[1] << ", " << x[2] << ") not found";
  EXPECT_TRUE(inside_reference(mesh.cell_shape(), hit->xi.data(), 1e-9));
  const auto mapped = map_to_physical(mesh, hit->cell, hit->xi.data());
  for (int d = 0; d < mesh.dim(); ++d) EXPECT_NEAR(mapped[d], x[d], 1e-12);
}

std::array<double, 3> random_point_in_box(std::mt19937& random, int dim) {
  const double lower[3] = {1, -1, 0};
  std::uniform_real_distribution<double> unit(0, 1);
  std::array<double, 3> x{0, 0, 0};
  for (int d = 0; d < dim; ++d) x[d] = lower[d] + unit(random);
  return x;
}

class PointLocatorTest : public ::testing::TestWithParam<MeshCase> {};

TEST_P(PointLocatorTest, FindsRandomInteriorPoints) {
  const Mesh mesh = make_mesh(GetParam());
  const PointLocator locator(mesh);
  std::mt19937 random(1);
  for (int i = 0; i < 500; ++i) expect_located(locator, mesh, random_point_in_box(random, mesh.dim()));
}

TEST_P(PointLocatorTest, FindsVerticesEdgeMidpointsAndFaceCentres) {
  const Mesh mesh = make_mesh(GetParam());
  const PointLocator locator(mesh);
  const int dim = mesh.dim();
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    std::array<double, 3> x{0, 0, 0};
    for (int d = 0; d < dim; ++d) x[d] = mesh.node(n)[d];
    expect_located(locator, mesh, x);
  }
  const Shape shape = mesh.cell_shape();
  for (int c = 0; c < mesh.num_cells(); ++c) {
    for (int e = 0; e < num_edges(shape); ++e) {
      const auto ends = edge_vertices(shape, e);
      std::array<double, 3> x{0, 0, 0};
      for (int d = 0; d < dim; ++d)
        x[d] = 0.5 * (mesh.node(mesh.cell(c)[ends[0]])[d] + mesh.node(mesh.cell(c)[ends[1]])[d]);
      expect_located(locator, mesh, x);
    }
    // The centre of a (possibly bilinear) face is the mean of its vertices.
    for (int f = 0; f < num_faces(shape); ++f) {
      const auto corners = face_vertices(shape, f);
      std::array<double, 3> x{0, 0, 0};
      for (int v : corners)
        for (int d = 0; d < dim; ++d) x[d] += mesh.node(mesh.cell(c)[v])[d] / corners.size();
      expect_located(locator, mesh, x);
    }
  }
}

TEST_P(PointLocatorTest, FindsRandomPointsOnTheBoundary) {
  const Mesh mesh = make_mesh(GetParam());
  const PointLocator locator(mesh);
  const double lower[3] = {1, -1, 0}, upper[3] = {2, 0, 1};
  std::mt19937 random(2);
  for (int i = 0; i < 200; ++i) {
    auto x = random_point_in_box(random, mesh.dim());
    const int side = i % (2 * mesh.dim());
    x[side / 2] = side % 2 == 0 ? lower[side / 2] : upper[side / 2];
    expect_located(locator, mesh, x);
    // Round-off outside the boundary is within the tolerance.
    x[side / 2] += side % 2 == 0 ? -1e-13 : 1e-13;
    expect_located(locator, mesh, x);
  }
}

TEST_P(PointLocatorTest, PointsOutsideAreNotFound) {
  const Mesh mesh = make_mesh(GetParam());
  const PointLocator locator(mesh);
  const int dim = mesh.dim();
  const double lower[3] = {1, -1, 0}, upper[3] = {2, 0, 1};
  std::mt19937 random(3);
  for (int i = 0; i < 100; ++i) {
    auto x = random_point_in_box(random, dim);
    const int side = i % (2 * dim);
    // Just outside a side, or far away.
    const double gap = i % 3 == 0 ? 10.0 : 1e-6;
    x[side / 2] = side % 2 == 0 ? lower[side / 2] - gap : upper[side / 2] + gap;
    EXPECT_FALSE(locator.locate(x.data()).has_value());
    EXPECT_THROW(locator.locate_or_throw(x.data()), Error);
  }
  const double not_a_number[3] = {std::nan(""), 0.5, 0.5};
  EXPECT_FALSE(locator.locate(not_a_number).has_value());
}

INSTANTIATE_TEST_SUITE_P(Shapes, PointLocatorTest,
                         ::testing::Values(MeshCase{"triangles", Shape::Triangle, false},
                                           MeshCase{"quadrilaterals", Shape::Quadrilateral, false},
                                           MeshCase{"distorted_quadrilaterals", Shape::Quadrilateral, true},
                                           MeshCase{"tetrahedra", Shape::Tetrahedron, false},
                                           MeshCase{"hexahedra", Shape::Hexahedron, false},
                                           MeshCase{"distorted_hexahedra", Shape::Hexahedron, true}),
                         [](const auto& info) { return std::string(info.param.name); });

// An L-shaped domain: [0,2]^2 meshed with n x n squares, without the cells of one quarter (the upper
// right one, or the upper left one), nodes renumbered.
Mesh l_shape(Shape shape, int n = 4, bool without_upper_left = false) {
  const Mesh square = rectangle_mesh({0, 0}, {2, 2}, n, n, shape);
  std::vector<int> new_index(square.num_nodes(), -1), connectivity;
  std::vector<double> coordinates;
  for (int c = 0; c < square.num_cells(); ++c) {
    double centre[2] = {0, 0};
    for (int n : square.cell(c))
      for (int d = 0; d < 2; ++d) centre[d] += square.node(n)[d] / square.vertices_per_cell();
    if ((without_upper_left ? centre[0] < 1 : centre[0] > 1) && centre[1] > 1) continue;
    for (int n : square.cell(c)) {
      if (new_index[n] < 0) {
        new_index[n] = int(coordinates.size() / 2);
        coordinates.insert(coordinates.end(), square.node(n).begin(), square.node(n).end());
      }
      connectivity.push_back(new_index[n]);
    }
  }
  return Mesh(2, shape, coordinates, connectivity);
}

TEST(PointLocator, NonConvexDomain) {
  for (Shape shape : {Shape::Triangle, Shape::Quadrilateral}) {
    const Mesh mesh = l_shape(shape);
    const PointLocator locator(mesh);
    const std::vector<std::array<double, 3>> outside = {{1.5, 1.5, 0}, {1.0 + 1e-6, 1.7, 0}, {1.99, 1.01, 0}};
    for (const auto& x : outside) {
      EXPECT_FALSE(locator.locate(x.data()).has_value());
      try {
        locator.locate_or_throw(x.data());
        ADD_FAILURE() << "no throw";
      } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("outside the mesh"), std::string::npos) << error.what();
      }
    }
    // On the re-entrant edges and corner.
    const std::vector<std::array<double, 3>> re_entrant = {{1, 1.5, 0}, {1.5, 1, 0}, {1, 1, 0}, {1, 2, 0}};
    for (const auto& x : re_entrant) expect_located(locator, mesh, x);
  }
}

// Three unit squares: the buckets are the unit squares too, so that the point just left of the
// re-entrant edge x = 1 falls in the empty upper-left bucket, where only the widened bounding box of
// the cell on the right registers that cell.
TEST(PointLocator, RoundOffOutsideAReEntrantEdge) {
  const Mesh mesh = l_shape(Shape::Quadrilateral, 2, true);
  const PointLocator locator(mesh);
  expect_located(locator, mesh, {1 - 1e-13, 1.5, 0});
  EXPECT_FALSE(locator.locate(std::array<double, 3>{1 - 1e-6, 1.5, 0}.data()).has_value());
}

// A polynomial of the given degree in dim variables, and its vector version (two components).
void polynomial(int degree, int dim, const double* x, double* out) {
  const double z = dim == 3 ? x[2] : 0;
  out[0] = 1 + 2 * x[0] - x[1] + 0.5 * z;
  if (degree == 2) out[0] += x[0] * x[0] - 3 * x[0] * x[1] + x[1] * x[1] + z * z - x[1] * z + 0.5 * x[0] * z;
}

class EvaluateAtTest : public ::testing::TestWithParam<MeshCase> {};

// P1/Q1 reproduce linear functions and P2/Q2 quadratic ones (Q2 also on distorted cells, whose
// multilinear map keeps x_i x_j in Q2), so evaluation is exact up to round-off at any point.
TEST_P(EvaluateAtTest, ReproducesPolynomialsOfTheSpaceDegree) {
  auto mesh = std::make_shared<const Mesh>(make_mesh(GetParam()));
  const int dim = mesh->dim();
  const PointLocator locator(*mesh);
  std::mt19937 random(4);
  for (int order : {1, 2}) {
    const auto f = [order, dim](const double* x, double* out) {
      polynomial(order, dim, x, out);
      out[1] = -2 * out[0] + 1;
    };
    const FESpace space(mesh, order, 2);
    const Eigen::VectorXd coefficients = space.interpolate(f);
    for (int i = 0; i < 200; ++i) {
      const auto x = random_point_in_box(random, dim);
      double exact[2];
      f(x.data(), exact);
      const auto value = evaluate_at(space, coefficients, locator, x.data());
      ASSERT_EQ(value.size(), 2u);
      for (int k = 0; k < 2; ++k)
        EXPECT_NEAR(value[k], exact[k], 1e-12 * (1 + std::abs(exact[k]))) << "order " << order;
    }
    const double outside[3] = {0, 0, 0};
    EXPECT_THROW(evaluate_at(space, coefficients, locator, outside), Error);
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, EvaluateAtTest,
                         ::testing::Values(MeshCase{"triangles", Shape::Triangle, false},
                                           MeshCase{"distorted_quadrilaterals", Shape::Quadrilateral, true},
                                           MeshCase{"tetrahedra", Shape::Tetrahedron, false},
                                           MeshCase{"distorted_hexahedra", Shape::Hexahedron, true}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(EvaluateAt, SpaceOnARegionIsEvaluatedUpToItsBorder) {
  Mesh strip = rectangle_mesh({0, 0}, {4, 1}, 4, 1, Shape::Quadrilateral);
  std::vector<int> east_cells;
  for (int c = 0; c < strip.num_cells(); ++c) {
    double centre = 0;
    for (int n : strip.cell(c)) centre += strip.node(n)[0] / 4;
    if (centre > 2) east_cells.push_back(c);
  }
  strip.add_cell_region("east_half", east_cells);
  auto mesh = std::make_shared<const Mesh>(std::move(strip));
  const PointLocator locator(*mesh);
  const FESpace east(mesh, 1, 1, "east_half");
  const auto f = [](const double* x, double* out) { out[0] = 3 * x[0] + x[1]; };
  const Eigen::VectorXd coefficients = east.interpolate(f);

  // On the border x = 2 the neighbouring cell outside the region (which comes first in the mesh) must
  // not be picked.
  for (double y : {0.0, 0.3, 1.0}) {
    const double x[2] = {2, y};
    EXPECT_NEAR(evaluate_at(east, coefficients, locator, x)[0], 6 + y, 1e-12);
  }
  const double west[2] = {1, 0.5};
  try {
    evaluate_at(east, coefficients, locator, west);
    ADD_FAILURE() << "no throw";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("outside the cells of the field's space"), std::string::npos)
        << error.what();
  }

  auto other = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {4, 1}, 4, 1, Shape::Quadrilateral));
  const FESpace elsewhere(other, 1, 1);
  const double inside[2] = {1, 0.5};
  EXPECT_THROW(evaluate_at(elsewhere, elsewhere.interpolate(f), locator, inside), Error);
}

}  // namespace
}  // namespace pc

// Newest-vertex bisection (assembly/mesh_bisection.hpp) and the nested interpolation that moves fields
// onto the refined mesh (assembly/nested_interpolation.hpp):
//  - the refined mesh is conforming (its boundary is the old one's length: a hanging node would add an
//    inner edge that one cell owns) and covers the same area, each cell inside its parent;
//  - refining a corner again and again keeps the angles of the right isosceles cells (NVB makes no new
//    shapes of them), and regions follow their cells and faces;
//  - P1 and P2 fields move without change (evaluated at points, to round-off);
//  - Dörfler marking takes the fewest largest indicators; bad input is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "assembly/cell_geometry.hpp"
#include "assembly/mesh_bisection.hpp"
#include "assembly/mesh_generators.hpp"
#include "assembly/nested_interpolation.hpp"
#include "assembly/point_locator.hpp"
#include "support/error_and_temp_dir.hpp"

namespace pc {
namespace {

double smallest_angle_degrees(const Mesh& mesh) {
  double smallest = 180;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto t = mesh.cell(c);
    for (int k = 0; k < 3; ++k) {
      const auto a = mesh.node(t[k]), b = mesh.node(t[(k + 1) % 3]), o = mesh.node(t[(k + 2) % 3]);
      const double ux = a[0] - o[0], uy = a[1] - o[1], vx = b[0] - o[0], vy = b[1] - o[1];
      const double angle = std::acos((ux * vx + uy * vy) / std::hypot(ux, uy) / std::hypot(vx, vy));
      smallest = std::min(smallest, angle * 180 / std::numbers::pi);
    }
  }
  return smallest;
}

// The cells with a vertex within r of the point.
std::vector<int> cells_near(const Mesh& mesh, double x, double y, double r) {
  std::vector<int> cells;
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int n : mesh.cell(c))
      if (std::hypot(mesh.node(n)[0] - x, mesh.node(n)[1] - y) < r) {
        cells.push_back(c);
        break;
      }
  return cells;
}

TEST(MeshBisection, OneMarkedCellGivesAConformingMeshOfTheSameDomain) {
  const Mesh coarse = rectangle_mesh({0, 0}, {3, 1}, 6, 2, Shape::Triangle);
  const MeshBisection refined = bisect(coarse, {7}, RefinementEdge::Longest);
  const Mesh& fine = *refined.mesh;
  EXPECT_GT(fine.num_cells(), coarse.num_cells() + 1) << "the closure bisects the neighbour too";
  EXPECT_NEAR(fine.region_measure("all"), 3.0, 1e-13);
  EXPECT_NEAR(fine.region_measure("boundary"), 8.0, 1e-13) << "a hanging node would lengthen the boundary";
  ASSERT_EQ(refined.parent_cell.size(), size_t(fine.num_cells()));
  double parents_area = 0;
  std::vector<double> children_area(coarse.num_cells(), 0.0);
  for (int c = 0; c < fine.num_cells(); ++c) {
    // The child's centroid lies in its parent.
    std::array<double, 3> centre{};
    for (int n : fine.cell(c))
      for (int d = 0; d < 2; ++d) centre[d] += fine.node(n)[d] / 3;
    double xi[3];
    ASSERT_TRUE(map_to_reference(coarse, refined.parent_cell[c], centre.data(), xi));
    EXPECT_TRUE(inside_reference(Shape::Triangle, xi, 1e-12)) << "cell " << c;
    children_area[refined.parent_cell[c]] += fine.cell_measure(c);
  }
  for (int c = 0; c < coarse.num_cells(); ++c) {
    EXPECT_NEAR(children_area[c], coarse.cell_measure(c), 1e-14) << "cell " << c;
    parents_area += coarse.cell_measure(c);
  }
  EXPECT_NEAR(parents_area, 3.0, 1e-13);
}

TEST(MeshBisection, RefiningACornerKeepsTheAnglesAndTheRegions) {
  std::shared_ptr<const Mesh> mesh = std::make_shared<Mesh>(rectangle_mesh({0, 0}, {3, 1}, 6, 2, Shape::Triangle));
  const double initial = smallest_angle_degrees(*mesh);
  RefinementEdge edges = RefinementEdge::Longest;
  for (int round = 0; round < 12; ++round) {
    mesh = bisect(*mesh, cells_near(*mesh, 0, 0, 1e-9), edges).mesh;
    edges = RefinementEdge::OppositeVertexZero;
  }
  EXPECT_GE(mesh->num_cells(), 24 + 12) << "each round bisects at least the corner cell";
  EXPECT_NEAR(smallest_angle_degrees(*mesh), initial, 1e-9) << "NVB makes no new shapes of right isosceles cells";
  EXPECT_NEAR(initial, 45.0, 1e-9);
  EXPECT_NEAR(mesh->region_measure("all"), 3.0, 1e-12);
  EXPECT_NEAR(mesh->region_measure("boundary"), 8.0, 1e-12);
  for (const char* side : {"left", "right", "top", "bottom"})
    EXPECT_NEAR(mesh->region_measure(side), std::string(side) == "left" || std::string(side) == "right" ? 1.0 : 3.0,
                1e-12)
        << side;
  for (const FaceRef& f : mesh->face_region("bottom"))
    for (int n : mesh->face_nodes(f)) EXPECT_NEAR(mesh->node(n)[1], 0.0, 1e-15);
  // The smallest cells are at the corner: 12 bisections halve an area 12 times.
  double smallest_area = 1e300;
  for (int c = 0; c < mesh->num_cells(); ++c) smallest_area = std::min(smallest_area, mesh->cell_measure(c));
  EXPECT_NEAR(smallest_area, 0.125 / std::pow(2.0, 12), 1e-15);
}

TEST(MeshBisection, FieldsMoveToTheRefinedMeshUnchanged) {
  const auto coarse = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {2, 1}, 4, 2, Shape::Triangle));
  MeshBisection refined = bisect(*coarse, {0, 5, 6}, RefinementEdge::Longest);
  refined = [&] {  // twice, so that the parents compose
    MeshBisection again = bisect(*refined.mesh, {0, 1, 2, 3});
    for (int& p : again.parent_cell) p = refined.parent_cell[p];
    return again;
  }();
  const PointLocator coarse_locator(*coarse), fine_locator(*refined.mesh);
  for (int order : {1, 2}) {
    const FESpace from(coarse, order, 2), to(refined.mesh, order, 2);
    const Eigen::VectorXd f = from.interpolate([](const double* x, double* out) {
      out[0] = std::sin(3 * x[0]) * std::cos(2 * x[1]);
      out[1] = std::exp(x[0] - x[1]);
    });
    const Eigen::VectorXd g = interpolate_nested(from, f, to, refined.parent_cell);
    for (double x : {0.1, 0.37, 0.9, 1.41, 1.99})
      for (double y : {0.05, 0.5, 0.77}) {
        const double p[2] = {x, y};
        const auto a = evaluate_at(from, f, coarse_locator, p), b = evaluate_at(to, g, fine_locator, p);
        EXPECT_NEAR(a[0], b[0], 1e-13) << "P" << order << " at " << x << ", " << y;
        EXPECT_NEAR(a[1], b[1], 1e-13) << "P" << order << " at " << x << ", " << y;
      }
  }
}

TEST(DorflerMarking, TakesTheFewestLargestIndicators) {
  // Squares 9, 1, 4, 0, 16: total 30; half is 15: 16 alone passes it.
  EXPECT_EQ(dorfler_marking({3, 1, 2, 0, 4}, 0.5), (std::vector<int>{4}));
  EXPECT_EQ(dorfler_marking({3, 1, 2, 0, 4}, 0.6), (std::vector<int>{0, 4}));  // 18 < 25 <= 30
  EXPECT_EQ(dorfler_marking({3, 1, 2, 0, 4}, 1.0), (std::vector<int>{0, 1, 2, 4})) << "a zero is never needed";
  EXPECT_TRUE(dorfler_marking({0, 0}, 0.5).empty());
}

TEST(MeshBisection, BadInputIsRefused) {
  const Mesh quads = rectangle_mesh({0, 0}, {1, 1}, 2, 2, Shape::Quadrilateral);
  testing::expect_error_containing([&] { bisect(quads, {0}); }, {"2D mesh of triangles", "quadrilateral"});
  const Mesh triangles = rectangle_mesh({0, 0}, {1, 1}, 2, 2, Shape::Triangle);
  testing::expect_error_containing([&] { bisect(triangles, {8}); }, {"marked cell 8 does not exist", "8 cells"});
  testing::expect_error_containing([&] { dorfler_marking({1, 2}, 0); }, {"fraction", "got 0"});
  testing::expect_error_containing([&] { dorfler_marking({1, -2}, 0.5); }, {"cell 1", "-2"});
  testing::expect_error_containing([&] { dorfler_marking({1, std::nan("")}, 0.5); }, {"cell 1", "nan"});
}

}  // namespace
}  // namespace pc

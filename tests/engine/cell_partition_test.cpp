// The partition of a distributed run (assembly/cell_partition.hpp) and assembly by parts: METIS gives
// every cell one part, parts of nearly equal size whose cells hang together through faces, the same
// parts on every call; and the element loops over each part's cells (RegionGeometry's owned cells),
// summed over the parts, are the loop over the whole mesh, over cells and faces, in 2D and 3D, P1 and P2.
// This sum is what a distributed model's processes form (models/model.hpp, MUMPS's distributed input).
#include "assembly/cell_partition.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <numeric>
#include <set>

#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"
#include "support/nonlinear_terms.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

using testing::error_of;

// Cells sharing a face (as many nodes as a face has).
bool face_neighbours(const Mesh& mesh, int a, int b) {
  const auto ca = mesh.cell(a), cb = mesh.cell(b);
  int shared = 0;
  for (int n : ca) shared += std::count(cb.begin(), cb.end(), n) > 0;
  return shared >= int(mesh.face_nodes(FaceRef{0, 0}).size());
}

// Number of pieces of a part that hang together through faces (1: connected).
int pieces(const Mesh& mesh, const std::vector<int>& owner, int part) {
  std::vector<int> cells;
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (owner[c] == part) cells.push_back(c);
  std::vector<char> seen(cells.size(), 0);
  int count = 0;
  for (size_t start = 0; start < cells.size(); ++start) {
    if (seen[start]) continue;
    ++count;
    std::vector<size_t> stack = {start};
    seen[start] = 1;
    while (!stack.empty()) {
      const size_t i = stack.back();
      stack.pop_back();
      for (size_t j = 0; j < cells.size(); ++j)
        if (!seen[j] && face_neighbours(mesh, cells[i], cells[j])) {
          seen[j] = 1;
          stack.push_back(j);
        }
    }
  }
  return count;
}

TEST(CellPartition, PartsAreBalancedConnectedAndTheSameOnEveryCall) {
  const Mesh meshes[] = {rectangle_mesh({0, 0}, {3, 1}, 30, 10, Shape::Triangle),
                         rectangle_mesh({0, 0}, {3, 1}, 24, 8, Shape::Quadrilateral),
                         box_mesh({0, 0, 0}, {3, 1, 1}, 9, 3, 3, Shape::Tetrahedron),
                         box_mesh({0, 0, 0}, {3, 1, 1}, 9, 3, 3, Shape::Hexahedron)};
  for (const Mesh& mesh : meshes)
    for (int parts : {2, 3, 4}) {
      const std::vector<int> owner = partition_cells(mesh, parts);
      ASSERT_EQ(int(owner.size()), mesh.num_cells());
      std::vector<int> sizes(parts, 0);
      for (int p : owner) {
        ASSERT_GE(p, 0);
        ASSERT_LT(p, parts);
        ++sizes[p];
      }
      const double ideal = double(mesh.num_cells()) / parts;
      // METIS's default imbalance tolerance is 3 % of the ideal size (a cell more on small meshes).
      for (int p = 0; p < parts; ++p) {
        EXPECT_LE(sizes[p], 1.03 * ideal + 1) << mesh.num_cells() << " cells, part " << p << " of " << parts;
        EXPECT_GE(sizes[p], 0.9 * ideal) << mesh.num_cells() << " cells, part " << p << " of " << parts;
        EXPECT_EQ(pieces(mesh, owner, p), 1) << mesh.num_cells() << " cells, part " << p << " of " << parts;
      }
      EXPECT_EQ(owner, partition_cells(mesh, parts)) << "the partition must not change from call to call";
    }
}

TEST(CellPartition, OnePartNeedsNoMetisAndImpossiblePartitionsAreRefused) {
  const Mesh mesh = rectangle_mesh({0, 0}, {1, 1}, 2, 1, Shape::Triangle);  // 4 cells
  EXPECT_EQ(partition_cells(mesh, 1), std::vector<int>(4, 0));
  EXPECT_EQ(error_of([&] { partition_cells(mesh, 5); }),
            "partition_cells: 5 parts of a mesh of 4 cells (each process must own a cell): run on fewer processes "
            "or refine the mesh");
  EXPECT_EQ(error_of([&] { partition_cells(mesh, 0); }), "partition_cells: the number of parts must be >= 1, got 0");
  const std::vector<char> owned = cells_of_part({0, 1, 1, 0}, 1);
  EXPECT_EQ(owned, (std::vector<char>{0, 1, 1, 0}));
}

// Residual and tangent (as a dense matrix) of the nonlinear term over the region's elements of the owned
// cells (all: empty).
std::pair<Eigen::VectorXd, Eigen::MatrixXd> assembled(const FESpace& space, Integration integration,
                                                      const std::string& region, std::span<const char> owned) {
  const auto [r, k] = testing::assembled_term<testing::NonlinearDiffusion>(space, integration, region, owned);
  return {r, Eigen::MatrixXd(k)};
}

TEST(CellPartition, AssemblyOverThePartsSumsToAssemblyOverTheMesh) {
  struct Case {
    std::shared_ptr<const Mesh> mesh;
    int order;
  };
  const Case cases[] = {
      {std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {3, 1}, 12, 4, Shape::Triangle)), 1},
      {std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {3, 1}, 9, 3, Shape::Quadrilateral)), 2},
      {std::make_shared<const Mesh>(box_mesh({0, 0, 0}, {3, 1, 1}, 6, 2, 2, Shape::Tetrahedron)), 1},
      {std::make_shared<const Mesh>(box_mesh({0, 0, 0}, {3, 1, 1}, 4, 2, 2, Shape::Hexahedron)), 2},
  };
  for (const Case& c : cases) {
    const FESpace space(c.mesh, c.order, c.mesh->dim());
    for (Integration integration : {Integration::Cells, Integration::Faces}) {
      const std::string region = integration == Integration::Cells ? "all" : "boundary";
      const auto whole = assembled(space, integration, region, {});
      ASSERT_GT(whole.second.cwiseAbs().maxCoeff(), 0);
      const std::vector<int> owner = partition_cells(*c.mesh, 3);
      Eigen::VectorXd r = Eigen::VectorXd::Zero(whole.first.size());
      Eigen::MatrixXd k = Eigen::MatrixXd::Zero(whole.second.rows(), whole.second.cols());
      int elements = 0;
      for (int part = 0; part < 3; ++part) {
        const std::vector<char> owned = cells_of_part(owner, part);
        const auto share = assembled(space, integration, region, owned);
        r += share.first;
        k += share.second;
        elements += RegionGeometry(*c.mesh, region, 4, owned).num_elements();
        EXPECT_LT(share.second.cwiseAbs().sum(), whole.second.cwiseAbs().sum()) << "a part holds all of the mesh";
      }
      EXPECT_EQ(elements, RegionGeometry(*c.mesh, region, 4).num_elements()) << "each element in one part";
      const double tolerance = 1e-13 * (whole.second.cwiseAbs().maxCoeff() + whole.first.cwiseAbs().maxCoeff());
      EXPECT_LE((r - whole.first).cwiseAbs().maxCoeff(), tolerance) << c.mesh->num_cells() << " cells, " << region;
      EXPECT_LE((k - whole.second).cwiseAbs().maxCoeff(), tolerance) << c.mesh->num_cells() << " cells, " << region;
    }
  }
}

TEST(CellPartition, OwnershipFlagsMustCoverTheMesh) {
  const Mesh mesh = rectangle_mesh({0, 0}, {1, 1}, 2, 1, Shape::Triangle);
  const std::vector<char> too_few(3, 1);
  EXPECT_EQ(error_of([&] { RegionGeometry(mesh, "all", 2, too_few); }),
            "RegionGeometry: 3 ownership flags for a mesh of 4 cells");
}

}  // namespace
}  // namespace pc

// The .vtu files are parsed back in every format (tests/support/vtu_reader.hpp: text, base64, raw and
// zlib appended data) and compared with the mesh and with the fields' exact values at the nodes, for
// quadratic cells also with VTK's node order; the .pvd collection is read back as text.
#include "assembly/vtu_writer.hpp"
#include "support/error_and_temp_dir.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <regex>
#include <sstream>

#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"
#include "support/test_helpers.hpp"
#include "support/vtu_reader.hpp"

namespace pc {
namespace {

namespace fs = std::filesystem;

using testing::DataArray;
using testing::find_array;
using testing::read_text;

// The mesh part of a .vtu: piece sizes, points (z = 0 in 2D), connectivity, offsets and cell types.
void expect_mesh(const std::string& vtu, const Mesh& mesh, int vtk_type) {
  EXPECT_NE(vtu.find("type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
                     "header_type=\"UInt64\""),
            std::string::npos);
  EXPECT_NE(vtu.find(message("NumberOfPoints=\"", mesh.num_nodes(), "\" NumberOfCells=\"", mesh.num_cells(), "\"")),
            std::string::npos);

  const DataArray points = find_array(vtu, "Points", "Points");
  EXPECT_EQ(points.type, "Float64");
  EXPECT_EQ(points.components, 3);
  const auto xyz = points.doubles();
  ASSERT_EQ(xyz.size(), 3u * mesh.num_nodes());
  for (int n = 0; n < mesh.num_nodes(); ++n)
    for (int d = 0; d < 3; ++d) EXPECT_EQ(xyz[3 * n + d], d < mesh.dim() ? mesh.node(n)[d] : 0.0);

  const DataArray connectivity = find_array(vtu, "Cells", "connectivity");
  EXPECT_EQ(connectivity.type, "Int64");
  const auto nodes = connectivity.int64s();
  ASSERT_EQ(nodes.size(), mesh.connectivity().size());
  for (size_t i = 0; i < nodes.size(); ++i) EXPECT_EQ(nodes[i], mesh.connectivity()[i]);

  const DataArray offsets = find_array(vtu, "Cells", "offsets");
  EXPECT_EQ(offsets.type, "Int64");
  const auto ends = offsets.int64s();
  ASSERT_EQ(ends.size(), size_t(mesh.num_cells()));
  for (int c = 0; c < mesh.num_cells(); ++c) EXPECT_EQ(ends[c], std::int64_t(c + 1) * mesh.vertices_per_cell());

  const DataArray types = find_array(vtu, "Cells", "types");
  EXPECT_EQ(types.type, "UInt8");
  ASSERT_EQ(types.bytes.size(), size_t(mesh.num_cells()));
  for (char t : types.bytes) EXPECT_EQ(static_cast<unsigned char>(t), vtk_type);
}

// Point data must equal f at every node: exact for the vertex dofs of an interpolant.
void expect_point_values(const std::string& vtu, const Mesh& mesh, const std::string& name, int components,
                         const std::function<void(const double* x, double* out)>& f) {
  const DataArray array = find_array(vtu, "PointData", name);
  EXPECT_EQ(array.type, "Float64");
  ASSERT_EQ(array.components, components);
  const auto values = array.doubles();
  ASSERT_EQ(values.size(), size_t(components) * mesh.num_nodes());
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    double exact[3] = {0, 0, 0};
    f(mesh.node(n).data(), exact);
    for (int k = 0; k < components; ++k) EXPECT_EQ(values[components * n + k], exact[k]) << name << " node " << n;
  }
}

using testing::expect_error_containing;
class VtuWriterTest : public testing::TemporaryDirectoryTest {};

constexpr VtuFormat kFormats[] = {VtuFormat::Ascii, VtuFormat::Base64, VtuFormat::Binary, VtuFormat::Zlib};

const auto linear = [](const double* x, double* out) { out[0] = 1 + 2 * x[0] - 3 * x[1]; };
const auto linear_vector = [](const double* x, double* out) {
  out[0] = 2 * x[0] + x[1];
  out[1] = 0.5 - x[1];
};

TEST_F(VtuWriterTest, TrianglesWithScalarVectorAndCellData) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {2, 1}, 3, 2, Shape::Triangle));
  FESpace p1(mesh, 1, 1), p1_vector(mesh, 1, 2);
  std::vector<double> cell_ids(mesh->num_cells()), pairs(2 * mesh->num_cells());
  for (int c = 0; c < mesh->num_cells(); ++c) {
    cell_ids[c] = c;
    pairs[2 * c] = -c;
    pairs[2 * c + 1] = 0.5 * c;
  }

  VtuWriter writer(*mesh);
  writer.add_point_field("phi", p1, p1.interpolate(linear));
  writer.add_point_field("u", p1_vector, p1_vector.interpolate(linear_vector));
  writer.add_cell_data("cell", 1, cell_ids);
  writer.add_cell_data("pair", 2, pairs);
  for (const VtuFormat format : kFormats) {
    SCOPED_TRACE(to_string(format));
    const fs::path path = directory_ / "triangles.vtu";
    writer.write(path.string(), format);

    EXPECT_FALSE(fs::exists(path.string() + ".tmp"));
    const std::string vtu = read_text(path);
    expect_mesh(vtu, *mesh, 5);
    expect_point_values(vtu, *mesh, "phi", 1, linear);
    // A 2D vector is padded with a zero z component.
    expect_point_values(vtu, *mesh, "u", 3, linear_vector);
    EXPECT_EQ(find_array(vtu, "CellData", "cell").doubles(), cell_ids);
    const DataArray pair_array = find_array(vtu, "CellData", "pair");
    EXPECT_EQ(pair_array.components, 2);
    EXPECT_EQ(pair_array.doubles(), pairs);
  }
}

TEST_F(VtuWriterTest, TetrahedraWithVectorField) {
  auto mesh = std::make_shared<const Mesh>(box_mesh({0, 0, 0}, {1, 2, 1}, 2, 2, 1, Shape::Tetrahedron));
  FESpace p1(mesh, 1, 3);
  const auto f = [](const double* x, double* out) {
    out[0] = x[0] + 1;
    out[1] = 2 * x[1] - x[2];
    out[2] = -x[0] + 3 * x[2];
  };
  VtuWriter writer(*mesh);
  writer.add_point_field("displacement", p1, p1.interpolate(f));
  for (const VtuFormat format : kFormats) {
    SCOPED_TRACE(to_string(format));
    const fs::path path = directory_ / "tets.vtu";
    writer.write(path.string(), format);

    const std::string vtu = read_text(path);
    expect_mesh(vtu, *mesh, 10);
    expect_point_values(vtu, *mesh, "displacement", 3, f);
  }
}

TEST_F(VtuWriterTest, HexahedraWithScalarAndPointData) {
  auto mesh = std::make_shared<const Mesh>(box_mesh({0, 0, 0}, {1, 1, 2}, 2, 1, 2, Shape::Hexahedron));
  FESpace q1(mesh, 1, 1);
  const auto f = [](const double* x, double* out) { out[0] = x[0] * x[1] * x[2] + 1; };
  std::vector<double> node_ids(mesh->num_nodes());
  for (int n = 0; n < mesh->num_nodes(); ++n) node_ids[n] = n;
  VtuWriter writer(*mesh);
  writer.add_point_field("T", q1, q1.interpolate(f));
  writer.add_point_data("node", 1, node_ids);
  for (const VtuFormat format : kFormats) {
    SCOPED_TRACE(to_string(format));
    const fs::path path = directory_ / "hexes.vtu";
    writer.write(path.string(), format);

    const std::string vtu = read_text(path);
    expect_mesh(vtu, *mesh, 12);
    expect_point_values(vtu, *mesh, "T", 1, f);
    EXPECT_EQ(find_array(vtu, "PointData", "node").doubles(), node_ids);
  }
}

TEST_F(VtuWriterTest, NodesOutsideTheSpaceRegionGetZero) {
  Mesh left_right = rectangle_mesh({0, 0}, {4, 1}, 4, 1, Shape::Quadrilateral);
  std::vector<int> left_cells;
  for (int c = 0; c < left_right.num_cells(); ++c) {
    double centre = 0;
    for (int n : left_right.cell(c)) centre += left_right.node(n)[0] / 4;
    if (centre < 2) left_cells.push_back(c);
  }
  left_right.add_cell_region("west_half", left_cells);
  auto mesh = std::make_shared<const Mesh>(std::move(left_right));
  FESpace left(mesh, 1, 1, "west_half");
  VtuWriter writer(*mesh);
  writer.add_point_field("phi", left, left.interpolate(linear));
  const fs::path path = directory_ / "left.vtu";
  writer.write(path.string());

  expect_point_values(read_text(path), *mesh, "phi", 1, [](const double* x, double* out) {
    if (x[0] <= 2)
      linear(x, out);
    else
      out[0] = 0;
  });
}

// ---- quadratic files ----------------------------------------------------------------------------

// VTK's quadratic cells, written down from VTK (vtkQuadraticTriangle, vtkBiQuadraticQuad,
// vtkQuadraticTetra, vtkTriQuadraticHexahedron) independently of shape.cpp: the parametric coordinates of
// the corners, and for every further node the corners whose mean it is (its edge, face or cell).
struct VtkQuadraticCell {
  Shape shape;
  int type;
  std::vector<std::array<double, 3>> corners;
  std::vector<std::vector<int>> means;
};

std::vector<VtkQuadraticCell> vtk_quadratic_cells() {
  const std::vector<std::array<double, 3>> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  std::vector<std::array<double, 3>> cube = square;
  for (const auto& p : square) cube.push_back({p[0], p[1], 1});
  return {
      {Shape::Triangle, 22, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1}, {1, 2}, {2, 0}}},
      {Shape::Quadrilateral, 28, square, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 1, 2, 3}}},
      {Shape::Tetrahedron,
       24,
       {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
       {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}}},
      // Faces in the order of VTK's parametric coordinates: x = 0, x = 1, y = 0, y = 1, z = 0, z = 1.
      {Shape::Hexahedron,
       29,
       cube,
       {{0, 1},
        {1, 2},
        {2, 3},
        {3, 0},
        {4, 5},
        {5, 6},
        {6, 7},
        {7, 4},
        {0, 4},
        {1, 5},
        {2, 6},
        {3, 7},
        {0, 4, 7, 3},
        {1, 2, 6, 5},
        {0, 1, 5, 4},
        {3, 7, 6, 2},
        {0, 3, 2, 1},
        {4, 5, 6, 7},
        {0, 1, 2, 3, 4, 5, 6, 7}}},
  };
}

// The mean of the given points.
std::array<double, 3> mean_of(const std::vector<std::array<double, 3>>& points, const std::vector<int>& which) {
  std::array<double, 3> mean{0, 0, 0};
  for (int k : which)
    for (int d = 0; d < 3; ++d) mean[d] += points[k][d] / double(which.size());
  return mean;
}

// The nodes of a VTK cell: its corners, then the means.
std::vector<std::array<double, 3>> vtk_nodes(const VtkQuadraticCell& cell,
                                             const std::vector<std::array<double, 3>>& corners) {
  std::vector<std::array<double, 3>> nodes = corners;
  for (const auto& which : cell.means) nodes.push_back(mean_of(corners, which));
  return nodes;
}

TEST(VtkQuadraticCells, NodesAreTheOrderTwoElementsDofsInTheirLocalOrder) {
  for (const VtkQuadraticCell& cell : vtk_quadratic_cells()) {
    SCOPED_TRACE(to_string(cell.shape));
    const ReferenceElement& element = ReferenceElement::get(cell.shape, 2);
    const auto nodes = vtk_nodes(cell, cell.corners);
    ASSERT_EQ(element.num_dofs(), int(nodes.size()));
    for (int i = 0; i < element.num_dofs(); ++i) EXPECT_EQ(element.dof_point(i), nodes[i]) << "node " << i;
  }
}

// A mesh of the shape with its nodes moved by a smooth map, so that its cells are neither translates of
// one another nor, for quadrilaterals and hexahedra, parallelograms.
std::shared_ptr<const Mesh> distorted_mesh(Shape shape) {
  const int dim = dimension(shape);
  const Mesh base =
      dim == 2 ? rectangle_mesh({0, 0}, {1, 1}, 3, 2, shape) : box_mesh({0, 0, 0}, {1, 1, 1}, 2, 2, 2, shape);
  std::vector<double> x = base.coordinates();
  for (int n = 0; n < base.num_nodes(); ++n) {
    double* p = x.data() + size_t(n) * dim;
    const double px = p[0], py = p[1], pz = dim == 3 ? p[2] : 0.0;
    p[0] = px + 0.15 * py * py;
    p[1] = py + 0.1 * px * px + 0.05 * pz;
    if (dim == 3) p[2] = pz + 0.1 * px * py;
  }
  return std::make_shared<const Mesh>(dim, shape, std::move(x), base.connectivity());
}

// A full quadratic polynomial (z = 0 in 2D), and a vector of quadratics with one component per dimension.
const auto quadratic = [](const double* x, double* out) {
  out[0] = 1 + x[0] - 2 * x[1] + 3 * x[0] * x[1] + x[0] * x[0] - 2 * x[1] * x[1];
};
const auto quadratic_3d = [](const double* x, double* out) {
  quadratic(x, out);
  out[0] += 0.5 * x[2] - x[1] * x[2] + x[2] * x[2];
};
const auto quadratic_vector = [](const double* x, double* out) {
  out[0] = x[0] * x[1] - 1;
  out[1] = x[0] * x[0] + x[1];
  out[2] = x[2] * x[0] - x[1] * x[1];
};

// The written points (3 coordinates each).
std::vector<std::array<double, 3>> read_points(const std::string& vtu) {
  const auto xyz = find_array(vtu, "Points", "Points").doubles();
  std::vector<std::array<double, 3>> points(xyz.size() / 3);
  for (size_t p = 0; p < points.size(); ++p) points[p] = {xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]};
  return points;
}

// Point data must equal f at every written point, to round-off.
void expect_values_at_points(const std::string& vtu, const std::string& name, int components,
                             const std::function<void(const double* x, double* out)>& f) {
  const auto points = read_points(vtu);
  const DataArray array = find_array(vtu, "PointData", name);
  ASSERT_EQ(array.components, components) << name;
  const auto values = array.doubles();
  ASSERT_EQ(values.size(), points.size() * components) << name;
  for (size_t p = 0; p < points.size(); ++p) {
    double exact[3] = {0, 0, 0};
    f(points[p].data(), exact);
    for (int k = 0; k < components; ++k)
      EXPECT_NEAR(values[p * components + k], exact[k], 1e-13) << name << " point " << p << " component " << k;
  }
}

TEST_F(VtuWriterTest, QuadraticFieldsAreWrittenAtTheirDofsAsQuadraticCellsOnEveryShape) {
  for (const VtkQuadraticCell& cell : vtk_quadratic_cells()) {
    for (const VtuFormat format : kFormats) {
      SCOPED_TRACE(to_string(cell.shape) + ", " + to_string(format));
      const auto mesh = distorted_mesh(cell.shape);
      const int dim = mesh->dim();
      const FESpace scalars(mesh, 2, 1), vectors(mesh, 2, dim);
      const auto f = dim == 2 ? std::function<void(const double*, double*)>(quadratic) : quadratic_3d;
      // The vector field's interpolant sees dim coordinates: give it a zero z in 2D.
      const auto g = [&](const double* x, double* out) {
        const double p[3] = {x[0], x[1], dim == 3 ? x[2] : 0.0};
        double all[3];
        quadratic_vector(p, all);
        for (int k = 0; k < dim; ++k) out[k] = all[k];
      };
      VtuWriter writer(*mesh);
      writer.add_point_field("f", scalars, scalars.interpolate(f));
      writer.add_point_field("g", vectors, vectors.interpolate(g));
      const fs::path path = directory_ / "quadratic.vtu";
      writer.write(path.string(), format);
      const std::string vtu = read_text(path);

      // One point per P2/Q2 dof, each cell a VTK quadratic cell.
      EXPECT_NE(vtu.find(message("NumberOfPoints=\"", scalars.num_scalar_dofs(), "\" NumberOfCells=\"",
                                 mesh->num_cells(), "\"")),
                std::string::npos);
      const auto points = read_points(vtu);
      ASSERT_EQ(points.size(), size_t(scalars.num_scalar_dofs()));
      const DataArray types = find_array(vtu, "Cells", "types");
      ASSERT_EQ(types.bytes.size(), size_t(mesh->num_cells()));
      for (char t : types.bytes) EXPECT_EQ(static_cast<unsigned char>(t), cell.type);
      const int per_cell = num_vertices(cell.shape) + int(cell.means.size());
      const auto ends = find_array(vtu, "Cells", "offsets").int64s();
      ASSERT_EQ(ends.size(), size_t(mesh->num_cells()));
      for (int c = 0; c < mesh->num_cells(); ++c) EXPECT_EQ(ends[c], std::int64_t(c + 1) * per_cell);

      // In VTK's order, a cell's nodes are its vertices, then the means of its vertices that VTK names.
      const auto connectivity = find_array(vtu, "Cells", "connectivity").int64s();
      ASSERT_EQ(connectivity.size(), size_t(mesh->num_cells()) * per_cell);
      for (int c = 0; c < mesh->num_cells(); ++c) {
        std::vector<std::array<double, 3>> corners;
        for (int n : mesh->cell(c)) {
          std::array<double, 3> x{0, 0, 0};
          for (int d = 0; d < dim; ++d) x[d] = mesh->node(n)[d];
          corners.push_back(x);
        }
        const auto expected = vtk_nodes(cell, corners);
        for (int i = 0; i < per_cell; ++i) {
          const std::int64_t p = connectivity[size_t(c) * per_cell + i];
          ASSERT_GE(p, 0);
          ASSERT_LT(p, std::int64_t(points.size()));
          for (int d = 0; d < 3; ++d)
            EXPECT_NEAR(points[p][d], expected[i][d], 1e-14) << "cell " << c << " node " << i << " axis " << d;
        }
      }

      // A field of the space is its polynomial at every point.
      expect_values_at_points(vtu, "f", 1, f);
      expect_values_at_points(vtu, "g", 3, [&](const double* x, double* out) {
        quadratic_vector(x, out);
        if (dim == 2) out[2] = 0;  // a 2D vector is padded with a zero z component
      });
    }
  }
}

TEST_F(VtuWriterTest, LinearDataInAQuadraticFileIsTheirInterpolantAndZeroOutsideTheirCells) {
  Mesh left_right = rectangle_mesh({0, 0}, {4, 1}, 4, 2, Shape::Triangle);
  std::vector<int> left_cells;
  for (int c = 0; c < left_right.num_cells(); ++c) {
    double centre = 0;
    for (int n : left_right.cell(c)) centre += left_right.node(n)[0] / 3;
    if (centre < 2) left_cells.push_back(c);
  }
  left_right.add_cell_region("west_half", left_cells);
  auto mesh = std::make_shared<const Mesh>(std::move(left_right));
  const FESpace p1_west(mesh, 1, 1, "west_half"), p2_west(mesh, 2, 1, "west_half");
  std::vector<double> at_nodes(mesh->num_nodes());
  for (int n = 0; n < mesh->num_nodes(); ++n) linear(mesh->node(n).data(), &at_nodes[n]);

  VtuWriter writer(*mesh);
  // Linear data before and after the field that makes the file quadratic.
  writer.add_point_field("p1", p1_west, p1_west.interpolate(linear));
  writer.add_point_field("p2", p2_west, p2_west.interpolate(quadratic));
  writer.add_point_data("nodes", 1, at_nodes);
  const fs::path path = directory_ / "mixed.vtu";
  writer.write(path.string());
  const std::string vtu = read_text(path);

  const auto west = [](auto f) {
    return [f](const double* x, double* out) {
      if (x[0] <= 2)
        f(x, out);
      else
        out[0] = 0;
    };
  };
  expect_values_at_points(vtu, "p1", 1, west(linear));
  expect_values_at_points(vtu, "p2", 1, west(quadratic));
  expect_values_at_points(vtu, "nodes", 1, linear);
}

TEST_F(VtuWriterTest, RewritingReplacesTheFile) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 1, 1, Shape::Quadrilateral));
  const fs::path path = directory_ / "again.vtu";
  VtuWriter first(*mesh);
  first.add_point_data("a", 1, std::vector<double>(mesh->num_nodes(), 1.0));
  first.write(path.string());
  VtuWriter second(*mesh);
  second.add_point_data("b", 1, std::vector<double>(mesh->num_nodes(), 2.0));
  second.write(path.string());

  const std::string vtu = read_text(path);
  EXPECT_EQ(vtu.find("Name=\"a\""), std::string::npos);
  EXPECT_EQ(find_array(vtu, "PointData", "b").doubles(), std::vector<double>(mesh->num_nodes(), 2.0));
}

// Pieces of a distributed run: each process's file holds its cells, the points they use and their data,
// and together the pieces are the whole file (linear and quadratic); the .pvtu lists the arrays and the
// pieces.
TEST_F(VtuWriterTest, PiecesOfThePartsMakeTheWholeFileAndThePvtuNamesThem) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {2, 1}, 6, 3, Shape::Triangle));
  // Every format (the appended ones read the values when the file ends), linear and quadratic files (whose
  // data at the mesh nodes is interpolated, then cut to the piece).
  for (const VtuFormat format : kFormats)
    for (int order : {1, 2}) {
      SCOPED_TRACE(message(to_string(format), ", order ", order));
      FESpace space(mesh, order, 2);
      std::vector<double> cell_ids(mesh->num_cells());
      for (int c = 0; c < mesh->num_cells(); ++c) cell_ids[c] = c;
      VtuWriter writer(*mesh);
      writer.add_point_field("u", space, space.interpolate(linear_vector));
      std::vector<double> x_at_nodes(mesh->num_nodes());
      for (int n = 0; n < mesh->num_nodes(); ++n) x_at_nodes[n] = mesh->node(n)[0];
      writer.add_point_data("x", 1, x_at_nodes);
      writer.add_cell_data("cell", 1, cell_ids);
      const fs::path whole_path = directory_ / "whole.vtu";
      writer.write(whole_path.string(), format);
      const std::string whole = read_text(whole_path);
      // The whole file's value of u at each point, by its coordinates.
      const auto points = find_array(whole, "Points", "Points").doubles();
      const auto u = find_array(whole, "PointData", "u").doubles();
      const auto x = find_array(whole, "PointData", "x").doubles();
      std::map<std::array<double, 3>, std::array<double, 4>> u_at;  // u and x at each point
      for (size_t p = 0; p * 3 < points.size(); ++p)
        u_at[{points[3 * p], points[3 * p + 1], points[3 * p + 2]}] = {u[3 * p], u[3 * p + 1], u[3 * p + 2], x[p]};

      std::vector<int> seen(mesh->num_cells(), 0);
      std::vector<std::string> pieces;
      for (int part = 0; part < 3; ++part) {
        std::vector<char> cells(mesh->num_cells(), 0);
        for (int c = 0; c < mesh->num_cells(); ++c) cells[c] = c % 3 == part;  // parts need not hang together
        pieces.push_back("piece_" + std::to_string(part) + ".vtu");
        writer.write((directory_ / pieces.back()).string(), format, cells);
        const std::string piece = read_text(directory_ / pieces.back());
        const auto ids = find_array(piece, "CellData", "cell").doubles();
        for (double id : ids) {
          EXPECT_EQ(int(id) % 3, part);
          ++seen[int(id)];
        }
        const auto piece_points = find_array(piece, "Points", "Points").doubles();
        const auto piece_u = find_array(piece, "PointData", "u").doubles();
        const auto piece_x = find_array(piece, "PointData", "x").doubles();
        ASSERT_EQ(piece_points.size(), piece_u.size());
        ASSERT_EQ(piece_points.size(), 3 * piece_x.size());
        EXPECT_LT(piece_points.size(), points.size()) << "a piece holds every point";
        for (size_t p = 0; p * 3 < piece_points.size(); ++p) {
          const auto found = u_at.find({piece_points[3 * p], piece_points[3 * p + 1], piece_points[3 * p + 2]});
          ASSERT_NE(found, u_at.end()) << "a piece's point that the whole file does not have";
          for (int k = 0; k < 3; ++k) EXPECT_EQ(piece_u[3 * p + k], found->second[k]);
          EXPECT_EQ(piece_x[p], found->second[3]);
          EXPECT_NEAR(piece_x[p], piece_points[3 * p], 1e-15) << "x interpolated at the point is its x";
        }
        const auto offsets = find_array(piece, "Cells", "offsets").int64s();
        ASSERT_EQ(offsets.size(), ids.size());
        for (std::int64_t node : find_array(piece, "Cells", "connectivity").int64s()) {
          EXPECT_GE(node, 0);
          EXPECT_LT(node, std::int64_t(piece_points.size() / 3));
        }
      }
      EXPECT_EQ(seen, std::vector<int>(mesh->num_cells(), 1)) << "each cell in one piece";

      const fs::path pvtu = directory_ / "whole.pvtu";
      writer.write_pvtu(pvtu.string(), pieces);
      const std::string text = read_text(pvtu);
      EXPECT_NE(text.find("<VTKFile type=\"PUnstructuredGrid\""), std::string::npos);
      EXPECT_NE(text.find("<PDataArray type=\"Float64\" Name=\"u\" NumberOfComponents=\"3\"/>"), std::string::npos);
      EXPECT_NE(text.find("<PDataArray type=\"Float64\" Name=\"cell\" NumberOfComponents=\"1\"/>"), std::string::npos);
      for (const std::string& piece : pieces)
        EXPECT_NE(text.find("<Piece Source=\"" + piece + "\"/>"), std::string::npos) << piece;
    }
  EXPECT_THROW(VtuWriter(*mesh).write((directory_ / "bad.vtu").string(), kDefaultVtuFormat, std::vector<char>(3, 1)),
               Error);
}

// ---- formats ------------------------------------------------------------------------------------

// Values that a careless text or binary encoding would change: signed zero, subnormals, the extremes,
// and fractions with no short decimal form.
std::vector<double> awkward_values(size_t count) {
  const std::vector<double> awkward = {-0.0,
                                       0.1,
                                       1.0 / 3.0,
                                       -2.0 / 7.0,
                                       5e-324,
                                       -2.2250738585072014e-308,
                                       1.7976931348623157e308,
                                       -1.7976931348623157e308,
                                       3.141592653589793e-300,
                                       123456789012345678.0,
                                       1e-7,
                                       -9.999999999999999e22};
  std::vector<double> values(count);
  for (size_t i = 0; i < count; ++i) values[i] = awkward[i % awkward.size()] * (i < awkward.size() ? 1 : 1 + 1e-3 * i);
  return values;
}

// Bit for bit, so that -0.0 and 0.0 differ.
void expect_same_bits(const std::vector<double>& read, const std::vector<double>& written, const std::string& what) {
  ASSERT_EQ(read.size(), written.size()) << what;
  for (size_t i = 0; i < read.size(); ++i)
    EXPECT_EQ(std::bit_cast<std::uint64_t>(read[i]), std::bit_cast<std::uint64_t>(written[i]))
        << what << "[" << i << "]: read " << read[i] << ", written " << written[i];
}

TEST_F(VtuWriterTest, EveryFormatReadsBackBitForBitWithItsOwnEncoding) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 4, 3, Shape::Quadrilateral));
  const std::vector<double> at_nodes = awkward_values(size_t(mesh->num_nodes()) * 3);
  const std::vector<double> at_cells = awkward_values(size_t(mesh->num_cells()) * 2);
  VtuWriter writer(*mesh);
  writer.add_point_data("awkward", 3, at_nodes);
  writer.add_cell_data("awkward_cells", 2, at_cells);
  const std::map<VtuFormat, std::string> encoding = {{VtuFormat::Ascii, "ascii"},
                                                     {VtuFormat::Base64, "binary"},
                                                     {VtuFormat::Binary, "appended"},
                                                     {VtuFormat::Zlib, "appended"}};
  for (const VtuFormat format : kFormats) {
    SCOPED_TRACE(to_string(format));
    const fs::path path = directory_ / "awkward.vtu";
    writer.write(path.string(), format);
    const std::string vtu = read_text(path);

    const DataArray points = find_array(vtu, "PointData", "awkward");
    EXPECT_EQ(points.components, 3);
    expect_same_bits(points.doubles(), at_nodes, "point data");
    const DataArray cells = find_array(vtu, "CellData", "awkward_cells");
    EXPECT_EQ(cells.components, 2);
    expect_same_bits(cells.doubles(), at_cells, "cell data");
    expect_mesh(vtu, *mesh, 9);

    for (const auto& [section, name] : std::vector<std::pair<std::string, std::string>>{{"PointData", "awkward"},
                                                                                        {"CellData", "awkward_cells"},
                                                                                        {"Points", "Points"},
                                                                                        {"Cells", "connectivity"},
                                                                                        {"Cells", "offsets"},
                                                                                        {"Cells", "types"}})
      EXPECT_EQ(find_array(vtu, section, name).format, encoding.at(format)) << name;
    const bool appended = format == VtuFormat::Binary || format == VtuFormat::Zlib;
    EXPECT_EQ(vtu.find("<AppendedData") != std::string::npos, appended);
    EXPECT_EQ(testing::element_attribute(vtu, "VTKFile", "compressor"),
              format == VtuFormat::Zlib ? "vtkZLibDataCompressor" : "");
  }
}

TEST_F(VtuWriterTest, AsciiAndBinaryFilesHoldTheSameArrays) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {2, 1}, 5, 3, Shape::Triangle));
  FESpace p2(mesh, 2, 2);
  VtuWriter writer(*mesh);
  writer.add_point_field("u", p2, p2.interpolate([](const double* x, double* out) {
    out[0] = std::sin(3 * x[0]) / 7;
    out[1] = std::exp(x[1]) * 1e-9;
  }));
  writer.add_point_data("at_nodes", 1, awkward_values(mesh->num_nodes()));
  writer.add_cell_data("at_cells", 3, awkward_values(size_t(mesh->num_cells()) * 3));
  std::map<VtuFormat, std::string> files;
  for (const VtuFormat format : kFormats) {
    const fs::path path = directory_ / (to_string(format) + ".vtu");
    writer.write(path.string(), format);
    files[format] = read_text(path);
  }
  const std::vector<std::pair<std::string, std::vector<std::string>>> sections = {
      {"PointData", {"u", "at_nodes"}},
      {"CellData", {"at_cells"}},
      {"Points", {"Points"}},
      {"Cells", {"connectivity", "offsets", "types"}}};
  for (const auto& [section, names] : sections) {
    for (const VtuFormat format : kFormats) EXPECT_EQ(testing::array_names(files[format], section), names);
    for (const std::string& name : names) {
      const DataArray ascii = find_array(files[VtuFormat::Ascii], section, name);
      EXPECT_FALSE(ascii.bytes.empty()) << name;
      for (const VtuFormat format : {VtuFormat::Base64, VtuFormat::Binary, VtuFormat::Zlib}) {
        const DataArray other = find_array(files[format], section, name);
        EXPECT_EQ(other.type, ascii.type) << name << " in " << to_string(format);
        EXPECT_EQ(other.components, ascii.components) << name << " in " << to_string(format);
        EXPECT_TRUE(other.bytes == ascii.bytes) << name << ": " << to_string(format) << " differs from ascii";
      }
    }
  }
  // Raw binary is 8 bytes a value (and the XML); zlib less than raw, ascii more.
  EXPECT_LT(files[VtuFormat::Zlib].size(), files[VtuFormat::Binary].size());
  EXPECT_LT(files[VtuFormat::Binary].size(), files[VtuFormat::Base64].size());
}

TEST_F(VtuWriterTest, RawAppendedArraysFollowOneAnotherWithTheirByteCounts) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 3, 2, Shape::Triangle));
  VtuWriter writer(*mesh);
  writer.add_point_data("a", 2, awkward_values(size_t(mesh->num_nodes()) * 2));
  writer.add_cell_data("b", 1, awkward_values(mesh->num_cells()));
  const fs::path path = directory_ / "raw.vtu";
  writer.write(path.string(), VtuFormat::Binary);
  const std::string vtu = read_text(path);

  // Each array's offset is the previous one's plus its UInt64 count and bytes; the last array ends the data.
  const std::string xml = testing::xml_part(vtu);
  const size_t data = vtu.find('_', vtu.find("<AppendedData")) + 1;
  std::uint64_t expected_offset = 0;
  const std::vector<std::pair<std::string, std::uint64_t>> in_file_order = {
      {"a", 16 * mesh->num_nodes()},      {"b", 8 * mesh->num_cells()},
      {"Points", 24 * mesh->num_nodes()}, {"connectivity", 24 * mesh->num_cells()},
      {"offsets", 8 * mesh->num_cells()}, {"types", mesh->num_cells()}};
  for (const auto& [name, bytes] : in_file_order) {
    const size_t at = xml.find("Name=\"" + name + "\"");
    ASSERT_NE(at, std::string::npos) << name;
    const std::string tag = xml.substr(xml.rfind("<DataArray", at), xml.find('>', at) - xml.rfind("<DataArray", at));
    EXPECT_EQ(std::stoull(testing::attribute(tag, "offset")), expected_offset) << name;
    EXPECT_EQ(testing::little_endian(vtu, data + expected_offset, 8), bytes) << name;
    expected_offset += 8 + bytes;
  }
  EXPECT_EQ(vtu.substr(data + expected_offset), "\n  </AppendedData>\n</VTKFile>\n");
}

TEST_F(VtuWriterTest, ZlibHeaderCountsFullBlocksAndAPartialLastOne) {
  // 91 x 91 nodes: 8281 doubles = 66248 bytes, 2 blocks of 32 KiB and one of 712 bytes; 8100 cells of
  // 2 doubles = 129600 bytes, 3 blocks and 31296 bytes; their types, 8100 bytes, one partial block.
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 90, 90, Shape::Quadrilateral));
  ASSERT_EQ(mesh->num_nodes(), 8281);
  ASSERT_EQ(mesh->num_cells(), 8100);
  VtuWriter writer(*mesh);
  writer.add_point_data("partial", 1, awkward_values(mesh->num_nodes()));
  writer.add_cell_data("pairs", 2, awkward_values(size_t(mesh->num_cells()) * 2));
  const fs::path path = directory_ / "blocks.vtu";
  writer.write(path.string(), VtuFormat::Zlib);
  const std::string vtu = read_text(path);

  const std::string xml = testing::xml_part(vtu);
  const size_t data = vtu.find('_', vtu.find("<AppendedData")) + 1;
  const auto header = [&](const std::string& name, int entry) {
    const size_t at = xml.find("Name=\"" + name + "\"");
    const std::string tag = xml.substr(xml.rfind("<DataArray", at), xml.find('>', at) - xml.rfind("<DataArray", at));
    return testing::little_endian(vtu, data + std::stoull(testing::attribute(tag, "offset")) + 8 * entry, 8);
  };
  EXPECT_EQ(header("partial", 0), 3u);
  EXPECT_EQ(header("partial", 1), 32768u);
  EXPECT_EQ(header("partial", 2), 712u);
  EXPECT_EQ(header("pairs", 0), 4u);
  EXPECT_EQ(header("pairs", 1), 32768u);
  EXPECT_EQ(header("pairs", 2), 31296u);
  EXPECT_EQ(header("types", 0), 1u);
  EXPECT_EQ(header("types", 2), 8100u);
  expect_same_bits(find_array(vtu, "PointData", "partial").doubles(), awkward_values(mesh->num_nodes()), "partial");
  expect_same_bits(find_array(vtu, "CellData", "pairs").doubles(), awkward_values(size_t(mesh->num_cells()) * 2),
                   "pairs");
}

TEST_F(VtuWriterTest, ZlibHeaderOfAnArrayOfWholeBlocksHasNoPartialBlock) {
  // 64 x 64 quadrilaterals, 4 components a cell: 4096 x 4 doubles = 131072 bytes = 4 blocks exactly.
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 64, 64, Shape::Quadrilateral));
  VtuWriter writer(*mesh);
  const std::vector<double> values = awkward_values(size_t(mesh->num_cells()) * 4);
  writer.add_cell_data("whole", 4, values);
  const fs::path path = directory_ / "whole.vtu";
  writer.write(path.string(), VtuFormat::Zlib);
  const std::string vtu = read_text(path);
  const size_t data = vtu.find('_', vtu.find("<AppendedData")) + 1;
  // The cell data is the first array: offset 0.
  EXPECT_NE(testing::xml_part(vtu).find("Name=\"whole\" NumberOfComponents=\"4\" format=\"appended\" offset=\"0\""),
            std::string::npos);
  EXPECT_EQ(testing::little_endian(vtu, data, 8), 4u);
  EXPECT_EQ(testing::little_endian(vtu, data + 8, 8), 32768u);
  EXPECT_EQ(testing::little_endian(vtu, data + 16, 8), 0u);
  expect_same_bits(find_array(vtu, "CellData", "whole").doubles(), values, "whole");
}

TEST(VtuFormat, NamesReadBackAndAnUnknownOneIsRefusedNamingItAndTheKnownOnes) {
  EXPECT_EQ(vtu_format_names(), (std::vector<std::string>{"ascii", "base64", "binary", "zlib"}));
  for (const VtuFormat format : kFormats) EXPECT_EQ(vtu_format_from_name(to_string(format), "here"), format);
  expect_error_containing([] { vtu_format_from_name("xml", "scene: 'output.vtu_format'"); },
                          {"scene: 'output.vtu_format'", "'xml'", "ascii, base64, binary, zlib"});
}

TEST_F(VtuWriterTest, PvdListsTimesAndFiles) {
  const std::vector<std::pair<double, std::string>> steps = {
      {0.0, "run_0000.vtu"}, {0.1, "run_0001.vtu"}, {2.5e-3, "run_0002.vtu"}};
  const fs::path path = directory_ / "run.pvd";
  write_pvd(path.string(), steps);
  EXPECT_FALSE(fs::exists(path.string() + ".tmp"));

  const std::string pvd = read_text(path);
  EXPECT_NE(pvd.find("<VTKFile type=\"Collection\""), std::string::npos);
  const std::regex dataset("<DataSet timestep=\"([^\"]*)\"[^>]* file=\"([^\"]*)\"");
  std::vector<std::pair<double, std::string>> read;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), dataset); it != std::sregex_iterator(); ++it)
    read.emplace_back(std::stod((*it)[1].str()), (*it)[2].str());
  EXPECT_EQ(read, steps);
}

TEST_F(VtuWriterTest, RejectsWrongSizes) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 2, 1, Shape::Triangle));
  VtuWriter writer(*mesh);
  expect_error_containing([&] { writer.add_point_data("phi", 2, std::vector<double>(5)); },
                          {"'phi'", "5 values", "2 x 6 nodes"});
  expect_error_containing([&] { writer.add_cell_data("stress", 3, std::vector<double>(4)); },
                          {"'stress'", "4 values", "3 x 4 cells"});
  FESpace p1(mesh, 1, 2);
  expect_error_containing([&] { writer.add_point_field("u", p1, Eigen::VectorXd::Zero(3)); },
                          {"'u'", "3 coefficients", "12 dofs"});

  auto other = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 2, 1, Shape::Triangle));
  FESpace elsewhere(other, 1, 1);
  expect_error_containing([&] { writer.add_point_field("v", elsewhere, Eigen::VectorXd::Zero(6)); },
                          {"'v'", "different mesh"});

  writer.add_point_data("once", 1, std::vector<double>(6));
  expect_error_containing([&] { writer.add_point_data("once", 1, std::vector<double>(6)); }, {"'once'", "twice"});
}

TEST_F(VtuWriterTest, ThrowsNamingAnUnwritablePath) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 1, 1, Shape::Triangle));
  const std::string path = (directory_ / "missing_directory" / "out.vtu").string();
  expect_error_containing([&] { VtuWriter(*mesh).write(path); }, {path});
  const std::string pvd = (directory_ / "missing_directory" / "out.pvd").string();
  expect_error_containing([&] { write_pvd(pvd, {{0.0, "a.vtu"}}); }, {pvd});
}

}  // namespace
}  // namespace pc

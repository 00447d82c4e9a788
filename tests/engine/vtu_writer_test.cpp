// The .vtu files are parsed back (base64 arrays decoded) and compared with the mesh and with the fields'
// exact values at the nodes; the .pvd collection is read back as text.
#include "support/error_and_temp_dir.hpp"
#include "assembly/vtu_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <sstream>

#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

namespace fs = std::filesystem;

using testing::read_text;

std::string base64_decode(const std::string& text) {
  auto sextet = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::string bytes;
  std::uint32_t group = 0;
  int bits = 0;
  for (char c : text) {
    const int value = sextet(c);
    if (value < 0) continue;  // padding and whitespace
    group = (group << 6) | std::uint32_t(value);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes.push_back(static_cast<char>((group >> bits) & 0xff));
    }
  }
  return bytes;
}

std::uint64_t little_endian(const std::string& bytes, size_t at, int size) {
  std::uint64_t value = 0;
  for (int b = size - 1; b >= 0; --b) value = (value << 8) | static_cast<unsigned char>(bytes[at + b]);
  return value;
}

struct DataArray {
  std::string type;
  int components = 0;
  std::string bytes;  // decoded payload without the UInt64 header

  std::vector<double> doubles() const {
    std::vector<double> values(bytes.size() / 8);
    for (size_t i = 0; i < values.size(); ++i) {
      const std::uint64_t bits = little_endian(bytes, 8 * i, 8);
      std::memcpy(&values[i], &bits, 8);
    }
    return values;
  }
  std::vector<std::int64_t> int64s() const {
    std::vector<std::int64_t> values(bytes.size() / 8);
    for (size_t i = 0; i < values.size(); ++i) values[i] = std::int64_t(little_endian(bytes, 8 * i, 8));
    return values;
  }
};

std::string attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const size_t start = tag.find(key);
  if (start == std::string::npos) return "";
  const size_t begin = start + key.size();
  return tag.substr(begin, tag.find('"', begin) - begin);
}

// The array of the given name inside the element <section> ... </section> of a .vtu text.
DataArray find_array(const std::string& vtu, const std::string& section, const std::string& name) {
  const size_t section_begin = vtu.find("<" + section + ">");
  const size_t section_end = vtu.find("</" + section + ">");
  if (section_begin == std::string::npos || section_end == std::string::npos) {
    ADD_FAILURE() << "no section " << section;
    return {};
  }
  const size_t name_at = vtu.find("Name=\"" + name + "\"", section_begin);
  if (name_at == std::string::npos || name_at > section_end) {
    ADD_FAILURE() << "no array " << name << " in " << section;
    return {};
  }
  const size_t tag_begin = vtu.rfind("<DataArray", name_at);
  const size_t tag_end = vtu.find('>', name_at);
  const std::string tag = vtu.substr(tag_begin, tag_end - tag_begin);
  EXPECT_EQ(attribute(tag, "format"), "binary");
  const size_t data_end = vtu.find("</DataArray>", tag_end);
  const std::string decoded = base64_decode(vtu.substr(tag_end + 1, data_end - tag_end - 1));

  DataArray array;
  array.type = attribute(tag, "type");
  array.components = std::stoi(attribute(tag, "NumberOfComponents"));
  EXPECT_GE(decoded.size(), 8u);
  EXPECT_EQ(little_endian(decoded, 0, 8), decoded.size() - 8) << "header byte count of " << name;
  array.bytes = decoded.substr(8);
  return array;
}

// The mesh part of a .vtu: piece sizes, points (z = 0 in 2D), connectivity, offsets and cell types.
void expect_mesh(const std::string& vtu, const Mesh& mesh, int vtk_type) {
  EXPECT_NE(vtu.find("type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" "
                     "header_type=\"UInt64\""),
            std::string::npos);
  EXPECT_NE(vtu.find(message("NumberOfPoints=\"", mesh.num_nodes(), "\" NumberOfCells=\"", mesh.num_cells(),
                             "\"")),
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

const auto linear = [](const double* x, double* out) { out[0] = 1 + 2 * x[0] - 3 * x[1]; };
const auto quadratic_vector = [](const double* x, double* out) {
  out[0] = x[0] * x[0] + x[1];
  out[1] = x[0] * x[1] - 1;
};

TEST_F(VtuWriterTest, TrianglesWithScalarVectorAndCellData) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {2, 1}, 3, 2, Shape::Triangle));
  FESpace p1(mesh, 1, 1), p2(mesh, 2, 2);
  std::vector<double> cell_ids(mesh->num_cells()), pairs(2 * mesh->num_cells());
  for (int c = 0; c < mesh->num_cells(); ++c) {
    cell_ids[c] = c;
    pairs[2 * c] = -c;
    pairs[2 * c + 1] = 0.5 * c;
  }

  VtuWriter writer(*mesh);
  writer.add_point_field("phi", p1, p1.interpolate(linear));
  writer.add_point_field("u", p2, p2.interpolate(quadratic_vector));
  writer.add_cell_data("cell", 1, cell_ids);
  writer.add_cell_data("pair", 2, pairs);
  const fs::path path = directory_ / "triangles.vtu";
  writer.write(path.string());

  EXPECT_FALSE(fs::exists(path.string() + ".tmp"));
  const std::string vtu = read_text(path);
  expect_mesh(vtu, *mesh, 5);
  expect_point_values(vtu, *mesh, "phi", 1, linear);
  // A 2D vector is padded with a zero z component.
  expect_point_values(vtu, *mesh, "u", 3, quadratic_vector);
  EXPECT_EQ(find_array(vtu, "CellData", "cell").doubles(), cell_ids);
  const DataArray pair_array = find_array(vtu, "CellData", "pair");
  EXPECT_EQ(pair_array.components, 2);
  EXPECT_EQ(pair_array.doubles(), pairs);
}

TEST_F(VtuWriterTest, QuadrilateralsWithQ2Field) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({-1, 0}, {1, 3}, 2, 3, Shape::Quadrilateral));
  FESpace q2(mesh, 2, 1);
  const auto f = [](const double* x, double* out) { out[0] = x[0] * x[0] * x[1] - x[1] * x[1]; };
  VtuWriter writer(*mesh);
  writer.add_point_field("q", q2, q2.interpolate(f));
  const fs::path path = directory_ / "quads.vtu";
  writer.write(path.string());

  const std::string vtu = read_text(path);
  expect_mesh(vtu, *mesh, 9);
  expect_point_values(vtu, *mesh, "q", 1, f);
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
  const fs::path path = directory_ / "tets.vtu";
  writer.write(path.string());

  const std::string vtu = read_text(path);
  expect_mesh(vtu, *mesh, 10);
  expect_point_values(vtu, *mesh, "displacement", 3, f);
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
  const fs::path path = directory_ / "hexes.vtu";
  writer.write(path.string());

  const std::string vtu = read_text(path);
  expect_mesh(vtu, *mesh, 12);
  expect_point_values(vtu, *mesh, "T", 1, f);
  EXPECT_EQ(find_array(vtu, "PointData", "node").doubles(), node_ids);
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
  expect_error_containing([&] { writer.add_point_data("once", 1, std::vector<double>(6)); },
                          {"'once'", "twice"});
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

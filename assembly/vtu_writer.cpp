#include "assembly/vtu_writer.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <type_traits>

#include "assembly/atomic_file.hpp"
#include "assembly/error.hpp"

namespace pc {
namespace {

// Binary arrays are little-endian whatever the host, so the byte_order attribute is always true.
void append_little_endian(std::string& bytes, std::uint64_t bits, int size) {
  for (int b = 0; b < size; ++b) bytes.push_back(static_cast<char>((bits >> (8 * b)) & 0xff));
}

std::string base64(const std::string& bytes) {
  static constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t n = std::min<size_t>(3, bytes.size() - i);
    std::uint32_t group = 0;
    for (size_t k = 0; k < 3; ++k)
      group = (group << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (size_t k = 0; k < 4; ++k) text.push_back(k <= n ? alphabet[(group >> (18 - 6 * k)) & 0x3f] : '=');
  }
  return text;
}

// Payload of an inline "binary" DataArray: a UInt64 byte count followed by the values, encoded as one
// base64 stream (VTK's reader decodes header and data from a single stream when uncompressed).
template <class Value>
std::string encode(const std::vector<Value>& values, int size) {
  std::string bytes;
  bytes.reserve(8 + values.size() * size);
  append_little_endian(bytes, std::uint64_t(values.size()) * size, 8);
  for (const Value& v : values) {
    if constexpr (std::is_floating_point_v<Value>)
      append_little_endian(bytes, std::bit_cast<std::uint64_t>(double(v)), size);
    else
      append_little_endian(bytes, static_cast<std::uint64_t>(v), size);
  }
  return base64(bytes);
}

std::string xml_escape(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    switch (c) {
      case '&': escaped += "&amp;"; break;
      case '<': escaped += "&lt;"; break;
      case '>': escaped += "&gt;"; break;
      case '"': escaped += "&quot;"; break;
      case '\'': escaped += "&apos;"; break;
      default: escaped.push_back(c);
    }
  }
  return escaped;
}

void write_data_array(std::ostream& out, const char* type, const std::string& name, int components,
                      const std::string& payload) {
  out << "        <DataArray type=\"" << type << "\" Name=\"" << xml_escape(name)
      << "\" NumberOfComponents=\"" << components << "\" format=\"binary\">\n          " << payload
      << "\n        </DataArray>\n";
}

std::uint8_t vtk_cell_type(Shape shape) {
  switch (shape) {
    case Shape::Point: return 1;
    case Shape::Segment: return 3;
    case Shape::Triangle: return 5;
    case Shape::Quadrilateral: return 9;
    case Shape::Tetrahedron: return 10;
    case Shape::Hexahedron: return 12;
  }
  fail("VtuWriter: no VTK cell type for shape ", static_cast<int>(shape));
}

void require_unique_name(const std::string& kind, const std::string& name, auto const& arrays) {
  require(!name.empty(), "VtuWriter: a ", kind, " field needs a name");
  for (const auto& a : arrays) require(a.name != name, "VtuWriter: ", kind, " field '", name, "' added twice");
}

}  // namespace

VtuWriter::VtuWriter(const Mesh& mesh) : mesh_(mesh) {}

void VtuWriter::add_point_field(const std::string& name, const FESpace& space,
                                const Eigen::VectorXd& coefficients) {
  require(&space.mesh() == &mesh_, "VtuWriter: point field '", name,
          "' lives on a different mesh than the one being written");
  require(coefficients.size() == space.num_dofs(), "VtuWriter: point field '", name, "' has ",
          coefficients.size(), " coefficients, its space has ", space.num_dofs(), " dofs");
  const int field_components = space.num_components();
  // Vectors are padded to 3 components because ParaView only treats 3-component arrays as vectors.
  const int components = field_components == 1 ? 1 : 3;

  // Nodes outside the space's cell region keep the value 0 (VTK has no notion of a partial field).
  std::vector<double> values(size_t(mesh_.num_nodes()) * components, 0.0);
  const ReferenceElement& element = space.element();
  for (int c = 0; c < mesh_.num_cells(); ++c) {
    if (!space.has_cell(c)) continue;
    const auto nodes = mesh_.cell(c);
    const auto dofs = space.cell_scalar_dofs(c);
    for (int i = 0; i < element.num_dofs(); ++i) {
      const DofEntity entity = element.dof_entity(i);
      if (entity.dim != 0) continue;
      for (int k = 0; k < field_components; ++k)
        values[size_t(nodes[entity.index]) * components + k] = coefficients[space.dof(dofs[i], k)];
    }
  }
  add_point_data(name, components, std::move(values));
}

void VtuWriter::add_point_data(const std::string& name, int components, std::vector<double> values) {
  require_unique_name("point", name, point_data_);
  require(components >= 1, "VtuWriter: point field '", name, "' needs at least one component, got ",
          components);
  require(values.size() == size_t(components) * mesh_.num_nodes(), "VtuWriter: point field '", name, "' has ",
          values.size(), " values, expected ", components, " x ", mesh_.num_nodes(), " nodes");
  point_data_.push_back({name, components, std::move(values)});
}

void VtuWriter::add_cell_data(const std::string& name, int components, std::vector<double> values) {
  require_unique_name("cell", name, cell_data_);
  require(components >= 1, "VtuWriter: cell field '", name, "' needs at least one component, got ",
          components);
  require(values.size() == size_t(components) * mesh_.num_cells(), "VtuWriter: cell field '", name, "' has ",
          values.size(), " values, expected ", components, " x ", mesh_.num_cells(), " cells");
  cell_data_.push_back({name, components, std::move(values)});
}

void VtuWriter::write(const std::string& path) const {
  const int dim = mesh_.dim();
  std::vector<double> points(size_t(mesh_.num_nodes()) * 3, 0.0);
  for (int n = 0; n < mesh_.num_nodes(); ++n)
    for (int d = 0; d < dim; ++d) points[size_t(n) * 3 + d] = mesh_.node(n)[d];

  const int per_cell = mesh_.vertices_per_cell();
  std::vector<std::int64_t> connectivity(mesh_.connectivity().begin(), mesh_.connectivity().end());
  std::vector<std::int64_t> offsets(mesh_.num_cells());
  for (int c = 0; c < mesh_.num_cells(); ++c) offsets[c] = std::int64_t(c + 1) * per_cell;
  const std::vector<std::uint8_t> types(mesh_.num_cells(), vtk_cell_type(mesh_.cell_shape()));

  write_atomically(path, "VtuWriter", [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
        << "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << mesh_.num_nodes() << "\" NumberOfCells=\"" << mesh_.num_cells()
        << "\">\n";
    out << "      <PointData>\n";
    for (const Array& a : point_data_) write_data_array(out, "Float64", a.name, a.components, encode(a.values, 8));
    out << "      </PointData>\n      <CellData>\n";
    for (const Array& a : cell_data_) write_data_array(out, "Float64", a.name, a.components, encode(a.values, 8));
    out << "      </CellData>\n      <Points>\n";
    write_data_array(out, "Float64", "Points", 3, encode(points, 8));
    out << "      </Points>\n      <Cells>\n";
    write_data_array(out, "Int64", "connectivity", 1, encode(connectivity, 8));
    write_data_array(out, "Int64", "offsets", 1, encode(offsets, 8));
    write_data_array(out, "UInt8", "types", 1, encode(types, 1));
    out << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  });
}

void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& steps) {
  write_atomically(path, "write_pvd", [&](std::ostream& out) {
    // Full precision so that times read back exactly as given.
    out.precision(std::numeric_limits<double>::max_digits10);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n";
    for (const auto& [time, file] : steps)
      out << "    <DataSet timestep=\"" << time << "\" group=\"\" part=\"0\" file=\"" << xml_escape(file)
          << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
  });
}

}  // namespace pc

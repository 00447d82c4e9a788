#include "assembly/vtu_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

#include "assembly/atomic_file.hpp"
#include "assembly/error.hpp"
#include "assembly/vtu_data_arrays.hpp"

namespace pc {
namespace {

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

// The VTK cell of an order-2 element. VTK orders its nodes as the element orders its local dofs
// (reference_element.hpp, with the edge and face tables of shape.cpp), so the permutation from local
// dofs to VTK nodes is the identity and a cell's connectivity is its dofs as they are:
//   VTK_QUADRATIC_TRIANGLE (22, 6 nodes): vertices 0-2, then the mid-edges of (0,1) (1,2) (2,0).
//   VTK_BIQUADRATIC_QUAD (28, 9 nodes): vertices 0-3, the mid-edges of (0,1) (1,2) (2,3) (3,0), the centre.
//   VTK_QUADRATIC_TETRA (24, 10 nodes): vertices 0-3, the mid-edges of (0,1) (1,2) (0,2) (0,3) (1,3) (2,3).
//   VTK_TRIQUADRATIC_HEXAHEDRON (29, 27 nodes): vertices 0-7, the mid-edges of (0,1) (1,2) (2,3) (3,0)
//     (4,5) (5,6) (6,7) (7,4) (0,4) (1,5) (2,6) (3,7), the centres of the faces x = 0, x = 1, y = 0,
//     y = 1, z = 0, z = 1 (the order of VTK's code and parametric coordinates; its class documentation
//     lists another), the cell centre.
// tests/engine/vtu_writer_test.cpp checks every local dof against VTK's parametric coordinates.
std::uint8_t vtk_quadratic_cell_type(Shape shape) {
  switch (shape) {
    case Shape::Triangle: return 22;
    case Shape::Quadrilateral: return 28;
    case Shape::Tetrahedron: return 24;
    case Shape::Hexahedron: return 29;
    default: break;
  }
  fail("VtuWriter: no quadratic VTK cell type for a ", to_string(shape));
}

// The points (3 coordinates each, z = 0 in 2D) and cells of a file.
struct Grid {
  int num_points = 0;
  std::vector<double> points;
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;
  std::vector<std::uint8_t> types;
};

std::vector<std::int64_t> offsets(int num_cells, int nodes_per_cell) {
  std::vector<std::int64_t> ends(num_cells);
  for (int c = 0; c < num_cells; ++c) ends[c] = std::int64_t(c + 1) * nodes_per_cell;
  return ends;
}

Grid linear_grid(const Mesh& mesh) {
  Grid grid;
  grid.num_points = mesh.num_nodes();
  grid.points.assign(size_t(mesh.num_nodes()) * 3, 0.0);
  for (int n = 0; n < mesh.num_nodes(); ++n)
    for (int d = 0; d < mesh.dim(); ++d) grid.points[size_t(n) * 3 + d] = mesh.node(n)[d];
  grid.connectivity.assign(mesh.connectivity().begin(), mesh.connectivity().end());
  grid.offsets = offsets(mesh.num_cells(), mesh.vertices_per_cell());
  grid.types.assign(mesh.num_cells(), vtk_cell_type(mesh.cell_shape()));
  return grid;
}

// The dofs of an order-2 scalar space of the whole mesh as points, its cells as quadratic cells.
Grid quadratic_grid(const FESpace& space) {
  const Mesh& mesh = space.mesh();
  Grid grid;
  grid.num_points = space.num_scalar_dofs();
  grid.points.assign(size_t(space.num_scalar_dofs()) * 3, 0.0);
  for (int s = 0; s < space.num_scalar_dofs(); ++s)
    for (int d = 0; d < mesh.dim(); ++d) grid.points[size_t(s) * 3 + d] = space.scalar_dof_point(s)[d];
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (const int dof : space.cell_scalar_dofs(c)) grid.connectivity.push_back(dof);
  grid.offsets = offsets(mesh.num_cells(), space.element().num_dofs());
  grid.types.assign(mesh.num_cells(), vtk_quadratic_cell_type(mesh.cell_shape()));
  return grid;
}

// The part of a grid on the flagged cells: their points (kept[i]: the grid's index of the piece's point
// i, increasing) and their cells (`cells_kept`).
Grid piece_of(const Grid& whole, std::span<const char> cells, std::vector<int>& kept, std::vector<int>& cells_kept) {
  std::vector<int> new_index(size_t(whole.num_points), -1);
  for (size_t c = 0; c < cells.size(); ++c)
    if (cells[c])
      for (std::int64_t k = c == 0 ? 0 : whole.offsets[c - 1]; k < whole.offsets[c]; ++k)
        new_index[size_t(whole.connectivity[size_t(k)])] = 0;
  kept.clear();
  for (int p = 0; p < whole.num_points; ++p)
    if (new_index[size_t(p)] == 0) {
      new_index[size_t(p)] = int(kept.size());
      kept.push_back(p);
    }
  Grid piece;
  piece.num_points = int(kept.size());
  for (int p : kept)
    piece.points.insert(piece.points.end(), whole.points.begin() + 3 * p, whole.points.begin() + 3 * p + 3);
  cells_kept.clear();
  for (size_t c = 0; c < cells.size(); ++c) {
    if (!cells[c]) continue;
    cells_kept.push_back(int(c));
    for (std::int64_t k = c == 0 ? 0 : whole.offsets[c - 1]; k < whole.offsets[c]; ++k)
      piece.connectivity.push_back(new_index[size_t(whole.connectivity[size_t(k)])]);
    piece.offsets.push_back(std::int64_t(piece.connectivity.size()));
    piece.types.push_back(whole.types[c]);
  }
  return piece;
}

// The values of the kept entries (points or cells) of an array of `components` values per entry.
std::vector<double> kept_values(const std::vector<double>& values, int components, const std::vector<int>& kept) {
  std::vector<double> out;
  out.reserve(kept.size() * size_t(components));
  for (int i : kept) out.insert(out.end(), values.begin() + i * components, values.begin() + (i + 1) * components);
  return out;
}

void require_unique_name(const std::string& kind, const std::string& name, auto const& arrays) {
  require(!name.empty(), "VtuWriter: a ", kind, " field needs a name");
  for (const auto& a : arrays) require(a.name != name, "VtuWriter: ", kind, " field '", name, "' added twice");
}

}  // namespace

VtuWriter::VtuWriter(const Mesh& mesh) : mesh_(mesh) {}

void VtuWriter::add_point_field(const std::string& name, const FESpace& space, const Eigen::VectorXd& coefficients) {
  require(&space.mesh() == &mesh_, "VtuWriter: point field '", name,
          "' lives on a different mesh than the one being written");
  require(coefficients.size() == space.num_dofs(), "VtuWriter: point field '", name, "' has ", coefficients.size(),
          " coefficients, its space has ", space.num_dofs(), " dofs");
  const int field_components = space.num_components();
  // Vectors are padded to 3 components because ParaView only treats 3-component arrays as vectors.
  const int components = field_components == 1 ? 1 : 3;

  if (space.order() == 1) {
    // The dofs of a P1/Q1 field are its values at the vertices of its cells, in the cell's vertex order.
    std::vector<double> values(size_t(mesh_.num_nodes()) * components, 0.0);
    std::vector<bool> cells(mesh_.num_cells(), false);
    for (int c = 0; c < mesh_.num_cells(); ++c) {
      if (!space.has_cell(c)) continue;
      cells[c] = true;
      const auto nodes = mesh_.cell(c);
      const auto dofs = space.cell_scalar_dofs(c);
      for (size_t v = 0; v < nodes.size(); ++v)
        for (int k = 0; k < field_components; ++k)
          values[size_t(nodes[v]) * components + k] = coefficients[space.dof(dofs[v], k)];
    }
    add_mesh_node_data(name, components, std::move(values), std::move(cells));
    return;
  }

  require_unique_name("point", name, point_data_);
  if (!quadratic_points_) quadratic_points_ = std::make_shared<const FESpace>(space.mesh_ptr(), 2, 1);
  const FESpace& points = *quadratic_points_;
  std::vector<double> values(size_t(points.num_scalar_dofs()) * components, 0.0);
  for (int c = 0; c < mesh_.num_cells(); ++c) {
    if (!space.has_cell(c)) continue;
    // Both spaces list a cell's dofs in the element's local order.
    const auto to = points.cell_scalar_dofs(c);
    const auto from = space.cell_scalar_dofs(c);
    for (size_t i = 0; i < to.size(); ++i)
      for (int k = 0; k < field_components; ++k)
        values[size_t(to[i]) * components + k] = coefficients[space.dof(from[i], k)];
  }
  point_data_.push_back({{name, components, std::move(values)}, false, {}});
}

void VtuWriter::add_point_data(const std::string& name, int components, std::vector<double> values) {
  add_mesh_node_data(name, components, std::move(values), {});
}

void VtuWriter::add_mesh_node_data(const std::string& name, int components, std::vector<double> values,
                                   std::vector<bool> cells) {
  require_unique_name("point", name, point_data_);
  require(components >= 1, "VtuWriter: point field '", name, "' needs at least one component, got ", components);
  require(values.size() == size_t(components) * mesh_.num_nodes(), "VtuWriter: point field '", name, "' has ",
          values.size(), " values, expected ", components, " x ", mesh_.num_nodes(), " nodes");
  point_data_.push_back({{name, components, std::move(values)}, true, std::move(cells)});
}

void VtuWriter::add_cell_data(const std::string& name, int components, std::vector<double> values) {
  require_unique_name("cell", name, cell_data_);
  require(components >= 1, "VtuWriter: cell field '", name, "' needs at least one component, got ", components);
  require(values.size() == size_t(components) * mesh_.num_cells(), "VtuWriter: cell field '", name, "' has ",
          values.size(), " values, expected ", components, " x ", mesh_.num_cells(), " cells");
  cell_data_.push_back({name, components, std::move(values)});
}

std::vector<double> VtuWriter::at_quadratic_points(const PointArray& array) const {
  const FESpace& points = *quadratic_points_;
  const ReferenceElement& linear = ReferenceElement::get(mesh_.cell_shape(), 1);
  const ReferenceElement& quadratic = points.element();
  const int vertices = linear.num_dofs();
  // weights[i * vertices + v]: the P1/Q1 function of vertex v at quadratic node i, the same in every cell.
  std::vector<double> weights(size_t(quadratic.num_dofs()) * vertices);
  for (int i = 0; i < quadratic.num_dofs(); ++i)
    linear.values(quadratic.dof_point(i).data(), weights.data() + size_t(i) * vertices);

  const int components = array.components;
  std::vector<double> values(size_t(points.num_scalar_dofs()) * components, 0.0);
  for (int c = 0; c < mesh_.num_cells(); ++c) {
    if (!array.cells.empty() && !array.cells[c]) continue;
    const auto nodes = mesh_.cell(c);
    const auto to = points.cell_scalar_dofs(c);
    for (size_t i = 0; i < to.size(); ++i)
      for (int k = 0; k < components; ++k) {
        double value = 0;
        for (int v = 0; v < vertices; ++v)
          value += weights[i * vertices + v] * array.values[size_t(nodes[v]) * components + k];
        values[size_t(to[i]) * components + k] = value;
      }
  }
  return values;
}

std::string VtuWriter::non_finite_array() const {
  auto finite = [](const Array& a) {
    return std::all_of(a.values.begin(), a.values.end(), [](double v) { return std::isfinite(v); });
  };
  for (const PointArray& a : point_data_)
    if (!finite(a)) return a.name;
  for (const Array& a : cell_data_)
    if (!finite(a)) return a.name;
  return "";
}

void VtuWriter::write(const std::string& path, VtuFormat format, std::span<const char> cells) const {
  require(cells.empty() || int(cells.size()) == mesh_.num_cells(), "VtuWriter: ", cells.size(),
          " cell flags for a mesh of ", mesh_.num_cells(), " cells (", path, ")");
  const Grid whole = quadratic_points_ ? quadratic_grid(*quadratic_points_) : linear_grid(mesh_);
  std::vector<int> points_kept, cells_kept;
  const Grid piece = cells.empty() ? Grid{} : piece_of(whole, cells, points_kept, cells_kept);
  const Grid& grid = cells.empty() ? whole : piece;
  const int num_cells = cells.empty() ? mesh_.num_cells() : int(cells_kept.size());
  write_atomically(path, "VtuWriter", [&](std::ostream& out) {
    VtuDataArrays arrays(format);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" " << arrays.file_attributes() << ">\n"
        << "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << grid.num_points << "\" NumberOfCells=\"" << num_cells << "\">\n";
    out << "      <PointData>\n";
    // Interpolated values and a piece's values live until the appended data is written.
    std::vector<std::vector<double>> computed;
    computed.reserve(point_data_.size() + cell_data_.size());
    for (const PointArray& a : point_data_) {
      const std::vector<double>* values = &a.values;
      if (quadratic_points_ && a.at_mesh_nodes) values = &computed.emplace_back(at_quadratic_points(a));
      if (!cells.empty()) values = &computed.emplace_back(kept_values(*values, a.components, points_kept));
      arrays.add(out, a.name, a.components, std::span<const double>(*values));
    }
    out << "      </PointData>\n      <CellData>\n";
    for (const Array& a : cell_data_) {
      const std::vector<double>* values = &a.values;
      if (!cells.empty()) values = &computed.emplace_back(kept_values(a.values, a.components, cells_kept));
      arrays.add(out, a.name, a.components, std::span<const double>(*values));
    }
    out << "      </CellData>\n      <Points>\n";
    arrays.add(out, "Points", 3, std::span<const double>(grid.points));
    out << "      </Points>\n      <Cells>\n";
    arrays.add(out, "connectivity", 1, std::span<const std::int64_t>(grid.connectivity));
    arrays.add(out, "offsets", 1, std::span<const std::int64_t>(grid.offsets));
    arrays.add(out, "types", 1, std::span<const std::uint8_t>(grid.types));
    out << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n";
    arrays.write_appended(out);
    out << "</VTKFile>\n";
  });
}

void VtuWriter::write_pvtu(const std::string& path, const std::vector<std::string>& pieces) const {
  write_atomically(path, "VtuWriter", [&](std::ostream& out) {
    auto declare = [&](const Array& a) {
      out << "      <PDataArray type=\"Float64\" Name=\"" << xml_escape(a.name) << "\" NumberOfComponents=\""
          << a.components << "\"/>\n";
    };
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
        << "  <PUnstructuredGrid GhostLevel=\"0\">\n    <PPointData>\n";
    for (const PointArray& a : point_data_) declare(a);
    out << "    </PPointData>\n    <PCellData>\n";
    for (const Array& a : cell_data_) declare(a);
    out << "    </PCellData>\n    <PPoints>\n      <PDataArray type=\"Float64\" Name=\"Points\" "
           "NumberOfComponents=\"3\"/>\n"
        << "    </PPoints>\n";
    for (const std::string& piece : pieces) out << "    <Piece Source=\"" << xml_escape(piece) << "\"/>\n";
    out << "  </PUnstructuredGrid>\n</VTKFile>\n";
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
      out << "    <DataSet timestep=\"" << time << "\" group=\"\" part=\"0\" file=\"" << xml_escape(file) << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
  });
}

}  // namespace pc

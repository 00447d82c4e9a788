#pragma once
// VTK XML unstructured-grid output (.vtu) of fields on a mesh, and the .pvd collection that ParaView
// reads as a time series. A file is linear, the mesh's nodes and cells, unless an order-2 field is
// added: it is then quadratic, its points the order-2 Lagrange nodes of the whole mesh and its cells
// VTK's quadratic cells, so that a P2/Q2 field is written as its dof values, exactly. Cell data carries
// one or more values per cell. The arrays are written in a VtuFormat (assembly/vtu_format.hpp): text,
// inline base64, or raw or zlib-compressed appended data.
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "assembly/fe_space.hpp"
#include "assembly/vtu_format.hpp"

namespace pc {

class VtuWriter {
 public:
  explicit VtuWriter(const Mesh& mesh);

  // A field of a space on this mesh: scalar (1 component) or vector (dim components, padded to 3).
  // Points outside the space's cell region get 0 (VTK has no notion of a partial field).
  void add_point_field(const std::string& name, const FESpace& space, const Eigen::VectorXd& coefficients);
  // Point data given directly at the mesh nodes: num_nodes * components values. A quadratic file
  // writes their linear (P1/Q1) interpolant at its other points.
  void add_point_data(const std::string& name, int components, std::vector<double> values);
  // Cell data: num_cells * components values.
  void add_cell_data(const std::string& name, int components, std::vector<double> values);

  // The name of the first array holding a value that is not finite (inf or NaN), or "" if every value is
  // finite: a caller that must never write a non-finite result checks this before write().
  std::string non_finite_array() const;

  // Writes the file (the directory must exist); throws naming the path if it cannot. With `cells` (one
  // flag per mesh cell) the file is the piece of the flagged cells: the points they use, in increasing
  // order, with their point data, and those cells with their cell data.
  void write(const std::string& path, VtuFormat format = kDefaultVtuFormat, std::span<const char> cells = {}) const;
  // The parallel file (.pvtu) of pieces written by write(..., cells): this writer's arrays, and the
  // pieces' file names (relative to the .pvtu), which ParaView reads as one data set.
  void write_pvtu(const std::string& path, const std::vector<std::string>& pieces) const;

 private:
  struct Array {
    std::string name;
    int components;
    std::vector<double> values;
  };
  // Point values at the mesh nodes, or at the quadratic points. Values at the mesh nodes are interpolated
  // only when a quadratic file is written, since a field added later may make the file quadratic; they
  // interpolate on the given cells (empty: all cells).
  struct PointArray : Array {
    bool at_mesh_nodes;
    std::vector<bool> cells;
  };

  void add_mesh_node_data(const std::string& name, int components, std::vector<double> values, std::vector<bool> cells);
  std::vector<double> at_quadratic_points(const PointArray& array) const;

  const Mesh& mesh_;
  // The whole mesh's order-2 scalar space, whose dofs are a quadratic file's points; null while linear.
  std::shared_ptr<const FESpace> quadratic_points_;
  std::vector<PointArray> point_data_;
  std::vector<Array> cell_data_;
};

// A ParaView collection: (time, file name relative to the .pvd) pairs.
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& steps);

}  // namespace pc

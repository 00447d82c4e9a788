#pragma once
// VTK XML unstructured-grid output (.vtu) of fields on a mesh, and the .pvd collection that ParaView
// reads as a time series. Fields of any order are written at the mesh vertices (the vertex dofs of a
// Lagrange space); cell data carries one or more values per cell.
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "assembly/fe_space.hpp"

namespace pc {

class VtuWriter {
 public:
  explicit VtuWriter(const Mesh& mesh);

  // A field of a space on this mesh: scalar (1 component) or vector (dim components, padded to 3).
  void add_point_field(const std::string& name, const FESpace& space, const Eigen::VectorXd& coefficients);
  // Point data given directly at the mesh nodes: num_nodes * components values.
  void add_point_data(const std::string& name, int components, std::vector<double> values);
  // Cell data: num_cells * components values.
  void add_cell_data(const std::string& name, int components, std::vector<double> values);

  // Writes the file (the directory must exist); throws naming the path if it cannot.
  void write(const std::string& path) const;

 private:
  struct Array {
    std::string name;
    int components;
    std::vector<double> values;
  };
  const Mesh& mesh_;
  std::vector<Array> point_data_;
  std::vector<Array> cell_data_;
};

// A ParaView collection: (time, file name relative to the .pvd) pairs.
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& steps);

}  // namespace pc

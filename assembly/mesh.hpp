#pragma once
// An unstructured mesh of one cell shape (first-order geometry) with named regions: regions of cells
// (subdomains) and regions of boundary or interior faces. Every mesh has the cell region "all" and the
// face region "boundary".
#include <array>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "assembly/shape.hpp"

namespace pc {

// A face of the mesh, named by a cell that owns it and the face's local number in that cell.
struct FaceRef {
  int cell = -1;
  int local_face = -1;
  friend bool operator==(const FaceRef&, const FaceRef&) = default;
  friend auto operator<=>(const FaceRef&, const FaceRef&) = default;
};

enum class RegionKind { Cells, Faces };

class Mesh {
 public:
  // coordinates: num_nodes * dim values; connectivity: num_cells * num_vertices(shape) node indices.
  // Throws on an out-of-range node index, a repeated node in a cell, or an inverted or degenerate cell.
  Mesh(int dim, Shape cell_shape, std::vector<double> coordinates, std::vector<int> connectivity);

  int dim() const { return dim_; }
  Shape cell_shape() const { return cell_shape_; }
  int num_nodes() const { return static_cast<int>(coordinates_.size()) / dim_; }
  int num_cells() const { return static_cast<int>(connectivity_.size()) / vertices_per_cell_; }
  int vertices_per_cell() const { return vertices_per_cell_; }

  std::span<const double> node(int n) const { return {coordinates_.data() + n * dim_, size_t(dim_)}; }
  std::span<const int> cell(int c) const {
    return {connectivity_.data() + c * vertices_per_cell_, size_t(vertices_per_cell_)};
  }
  const std::vector<double>& coordinates() const { return coordinates_; }
  const std::vector<int>& connectivity() const { return connectivity_; }

  // Global node indices of a face, in the order of face_vertices(cell_shape(), local_face).
  std::vector<int> face_nodes(FaceRef face) const;
  // Faces that belong to exactly one cell.
  const std::vector<FaceRef>& boundary_faces() const { return face_region("boundary"); }

  // Regions. Adding a region whose name exists, that is empty, or that names a cell or face that does
  // not exist throws. Looking up a name that does not exist throws and lists the names that do.
  void add_cell_region(const std::string& name, std::vector<int> cells);
  void add_face_region(const std::string& name, std::vector<FaceRef> faces);
  // Boundary faces whose every vertex satisfies the predicate (e.g. a side of a box).
  template <class Predicate> void add_boundary_region_where(const std::string& name, Predicate inside);
  bool has_region(const std::string& name) const;
  RegionKind region_kind(const std::string& name) const;
  const std::vector<int>& cell_region(const std::string& name) const;
  const std::vector<FaceRef>& face_region(const std::string& name) const;
  std::vector<std::string> region_names() const;

  // Measure (length, area or volume) of a cell, of a face, and of a region.
  double cell_measure(int c) const;
  double face_measure(FaceRef f) const;
  double region_measure(const std::string& name) const;
  // Outward unit normal of a face (exact for the flat faces of first-order simplices; at the face
  // centre for bilinear quadrilateral faces).
  std::array<double, 3> face_normal(FaceRef f) const;

 private:
  void check_cells() const;
  void find_boundary_faces();
  std::string known_region_names() const;

  int dim_;
  Shape cell_shape_;
  int vertices_per_cell_;
  std::vector<double> coordinates_;
  std::vector<int> connectivity_;
  std::map<std::string, std::vector<int>> cell_regions_;
  std::map<std::string, std::vector<FaceRef>> face_regions_;
};

template <class Predicate> void Mesh::add_boundary_region_where(const std::string& name, Predicate inside) {
  std::vector<FaceRef> faces;
  for (const FaceRef& f : boundary_faces()) {
    bool all_inside = true;
    for (int n : face_nodes(f)) all_inside = all_inside && inside(node(n));
    if (all_inside) faces.push_back(f);
  }
  add_face_region(name, std::move(faces));
}

}  // namespace pc

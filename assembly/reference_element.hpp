#pragma once
// Lagrange reference elements: P1 and P2 on triangles and tetrahedra, Q1 and Q2 on quadrilaterals and
// hexahedra. Local dofs are ordered as VTK orders the nodes of the matching (quadratic) cell: vertices,
// then edge midpoints, then face centres, then the cell centre; at most one dof lies on an entity, so
// global numbering needs no orientation.
#include <array>
#include <span>
#include <vector>

#include "assembly/shape.hpp"

namespace pc {

// The mesh entity a local dof sits on: its dimension (0 vertex, 1 edge, 2 face, 3 cell interior) and its
// local number among the cell's entities of that dimension (for a 2D cell, dimension 2 is the interior).
struct DofEntity {
  int dim = 0;
  int index = 0;
};

class ReferenceElement {
 public:
  // Shared, immutable instances. Throws for an order other than 1 or 2 or for a non-cell shape.
  static const ReferenceElement& get(Shape shape, int order);

  Shape shape() const { return shape_; }
  int order() const { return order_; }
  int dim() const { return dimension(shape_); }
  int num_dofs() const { return static_cast<int>(points_.size()); }

  // N[i] at reference point xi (dim coordinates).
  void values(const double* xi, double* N) const;
  // dN[i * dim + d] = dN_i / dxi_d at xi.
  void gradients(const double* xi, double* dN) const;

  const std::array<double, 3>& dof_point(int i) const { return points_[i]; }
  DofEntity dof_entity(int i) const { return entities_[i]; }
  // Local dofs whose node lies on the face (the only ones not identically zero there), increasing.
  std::span<const int> face_dofs(int face) const { return face_dofs_[face]; }

 private:
  ReferenceElement(Shape shape, int order);

  Shape shape_;
  int order_;
  std::vector<std::array<double, 3>> points_;
  std::vector<DofEntity> entities_;
  std::vector<std::vector<int>> face_dofs_;
};

}  // namespace pc

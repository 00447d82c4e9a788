#include "models/output/boundary_table.hpp"

#include <algorithm>
#include <numeric>
#include <set>

#include "assembly/error.hpp"

namespace pc {

BoundaryNodes boundary_nodes(const FESpace& space, const std::string& face_region, int sort_axis) {
  const Mesh& mesh = space.mesh();
  require(mesh.region_kind(face_region) == RegionKind::Faces, "boundary_nodes: '", face_region,
          "' is a cell region, a face region is needed");
  require(sort_axis >= 0 && sort_axis < mesh.dim(), "boundary_nodes: sort axis ", sort_axis, " is not an axis of a ",
          mesh.dim(), "D mesh");

  BoundaryNodes unsorted;
  std::set<int> seen;
  const ReferenceElement& element = space.element();
  for (const FaceRef& face : mesh.face_region(face_region)) {
    if (!space.has_cell(face.cell)) continue;
    const auto cell_dofs = space.cell_scalar_dofs(face.cell);
    for (int i : element.face_dofs(face.local_face)) {
      if (!seen.insert(cell_dofs[i]).second) continue;
      unsorted.scalar_dofs.push_back(cell_dofs[i]);
      unsorted.points.push_back(space.scalar_dof_point(cell_dofs[i]));
      unsorted.cells.push_back(face.cell);
      unsorted.reference_points.push_back(element.dof_point(i));
    }
  }
  require(!unsorted.scalar_dofs.empty(), "boundary_nodes: the space has no node on face region '", face_region, "'");

  // Lexicographic order on (x_axis, x_0, x_1, x_2): the sort axis first, then all coordinates.
  std::vector<size_t> order(unsorted.points.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const auto& p = unsorted.points[a];
    const auto& q = unsorted.points[b];
    if (p[sort_axis] != q[sort_axis]) return p[sort_axis] < q[sort_axis];
    return p < q;
  });
  BoundaryNodes nodes;
  nodes.mesh = &mesh;
  for (size_t k : order) {
    nodes.scalar_dofs.push_back(unsorted.scalar_dofs[k]);
    nodes.points.push_back(unsorted.points[k]);
    nodes.cells.push_back(unsorted.cells[k]);
    nodes.reference_points.push_back(unsorted.reference_points[k]);
  }
  return nodes;
}

std::vector<double> values_at_nodes(const BoundaryNodes& nodes, const FESpace& space,
                                    const Eigen::VectorXd& coefficients, int component) {
  require(component >= 0 && component < space.num_components(), "values_at_nodes: component ", component,
          " out of range for a field with ", space.num_components(), " components");
  require(&space.mesh() == nodes.mesh, "values_at_nodes: the field's space is on another mesh than the nodes");
  std::vector<double> values(nodes.cells.size());
  std::vector<double> all_components(space.num_components());
  for (size_t k = 0; k < nodes.cells.size(); ++k) {
    require(space.has_cell(nodes.cells[k]), "values_at_nodes: the field's space does not contain cell ", nodes.cells[k],
            " holding the node at (", nodes.points[k][0], ", ", nodes.points[k][1], ", ", nodes.points[k][2], ")");
    space.evaluate_in_cell(coefficients, nodes.cells[k], nodes.reference_points[k].data(), all_components.data());
    values[k] = all_components[component];
  }
  return values;
}

}  // namespace pc

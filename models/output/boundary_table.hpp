#pragma once
// The Lagrange nodes of a space on a face region, sorted along a coordinate axis, and the values of
// fields there: one table row per node of, e.g., the contact boundary sorted by x (the paper's
// gamma_c.csv: x, ux, uy, vx, vy, phi, ...).
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/fe_space.hpp"

namespace pc {

// Each node is also located in one cell holding it (its reference coordinates there), so that a field of
// any space containing that cell, of any order, can be evaluated at it: a P1 potential at the nodes of
// a P2 displacement, for instance.
struct BoundaryNodes {
  const Mesh* mesh = nullptr;
  std::vector<int> scalar_dofs;                         // of the space the nodes were taken from
  std::vector<std::array<double, 3>> points;            // physical coordinates
  std::vector<int> cells;                               // a cell holding the node
  std::vector<std::array<double, 3>> reference_points;  // the node's reference coordinates in that cell
};

// The space's nodes on the face region, each once, sorted by coordinate sort_axis, ties by the other
// coordinates in increasing axis order. Nodes of faces whose cell lies outside the space are skipped.
BoundaryNodes boundary_nodes(const FESpace& space, const std::string& face_region, int sort_axis);

// Values of one component of a field (space, coefficients) at the nodes, in the nodes' order. The space
// must be on the same mesh and contain the nodes' cells.
std::vector<double> values_at_nodes(const BoundaryNodes& nodes, const FESpace& space,
                                    const Eigen::VectorXd& coefficients, int component);

}  // namespace pc

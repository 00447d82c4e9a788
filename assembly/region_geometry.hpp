#pragma once
// Geometry of a region at the points of one quadrature rule, computed once and shared by every term
// integrated there: weights (rule weight times the measure factor), physical points, inverse Jacobians
// (cells) and outward normals (faces).
#include <array>
#include <span>
#include <string>
#include <vector>

#include "assembly/mesh.hpp"
#include "assembly/quadrature.hpp"
#include "assembly/term.hpp"

namespace pc {

class RegionGeometry {
 public:
  // degree: the polynomial degree the rule integrates exactly (on the cell, or on the face shape).
  // owned_cells, if not empty (one flag per mesh cell): only the region's cells, or faces of cells, that
  // are flagged (a process's share of a distributed model).
  RegionGeometry(const Mesh& mesh, const std::string& region, int degree, std::span<const char> owned_cells = {});

  const Mesh& mesh() const { return mesh_; }
  const std::string& region() const { return region_; }
  Integration integration() const { return integration_; }
  int degree() const { return rule_->degree; }
  int num_elements() const { return static_cast<int>(cells_.size()); }
  int num_points() const { return rule_->size(); }
  int cell(int element) const { return cells_[element]; }
  int local_face(int element) const { return local_faces_.empty() ? -1 : local_faces_[element]; }

  double weight(int element, int q) const { return weights_[element * num_points() + q]; }
  const std::array<double, 3>& point(int element, int q) const { return points_[element * num_points() + q]; }
  const std::array<double, 3>& normal(int element, int q) const { return normals_[element * num_points() + q]; }
  // G[d * dim + k] = d xi_k / d x_d, so that a physical gradient is grad_x N = G grad_xi N (cells only).
  const double* inverse_jacobian_t(int element, int q) const {
    return inverse_jacobians_.data() + (element * num_points() + q) * mesh_.dim() * mesh_.dim();
  }
  // Reference coordinates, in the cell, of the rule's points: on local face f, or in the cell (f = -1).
  const std::vector<std::array<double, 3>>& reference_points(int local_face) const {
    return reference_points_[local_face + 1];
  }

 private:
  void compute_cells(std::span<const char> owned_cells);
  void compute_faces(std::span<const char> owned_cells);

  const Mesh& mesh_;
  std::string region_;
  Integration integration_;
  const QuadratureRule* rule_;
  std::vector<int> cells_;
  std::vector<int> local_faces_;
  std::vector<double> weights_;
  std::vector<std::array<double, 3>> points_;
  std::vector<std::array<double, 3>> normals_;
  std::vector<double> inverse_jacobians_;
  std::vector<std::vector<std::array<double, 3>>> reference_points_;  // [local_face + 1][q]
};

}  // namespace pc

#pragma once
// A Lagrange finite-element space of scalar or vector fields over a mesh, or over one of its cell
// regions. A vector field has num_components() components per scalar dof, interleaved:
// dof = scalar_dof * num_components + component.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/mesh.hpp"
#include "assembly/reference_element.hpp"

namespace pc {

class FESpace {
 public:
  // order 1 or 2 (P1/P2 on simplices, Q1/Q2 on quadrilaterals and hexahedra). An empty cell_region
  // means the whole mesh.
  FESpace(std::shared_ptr<const Mesh> mesh, int order, int num_components, const std::string& cell_region = "");

  const Mesh& mesh() const { return *mesh_; }
  std::shared_ptr<const Mesh> mesh_ptr() const { return mesh_; }
  const ReferenceElement& element() const { return *element_; }
  int order() const { return element_->order(); }
  int num_components() const { return num_components_; }
  int num_scalar_dofs() const { return num_scalar_dofs_; }
  int num_dofs() const { return num_scalar_dofs_ * num_components_; }
  int dof(int scalar_dof, int component) const { return scalar_dof * num_components_ + component; }

  // Whether the space lives on a cell (false outside its cell region).
  bool has_cell(int cell) const { return cell_offset_[cell] >= 0; }
  // Scalar dofs of a cell in the reference element's local order.
  std::span<const int> cell_scalar_dofs(int cell) const;
  // Physical coordinates of a scalar dof (a Lagrange node).
  std::array<double, 3> scalar_dof_point(int scalar_dof) const { return dof_points_[scalar_dof]; }

  // Sorted scalar dofs on a face or cell region; all dofs of the given component (-1: all components).
  std::vector<int> scalar_dofs_on(const std::string& region) const;
  std::vector<int> dofs_on(const std::string& region, int component = -1) const;

  // Lagrange interpolant of f: f(x, out) writes num_components values at the point x.
  Eigen::VectorXd interpolate(const std::function<void(const double* x, double* out)>& f) const;

  // Values of the field with these coefficients at a cell's reference point (num_components values).
  void evaluate_in_cell(const Eigen::VectorXd& coefficients, int cell, const double* xi, double* out) const;
  // Physical gradient of every component there: out[c * dim + d] = d f_c / d x_d.
  void gradient_in_cell(const Eigen::VectorXd& coefficients, int cell, const double* xi, double* out) const;
  // Physical gradients of the cell's scalar shape functions there: out[i * dim + d] = d N_i / d x_d.
  void shape_gradients_in_cell(int cell, const double* xi, double* out) const;

 private:
  std::shared_ptr<const Mesh> mesh_;
  const ReferenceElement* element_;
  int num_components_;
  int num_scalar_dofs_ = 0;
  std::vector<int> cell_offset_;  // into cell_dofs_, -1 outside the region
  std::vector<int> cell_dofs_;
  std::vector<std::array<double, 3>> dof_points_;
};

}  // namespace pc

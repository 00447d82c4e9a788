#pragma once
// The spatial discretisation's error, estimated a posteriori by gradient recovery (Zienkiewicz and Zhu,
// 1987): the finite-element gradient is discontinuous between cells, the true one is not, so a
// continuous gradient recovered from the discrete one is closer to the truth than the discrete one, and
// their difference measures the error.
//
// Recovery: at every Lagrange node, the average of the gradients the node's cells give there, weighted
// by the cells' measures; the recovered gradient is the interpolant of these nodal values in the field's
// own space. Indicator of a cell K, in the energy norm of a weight W (the elasticity for a displacement's
// strain, the permittivity for a potential's gradient):
//     eta_K^2 = int_K (q(G*) - q(G_h))^T W (q(G*) - q(G_h)) dx,   q the strain or the gradient itself,
// and the field's estimate eta = sqrt(sum_K eta_K^2), relative to its norm ||q(G_h)||_W.
//
// What it can and cannot see: for P1 on a mesh that is locally regular, the recovered gradient is
// superconvergent and eta is asymptotically exact (effectivity eta / true error -> 1); for P2 nodal
// averaging is not superconvergent, and eta underestimates (effectivity 0.6 on the manufactured
// solution of tests/models/space_error_test.cpp, at every mesh size): an indicator of where, not a
// bound. Across an interface of two materials the true gradient jumps, the recovered one does not, and
// eta overestimates there. It estimates the error of the fields at one time, not the time error
// (models/time_error_estimate.hpp).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/fe_space.hpp"
#include "assembly/norms.hpp"

namespace pc {

// How a field's gradient enters the norm: its symmetric part in Voigt form (a displacement or velocity:
// W is voigt_size(dim) square), or the gradient itself (each component's: W is dim square).
enum class GradientMeasure { Strain, Gradient };

struct SpaceErrorField {
  std::string field;
  std::vector<double> cells;  // eta_K for every mesh cell, 0 outside the field's space
  double estimate = 0;        // sqrt(sum_K eta_K^2)
  double norm = 0;            // ||q(G_h)||_W, what the estimate is relative to
  double relative() const { return norm > 0 ? estimate / norm : 0.0; }
};

// The recovery estimate on one space, with what depends on the mesh alone found once: for a first-order
// space, the patches' least-squares fits are linear in the cells' centre gradients, so each node's
// recovered gradient is a fixed weighted sum of them (a sparse row per node, of about a patch's cells).
// An estimate is then a pass over the cells for the centre gradients, one over the rows, and one over the
// quadrature points: a run that estimates at every output step builds the estimator once (a fiftieth of
// the cost of building the fits again). The space must outlive it.
class SpaceErrorEstimator {
 public:
  explicit SpaceErrorEstimator(const FESpace& space);
  const FESpace& space() const { return space_; }
  // Whether the estimator serves fields of `other` too: the same mesh, element and cells, and the same
  // scalar dofs in each (e.g. a vector field's space and a scalar one's built alike). What it keeps
  // depends on that scalar structure only, so a velocity and a potential share one.
  bool serves(const FESpace& other) const;
  // The estimate of one field on the space. Throws if W is not the size the measure needs, if the measure
  // is Strain and the field has not dim components, or if the coefficients do not fit the space.
  SpaceErrorField estimate(const std::string& field, const Eigen::VectorXd& coefficients, GradientMeasure measure,
                           const Eigen::MatrixXd& weight) const;
  // The same, of a field on another space that the estimator serves (throws if it does not).
  SpaceErrorField estimate(const std::string& field, const FESpace& field_space, const Eigen::VectorXd& coefficients,
                           GradientMeasure measure, const Eigen::MatrixXd& weight) const;

 private:
  std::vector<double> recovered_nodal_gradients(const FESpace& space, const Eigen::VectorXd& coefficients) const;
  const FESpace& space_;
  // First order: node i's recovered gradient is sum_k weight_[k] * (centre gradient of cell_[k]) over
  // k in [start_[i], start_[i + 1]); nodes with no fit near them (start_[i] == start_[i + 1]) take the
  // nodal average (averaged_ lists them, with their cells). Empty for higher orders, which average.
  std::vector<int> start_, cell_;
  std::vector<double> weight_;
  std::vector<int> averaged_;
  std::vector<std::vector<int>> averaged_cells_;  // the cells of each of averaged_
  std::vector<double> centre_shape_gradients_;    // per cell: its shape functions' gradients at its centre
};

// The recovery estimate of one field, the estimator built for this call.
SpaceErrorField recovery_error_estimate(const std::string& field, const FESpace& space,
                                        const Eigen::VectorXd& coefficients, GradientMeasure measure,
                                        const Eigen::MatrixXd& weight);

// || q(grad f) - q(g) ||_W over the field's cells, q as the measure says, W as above: the true error of f
// in the estimate's norm when g is the exact gradient (g(x, out): out[c * dim + d] = d u_c / d x_d), or
// that of a field on a coarser mesh when f is a fine reference and g the coarse field's gradient
// (gradient_at, assembly/point_locator.hpp). Integrated with the rule of degree 2p + 2 of f's cells.
double energy_norm_difference(const FESpace& space, const Eigen::VectorXd& f, const PointGradient& g,
                              GradientMeasure measure, const Eigen::MatrixXd& weight);

struct SpaceErrorEstimate {
  std::vector<SpaceErrorField> fields;
  const SpaceErrorField* field(const std::string& name) const;
  double max_relative() const;
  // Per cell, sqrt(sum over fields of (eta_K / ||field||)^2): the fields in their own relative units, what
  // marks cells for refinement (assembly/mesh_bisection.hpp's dorfler_marking).
  std::vector<double> relative_cell_indicators() const;
};

}  // namespace pc

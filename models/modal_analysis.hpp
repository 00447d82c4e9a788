#pragma once
// Eigenfrequencies and mode shapes of a model's undamped linear part: K x = omega^2 M x on the free dofs,
// by shift-invert Lanczos (Spectra) around a shift, each operator application one solve with a sparse
// factorisation of the shifted system, factorised once.
//
// The matrices are the model's own: the linear bricks' blocks, read from the model's linear Jacobian with
// the time scheme's factors set to pick them apart (the acceleration's factor gives the mass M, the
// displacement's the stiffness K; what depends on the velocity, the damping, is left out). Nonlinear bricks
// (contact) are not part of it: these are the modes of the free or clamped body.
//
// With a potential, the electric dofs are condensed statically: the modes are those of
//   K* = K_uu + C^T P^-1 C        (the electric rows' sign flipped, [[K_uu, C^T], [C, -P]] is symmetric),
// solved without forming K*: each solve is one of the whole symmetric saddle system
//   [[K_uu - sigma M, C^T], [C, -P]] [x; y] = [b; 0].
// The potential's conditions decide the electrical one: electrodes held at a potential (grounded, or
// driven) are short-circuited; a floating electrode (one unknown potential, UniformValueBrick) is an open
// circuit, its net charge zero; a face with no condition carries no charge (D.n = 0). A distributed (MPI)
// model is not supported.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/model.hpp"

namespace pc {

struct ModalOptions {
  int modes = 6;
  double shift_hz = 0;  // the modes nearest to this frequency (0: the lowest, for a body held in place)
  std::string linear_solver = "umfpack";
  // The affine fields the time scheme made of the velocity: u = k v + ..., a = v / k + ...
  std::string velocity = "v", displacement = "u", acceleration = "a", potential = "phi";
};

struct ModalResult {
  std::vector<double> frequencies_hz;  // ascending
  // Mode shapes in the fields' numbering (constrained dofs 0), one column per mode, M-orthonormal in v.
  Eigen::MatrixXd velocity_shapes;
  Eigen::MatrixXd potential_shapes;  // empty without a potential
  int lanczos_iterations = 0;
  int operator_applications = 0;
};

// The model must be finalized, with a mass (an inertia brick); its fields' values and the scheme's factors
// are as they were afterwards. Throws naming the cause when the eigensolver does not converge.
ModalResult modal_analysis(Model& model, const ModalOptions& options = {});

}  // namespace pc

#pragma once
// CHOLMOD (SuiteSparse) supernodal Cholesky L L^T, for symmetric positive definite matrices only
// (stiffness matrices with enough Dirichlet conditions). The full matrix is expected, as for every
// solver; an unsymmetric or not positive definite one throws.
#include <memory>

#include "assembly/linear_solver.hpp"

namespace pc {

std::unique_ptr<LinearSolver> make_cholmod_solver();

}  // namespace pc

#pragma once
// UMFPACK (SuiteSparse) multifrontal sparse LU with partial pivoting: the default solver, for any
// square nonsingular matrix.
#include <memory>

#include "assembly/linear_solver.hpp"

namespace pc {

std::unique_ptr<LinearSolver> make_umfpack_solver();

}  // namespace pc

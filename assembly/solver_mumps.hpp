#pragma once
// MUMPS multifrontal sparse LU (sequential build, general unsymmetric mode), for any square
// nonsingular matrix; its threshold pivoting copes well with indefinite saddle-point systems.
#include <memory>

#include "assembly/linear_solver.hpp"

namespace pc {

std::unique_ptr<LinearSolver> make_mumps_solver();

}  // namespace pc

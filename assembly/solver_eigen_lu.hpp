#pragma once
// Eigen's SparseLU (supernodal LU with partial pivoting): the reference solver, free of third-party
// libraries, for any square nonsingular matrix.
#include <memory>

#include "assembly/linear_solver.hpp"

namespace pc {

std::unique_ptr<LinearSolver> make_eigen_lu_solver();

}  // namespace pc

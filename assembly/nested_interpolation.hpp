#pragma once
// Moving a field from a mesh to a mesh that refines it (mesh_bisection.hpp): the interpolant, in the fine
// space, of the coarse field, evaluated in the coarse cell each fine cell lies in. For Lagrange spaces of
// one order it is exact, a coarse field being a fine one: nothing is lost in the move.
#include <span>

#include <Eigen/Core>

#include "assembly/fe_space.hpp"

namespace pc {

// parent_cell: for each cell of the fine mesh, the cell of the coarse mesh it lies in. Throws if the
// spaces have different components, if parent_cell does not fit the fine mesh, or if a fine cell of the
// space lies in a coarse cell outside the coarse space.
Eigen::VectorXd interpolate_nested(const FESpace& coarse, const Eigen::VectorXd& coefficients, const FESpace& fine,
                                   std::span<const int> parent_cell);

}  // namespace pc

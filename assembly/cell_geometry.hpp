#pragma once
// First-order geometry of a mesh cell: the map from the reference cell (see shape.hpp) to the physical
// cell, x(xi) = sum_k X_k N_k(xi) with the P1/Q1 vertex functions N_k, and its Jacobian.
#include <array>

#include "assembly/mesh.hpp"

namespace pc {

// Physical point of the reference point xi of a cell.
std::array<double, 3> map_to_physical(const Mesh& mesh, int cell, const double* xi);
// J[i * dim + j] = dx_i / dxi_j at xi (dim = mesh.dim()); returns det J.
double cell_jacobian(const Mesh& mesh, int cell, const double* xi, double* J);
// G = J^-T of a dim x dim Jacobian with determinant det, by cofactors: G[d * dim + k] = d xi_k / d x_d,
// the map from reference to physical gradients (a general inverse costs an LU per point).
void inverse_transpose_jacobian(int dim, const double* J, double det, double* G);
// Reference coordinates of a physical point by Newton's method on the map (exact in one step for
// simplices). Returns false if Newton fails to converge (a point far outside a distorted cell).
bool map_to_reference(const Mesh& mesh, int cell, const double* x, double* xi);
// Whether reference coordinates lie in the reference cell, within tolerance.
bool inside_reference(Shape shape, const double* xi, double tolerance);

}  // namespace pc

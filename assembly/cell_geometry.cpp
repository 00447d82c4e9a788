#include "assembly/cell_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "assembly/error.hpp"

namespace pc {
namespace {

constexpr int kMaxVertices = 8;

// First-order vertex functions N_k(xi) and their gradients dN[k * 3 + j] = dN_k / dxi_j, written out
// here so that the geometry does not depend on the (higher-order) reference elements.
void vertex_functions(Shape shape, const double* xi, double* N, double* dN) {
  switch (shape) {
    case Shape::Triangle:
      N[0] = 1 - xi[0] - xi[1];
      N[1] = xi[0];
      N[2] = xi[1];
      dN[0] = -1, dN[1] = -1;
      dN[3] = 1, dN[4] = 0;
      dN[6] = 0, dN[7] = 1;
      return;
    case Shape::Tetrahedron:
      N[0] = 1 - xi[0] - xi[1] - xi[2];
      for (int k = 1; k < 4; ++k) N[k] = xi[k - 1];
      for (int j = 0; j < 3; ++j) dN[j] = -1;
      for (int k = 1; k < 4; ++k)
        for (int j = 0; j < 3; ++j) dN[k * 3 + j] = (j == k - 1) ? 1 : 0;
      return;
    case Shape::Quadrilateral:
    case Shape::Hexahedron: {
      // Tensor products of the 1D functions 1 - t and t, one factor per reference direction; the
      // corner of vertex k is reference_vertex(shape, k).
      const int d = dimension(shape);
      for (int k = 0; k < num_vertices(shape); ++k) {
        const auto corner = reference_vertex(shape, k);
        double factor[3], slope[3];
        for (int j = 0; j < d; ++j) {
          factor[j] = corner[j] == 1 ? xi[j] : 1 - xi[j];
          slope[j] = corner[j] == 1 ? 1 : -1;
        }
        N[k] = 1;
        for (int j = 0; j < d; ++j) N[k] *= factor[j];
        for (int j = 0; j < d; ++j) {
          double g = slope[j];
          for (int i = 0; i < d; ++i)
            if (i != j) g *= factor[i];
          dN[k * 3 + j] = g;
        }
      }
      return;
    }
    default: break;
  }
  fail("cell geometry: a ", to_string(shape), " is not a mesh cell");
}

double determinant(int dim, const double* J) {
  if (dim == 2) return J[0] * J[3] - J[1] * J[2];
  return J[0] * (J[4] * J[8] - J[5] * J[7]) - J[1] * (J[3] * J[8] - J[5] * J[6]) + J[2] * (J[3] * J[7] - J[4] * J[6]);
}

// Solves J d = r by Cramer's rule (dim <= 3, det precomputed and non-zero).
void solve(int dim, const double* J, double det, const double* r, double* d) {
  if (dim == 2) {
    d[0] = (r[0] * J[3] - J[1] * r[1]) / det;
    d[1] = (J[0] * r[1] - r[0] * J[2]) / det;
    return;
  }
  for (int col = 0; col < 3; ++col) {
    double M[9];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) M[i * 3 + j] = (j == col) ? r[i] : J[i * 3 + j];
    d[col] = determinant(3, M) / det;
  }
}

}  // namespace

std::array<double, 3> map_to_physical(const Mesh& mesh, int cell, const double* xi) {
  double N[kMaxVertices], dN[kMaxVertices * 3];
  vertex_functions(mesh.cell_shape(), xi, N, dN);
  const auto nodes = mesh.cell(cell);
  std::array<double, 3> x{0, 0, 0};
  for (int k = 0; k < int(nodes.size()); ++k) {
    const auto X = mesh.node(nodes[k]);
    for (int i = 0; i < mesh.dim(); ++i) x[i] += N[k] * X[i];
  }
  return x;
}

double cell_jacobian(const Mesh& mesh, int cell, const double* xi, double* J) {
  double N[kMaxVertices], dN[kMaxVertices * 3];
  vertex_functions(mesh.cell_shape(), xi, N, dN);
  const int dim = mesh.dim();
  const auto nodes = mesh.cell(cell);
  for (int i = 0; i < dim * dim; ++i) J[i] = 0;
  for (int k = 0; k < int(nodes.size()); ++k) {
    const auto X = mesh.node(nodes[k]);
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j) J[i * dim + j] += X[i] * dN[k * 3 + j];
  }
  return determinant(dim, J);
}

void inverse_transpose_jacobian(int dim, const double* J, double det, double* G) {
  if (dim == 1) {
    G[0] = 1 / det;
  } else if (dim == 2) {
    G[0] = J[3] / det, G[1] = -J[2] / det, G[2] = -J[1] / det, G[3] = J[0] / det;
  } else {
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k < 3; ++k) {
        const int d1 = (d + 1) % 3, d2 = (d + 2) % 3, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        G[d * 3 + k] = (J[d1 * 3 + k1] * J[d2 * 3 + k2] - J[d1 * 3 + k2] * J[d2 * 3 + k1]) / det;
      }
  }
}

bool map_to_reference(const Mesh& mesh, int cell, const double* x, double* xi) {
  const Shape shape = mesh.cell_shape();
  const int dim = mesh.dim();
  const auto nodes = mesh.cell(cell);
  const auto origin = mesh.node(nodes[0]);
  // Positions relative to the cell's first vertex, so that round-off scales with the cell's size and
  // not with its distance from the coordinate origin.
  double target[3];
  for (int i = 0; i < dim; ++i) target[i] = x[i] - origin[i];

  for (int j = 0; j < dim; ++j) xi[j] = is_simplex(shape) ? 1.0 / (dim + 1) : 0.5;
  // Newton on x(xi) = x: exact after one step for the affine simplex map; quadratic convergence for
  // the multilinear maps of quadrilaterals and hexahedra.
  const int max_iterations = is_simplex(shape) ? 1 : 20;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    double N[kMaxVertices], dN[kMaxVertices * 3], J[9] = {};
    vertex_functions(shape, xi, N, dN);
    double residual[3] = {};
    for (int i = 0; i < dim; ++i) residual[i] = target[i];
    for (int k = 0; k < int(nodes.size()); ++k) {
      const auto X = mesh.node(nodes[k]);
      for (int i = 0; i < dim; ++i) {
        const double relative = X[i] - origin[i];
        residual[i] -= N[k] * relative;
        for (int j = 0; j < dim; ++j) J[i * dim + j] += relative * dN[k * 3 + j];
      }
    }
    const double det = determinant(dim, J);
    if (!(std::abs(det) > 0)) return false;
    double step[3];
    solve(dim, J, det, residual, step);
    double step_size = 0;
    for (int j = 0; j < dim; ++j) {
      xi[j] += step[j];
      step_size = std::max(step_size, std::abs(step[j]));
    }
    if (!std::isfinite(step_size)) return false;
    if (is_simplex(shape) || step_size < 1e-12) return true;
  }
  return false;
}

bool inside_reference(Shape shape, const double* xi, double tolerance) {
  const int d = dimension(shape);
  double sum = 0;
  for (int j = 0; j < d; ++j) {
    if (xi[j] < -tolerance) return false;
    if (!is_simplex(shape) && xi[j] > 1 + tolerance) return false;
    sum += xi[j];
  }
  return !is_simplex(shape) || sum <= 1 + tolerance;
}

}  // namespace pc

#pragma once
// Small sparse matrices with known structure for the linear-solver tests: an SPD Laplacian, a
// nonsymmetric convection-diffusion operator and an indefinite saddle-point matrix.
#include <cmath>
#include <vector>

#include "assembly/sparse.hpp"

namespace pc::testing::matrices {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

inline CsrMatrix from_triplets(int rows, int cols, const Triplets& triplets) {
  CsrMatrix matrix(rows, cols);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  matrix.makeCompressed();
  return matrix;
}

// 5-point stencil on an m x m grid with the neighbours outside the grid eliminated (Dirichlet), plus
// `convection` times a central first difference in x, which makes it nonsymmetric.
inline Triplets stencil_2d(int m, double convection, int offset = 0) {
  Triplets triplets;
  const auto node = [m, offset](int i, int j) { return offset + i * m + j; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      triplets.emplace_back(node(i, j), node(i, j), 4.0);
      if (j > 0) triplets.emplace_back(node(i, j), node(i, j - 1), -1.0 - convection);
      if (j + 1 < m) triplets.emplace_back(node(i, j), node(i, j + 1), -1.0 + convection);
      if (i > 0) triplets.emplace_back(node(i, j), node(i - 1, j), -1.0);
      if (i + 1 < m) triplets.emplace_back(node(i, j), node(i + 1, j), -1.0);
    }
  return triplets;
}

inline CsrMatrix laplacian_2d(int m) { return from_triplets(m * m, m * m, stencil_2d(m, 0.0)); }

inline CsrMatrix convection_diffusion_2d(int m) { return from_triplets(m * m, m * m, stencil_2d(m, 0.4)); }

// [[K, B^T], [B, 0]]: K the Laplacian, each multiplier fixing the mean of one grid row. Symmetric,
// indefinite, with a zero diagonal block that needs pivoting.
inline CsrMatrix saddle_point(int m) {
  Triplets triplets = stencil_2d(m, 0.0);
  const int multipliers = m * m;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      triplets.emplace_back(multipliers + i, i * m + j, 1.0);
      triplets.emplace_back(i * m + j, multipliers + i, 1.0);
    }
  return from_triplets(m * m + m, m * m + m, triplets);
}

// diag(d) A: a symmetric A with its rows weighted, as equations of different units are (for the
// symmetric factorisations that find the weights back, assembly/symmetrizing_scale.hpp).
inline CsrMatrix row_scaled(const CsrMatrix& a, const Eigen::VectorXd& d) {
  CsrMatrix b = a;
  for (int row = 0; row < b.rows(); ++row)
    for (int slot = b.outerIndexPtr()[row]; slot < b.outerIndexPtr()[row + 1]; ++slot) b.valuePtr()[slot] *= d[row];
  return b;
}

// Row weights of both signs over twelve decades, deterministic.
inline Eigen::VectorXd mixed_weights(Eigen::Index n) {
  Eigen::VectorXd d(n);
  for (Eigen::Index i = 0; i < n; ++i) d[i] = (i % 3 == 1 ? -1.0 : 1.0) * std::pow(10.0, double(i % 13) - 6.0);
  return d;
}

// The matrix with its second stored entry 1.5 times larger: one entry off, so that no row scaling makes a
// symmetric matrix symmetric again.
inline CsrMatrix one_entry_changed(const CsrMatrix& a) {
  CsrMatrix changed = a;
  changed.valuePtr()[1] *= 1.5;
  return changed;
}

inline Eigen::VectorXd rhs_for(const CsrMatrix& matrix) {
  Eigen::VectorXd x(matrix.rows());
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = std::sin(0.37 * static_cast<double>(i)) + 0.5;
  return matrix * x;
}

}  // namespace pc::testing::matrices

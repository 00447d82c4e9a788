#pragma once
// Sparse storage used across the engine: compressed sparse rows with 32-bit indices. A pattern is built
// once; assembly writes into valuePtr() through precomputed slot maps.
#include <Eigen/SparseCore>

namespace pc {

using CsrMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// Slot of entry (row, col) in a compressed CSR matrix, or -1 if the pattern lacks it (binary search).
int find_slot(const CsrMatrix& matrix, int row, int col);

}  // namespace pc

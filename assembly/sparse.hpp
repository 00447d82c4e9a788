#pragma once
// Sparse storage used across the engine: compressed sparse rows with 32-bit indices. A pattern is built
// once; assembly writes into valuePtr() through precomputed slot maps.
#include <Eigen/SparseCore>

namespace pc {

using CsrMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
// A CSR matrix over arrays held elsewhere (a term's block: its values over a pattern it shares), and a
// parameter that takes either kind without a copy.
using CsrView = Eigen::Map<const CsrMatrix>;
using CsrRef = Eigen::Ref<const CsrMatrix>;

// Slot of entry (row, col) in a compressed CSR matrix, or -1 if the pattern lacks it (binary search).
int find_slot(const CsrMatrix& matrix, int row, int col);

// First row whose column indices differ between two compressed matrices, or -1 when their sizes and
// patterns are equal (the number of rows when only the sizes differ).
int first_differing_row(const CsrMatrix& a, const CsrMatrix& b);
inline bool same_pattern(const CsrMatrix& a, const CsrMatrix& b) { return first_differing_row(a, b) < 0; }

}  // namespace pc

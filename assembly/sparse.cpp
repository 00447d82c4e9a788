#include "assembly/sparse.hpp"

#include <algorithm>

namespace pc {

int find_slot(const CsrMatrix& matrix, int row, int col) {
  if (row < 0 || row >= matrix.rows()) return -1;
  const int* indices = matrix.innerIndexPtr();
  const int* begin = indices + matrix.outerIndexPtr()[row];
  // An uncompressed matrix has free room at the end of each row: only innerNonZeroPtr() entries count.
  const int* end =
      matrix.isCompressed() ? indices + matrix.outerIndexPtr()[row + 1] : begin + matrix.innerNonZeroPtr()[row];
  // Column indices are sorted within a row.
  const int* found = std::lower_bound(begin, end, col);
  return found != end && *found == col ? static_cast<int>(found - indices) : -1;
}

int first_differing_row(const CsrMatrix& a, const CsrMatrix& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros()) return int(a.rows());
  for (int row = 0; row < a.rows(); ++row) {
    const int begin = a.outerIndexPtr()[row];
    const int end = a.outerIndexPtr()[row + 1];
    if (b.outerIndexPtr()[row + 1] != end ||
        !std::equal(a.innerIndexPtr() + begin, a.innerIndexPtr() + end, b.innerIndexPtr() + begin))
      return row;
  }
  return -1;
}

}  // namespace pc

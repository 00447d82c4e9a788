#pragma once
// The global matrix of a system on the free dofs of a DofLayout. Field blocks (CSR matrices in field
// numbering, e.g. TermAssembly::block) are declared once; finalize() builds the global pattern as their
// union. Summing blocks with scheme factors, J = sum_b factor_b * K_b, merges each block row into its
// global row: a field's free dofs are numbered in increasing order (DofLayout), so the block's columns
// meet the global row's in the same order, and the sum costs one pass over the block's non-zeros and the
// rows they fall in, with no search, no sorting and no map of the block's entries to keep (such a map,
// an int per block entry, was the size of the matrix again).
#include <span>
#include <vector>

#include "assembly/dof_layout.hpp"
#include "assembly/sparse.hpp"

namespace pc {

class SystemMatrix {
 public:
  explicit SystemMatrix(const DofLayout& layout) : layout_(layout) {}

  // Declares a block with rows in field row_field and columns in col_field; returns its handle.
  int declare(int row_field, int col_field, const CsrRef& block);
  void finalize();
  bool finalized() const { return finalized_; }

  void set_zero();
  // matrix += factor * block (the block must have the pattern it was declared with; an entry outside the
  // global pattern is refused).
  void add(int handle, const CsrRef& block, double factor = 1.0);
  // target += factor * block, for a matrix of this one's pattern held apart from it (e.g. the Jacobian
  // formed from the linear part this matrix holds).
  void add_to(int handle, const CsrRef& block, double factor, CsrMatrix& target) const;
  // The same sum into values held apart from the matrix, for some of its rows only: the row `row`'s
  // slots are values[row_start[row]] onwards, in the pattern's order, and a row with row_start -1 is not
  // held (an entry of the block on it is refused). E.g. the rows that nonlinear terms fill, summed
  // without a second copy of the whole matrix.
  void add_to_rows(int handle, const CsrRef& block, double factor, std::span<const long> row_start,
                   std::span<double> values) const;
  const CsrMatrix& matrix() const { return matrix_; }
  int num_blocks() const { return static_cast<int>(blocks_.size()); }

 private:
  // target(row, slot) += factor * block for each of the block's entries on a free row and column; target
  // is given the global row and the slot (an index into the matrix's pattern) of each entry.
  template <class Target> void scatter(int handle, const CsrRef& block, double factor, Target&& target) const;

  struct Block {
    int row_field, col_field, rows, cols;
    long nnz;
    bool any_free = false;          // an entry on a free row and column: a frozen field's blocks have none
    std::vector<int> outer, inner;  // the declared pattern, kept until finalize()
  };
  const DofLayout& layout_;
  std::vector<Block> blocks_;
  CsrMatrix matrix_;
  bool finalized_ = false;
};

}  // namespace pc

#pragma once
// The global matrix of a system on the free dofs of a DofLayout. Field blocks (CSR matrices in field
// numbering, e.g. TermAssembly::block) are declared once; finalize() builds the global pattern as their
// union and maps every block entry to its global slot, so that summing blocks with scheme factors,
// J = sum_b factor_b * K_b, costs one pass over the blocks' non-zeros with no search or sorting.
#include <span>
#include <vector>

#include "assembly/dof_layout.hpp"
#include "assembly/sparse.hpp"

namespace pc {

class SystemMatrix {
 public:
  explicit SystemMatrix(const DofLayout& layout) : layout_(layout) {}

  // Declares a block with rows in field row_field and columns in col_field; returns its handle.
  int declare(int row_field, int col_field, const CsrMatrix& block);
  void finalize();
  bool finalized() const { return finalized_; }

  void set_zero();
  // matrix += factor * block (the block must have the pattern it was declared with).
  void add(int handle, const CsrMatrix& block, double factor = 1.0);
  const CsrMatrix& matrix() const { return matrix_; }
  // The values in pattern order, e.g. to keep a partial sum and restore it without re-adding blocks.
  std::vector<double> values() const { return {matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros()}; }
  void set_values(std::span<const double> values);
  int num_blocks() const { return static_cast<int>(blocks_.size()); }

 private:
  struct Block {
    int row_field, col_field, rows, cols;
    long nnz;
    // Global slot of each block entry, -1 where a row or column is constrained; empty when no entry is free.
    std::vector<int> slots;
    std::vector<int> outer, inner;  // the declared pattern, kept until finalize()
  };
  const DofLayout& layout_;
  std::vector<Block> blocks_;
  CsrMatrix matrix_;
  bool finalized_ = false;
};

}  // namespace pc

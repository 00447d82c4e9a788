#include "assembly/system_matrix.hpp"

#include <algorithm>

#include "assembly/error.hpp"

namespace pc {

int SystemMatrix::declare(int row_field, int col_field, const CsrRef& block) {
  require(!finalized_, "SystemMatrix: declare() after finalize()");
  require(row_field >= 0 && row_field < layout_.num_fields() && col_field >= 0 && col_field < layout_.num_fields(),
          "SystemMatrix: field index out of range");
  require(block.isCompressed(), "SystemMatrix: blocks must be compressed");
  require(block.rows() == int(layout_.global_indices(row_field).size()) &&
              block.cols() == int(layout_.global_indices(col_field).size()),
          "SystemMatrix: block is ", block.rows(), " x ", block.cols(), " but fields '", layout_.field_name(row_field),
          "' x '", layout_.field_name(col_field), "' have ", layout_.global_indices(row_field).size(), " x ",
          layout_.global_indices(col_field).size(), " dofs");
  Block b{row_field, col_field, int(block.rows()), int(block.cols()), long(block.nonZeros()), {}, {}, {}};
  b.outer.assign(block.outerIndexPtr(), block.outerIndexPtr() + block.rows() + 1);
  b.inner.assign(block.innerIndexPtr(), block.innerIndexPtr() + block.nonZeros());
  blocks_.push_back(std::move(b));
  return num_blocks() - 1;
}

void SystemMatrix::finalize() {
  require(!finalized_, "SystemMatrix: finalize() called twice");
  const int n = layout_.size();
  // Column lists per global row, merged over blocks, in one array: each row's room is counted first (a
  // vector per row was a small allocation and its growth per row, half a million at the paper's 240 x 80).
  // Every free dof keeps its diagonal, so that a row no block touches shows as a zero pivot (a clear
  // solver error) rather than a structurally singular pattern.
  std::vector<long> room(n + 1, 0);
  for (int r = 0; r < n; ++r) room[r + 1] = 1;
  auto for_each_entry = [&](auto&& visit) {
    for (const Block& b : blocks_) {
      const auto rows = layout_.global_indices(b.row_field);
      const auto cols = layout_.global_indices(b.col_field);
      for (int r = 0; r < b.rows; ++r) {
        if (rows[r] < 0) continue;
        for (int k = b.outer[r]; k < b.outer[r + 1]; ++k)
          if (cols[b.inner[k]] >= 0) visit(rows[r], cols[b.inner[k]]);
      }
    }
  };
  for_each_entry([&](int row, int) { ++room[row + 1]; });
  for (int r = 0; r < n; ++r) room[r + 1] += room[r];
  std::vector<int> columns(static_cast<size_t>(room[n]));
  std::vector<long> filled(room.begin(), room.end() - 1);
  for (int r = 0; r < n; ++r) columns[size_t(filled[r]++)] = r;
  for_each_entry([&](int row, int col) { columns[size_t(filled[row]++)] = col; });
  std::vector<int> outer(n + 1, 0);
  for (int r = 0; r < n; ++r) {
    const auto first = columns.begin() + room[r], last = columns.begin() + room[r + 1];
    std::sort(first, last);
    outer[r + 1] = outer[r] + static_cast<int>(std::unique(first, last) - first);
  }
  matrix_.resize(n, n);
  matrix_.resizeNonZeros(outer[n]);
  std::copy(outer.begin(), outer.end(), matrix_.outerIndexPtr());
  for (int r = 0; r < n; ++r)
    std::copy_n(columns.begin() + room[r], outer[r + 1] - outer[r], matrix_.innerIndexPtr() + outer[r]);
  std::fill(matrix_.valuePtr(), matrix_.valuePtr() + outer[n], 0.0);

  for (Block& b : blocks_) {
    const auto rows = layout_.global_indices(b.row_field);
    const auto cols = layout_.global_indices(b.col_field);
    for (int r = 0; r < b.rows && !b.any_free; ++r)
      if (rows[r] >= 0)
        for (int k = b.outer[r]; k < b.outer[r + 1] && !b.any_free; ++k) b.any_free = cols[b.inner[k]] >= 0;
    // The declared pattern is no longer needed: swapping with empty vectors frees it, which `= {}` (a
    // clear that keeps the capacity) would not.
    std::vector<int>().swap(b.outer);
    std::vector<int>().swap(b.inner);
  }
  finalized_ = true;
}

void SystemMatrix::set_zero() { std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0); }

template <class Target>
void SystemMatrix::scatter(int handle, const CsrRef& block, double factor, Target&& target) const {
  require(finalized_, "SystemMatrix: add() before finalize()");
  require(handle >= 0 && handle < num_blocks(), "SystemMatrix: unknown block handle ", handle);
  const Block& b = blocks_[handle];
  require(block.isCompressed() && block.nonZeros() == b.nnz && block.rows() == b.rows && block.cols() == b.cols,
          "SystemMatrix: block ", handle, " changed its pattern since it was declared");
  if (!b.any_free) return;
  const auto rows = layout_.global_indices(b.row_field);
  const auto cols = layout_.global_indices(b.col_field);
  const int* block_outer = block.outerIndexPtr();
  const int* block_inner = block.innerIndexPtr();
  const double* values = block.valuePtr();
  const int* outer = matrix_.outerIndexPtr();
  const int* inner = matrix_.innerIndexPtr();
  for (int r = 0; r < b.rows; ++r) {
    const int row = rows[r];
    if (row < 0) continue;
    int slot = outer[row];
    const int end = outer[row + 1];
    for (int k = block_outer[r]; k < block_outer[r + 1]; ++k) {
      const int col = cols[block_inner[k]];
      if (col < 0) continue;
      // Columns come in increasing order, so the slot search moves forward, except after a tied dof
      // (DofLayout), whose column may lie behind: search that one from the row's start.
      if (slot < end && inner[slot] > col) slot = int(std::lower_bound(inner + outer[row], inner + end, col) - inner);
      while (slot < end && inner[slot] < col) ++slot;
      require(slot < end && inner[slot] == col, "SystemMatrix: block ", handle, " has an entry (", r, ", ",
              block_inner[k], ") outside the pattern it was declared with");
      target(row, slot, factor * values[k]);
    }
  }
}

void SystemMatrix::add(int handle, const CsrRef& block, double factor) { add_to(handle, block, factor, matrix_); }

void SystemMatrix::add_to(int handle, const CsrRef& block, double factor, CsrMatrix& target) const {
  require(target.rows() == matrix_.rows() && target.nonZeros() == matrix_.nonZeros(),
          "SystemMatrix: add_to() a matrix of another pattern");
  double* values = target.valuePtr();
  scatter(handle, block, factor, [values](int, int slot, double value) { values[slot] += value; });
}

void SystemMatrix::add_to_rows(int handle, const CsrRef& block, double factor, std::span<const long> row_start,
                               std::span<double> values) const {
  require(long(row_start.size()) == long(matrix_.rows()), "SystemMatrix: add_to_rows() with ", row_start.size(),
          " row starts for ", matrix_.rows(), " rows");
  const int* outer = matrix_.outerIndexPtr();
  scatter(handle, block, factor, [&](int row, int slot, double value) {
    require(row_start[row] >= 0, "SystemMatrix: block ", handle, " has an entry on row ", row,
            ", which add_to_rows() does not hold");
    values[size_t(row_start[row] + (slot - outer[row]))] += value;
  });
}

}  // namespace pc

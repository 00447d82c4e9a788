// The global matrix of a system on the free dofs (assembly/system_matrix.hpp): blocks land in their global
// slots with their factors, constrained rows and columns drop out, a block with no free entry at all (a
// frozen field's) adds nothing, and an entry outside the declared pattern is refused.
#include <gtest/gtest.h>

#include "assembly/dof_layout.hpp"
#include "assembly/error.hpp"
#include "assembly/system_matrix.hpp"

namespace pc {
namespace {

CsrMatrix block(int rows, int cols, std::vector<Eigen::Triplet<double, int>> entries) {
  CsrMatrix m(rows, cols);
  m.setFromTriplets(entries.begin(), entries.end());
  m.makeCompressed();
  return m;
}

TEST(SystemMatrix, SumsBlocksOnTheFreeDofsAndSkipsBlocksWithNoFreeEntry) {
  DofLayout layout;
  layout.add_field("a", 2, {1});     // dof 1 of a is constrained
  layout.add_field("b", 2, {0, 1});  // b is frozen: no free dof
  SystemMatrix system(layout);
  const CsrMatrix aa = block(2, 2, {{0, 0, 1.0}, {0, 1, 2.0}, {1, 0, 3.0}, {1, 1, 4.0}});
  const CsrMatrix ab = block(2, 2, {{0, 0, 5.0}, {1, 1, 6.0}});
  const CsrMatrix bb = block(2, 2, {{0, 0, 7.0}, {1, 1, 8.0}});
  const int h_aa = system.declare(0, 0, aa), h_ab = system.declare(0, 1, ab), h_bb = system.declare(1, 1, bb);
  system.finalize();
  ASSERT_EQ(system.matrix().rows(), 1);
  system.set_zero();
  system.add(h_aa, aa, 2.0);
  system.add(h_ab, ab, 10.0);  // its only free row meets no free column
  system.add(h_bb, bb, 10.0);  // no free entry at all
  EXPECT_EQ(system.matrix().nonZeros(), 1);
  EXPECT_EQ(system.matrix().coeff(0, 0), 2.0);
  EXPECT_THROW(system.add(h_bb, block(1, 1, {{0, 0, 1.0}}), 1.0), Error) << "a block of another pattern is refused";
}

// Each block row is merged into its global row: blocks of different patterns over the same fields sum
// into the union, and a block whose entries moved (same count, other columns) is refused, not misplaced.
TEST(SystemMatrix, MergesBlocksIntoTheUnionOfTheirPatterns) {
  DofLayout layout;
  layout.add_field("u", 3);
  SystemMatrix system(layout);
  const CsrMatrix lower = block(3, 3, {{1, 0, 1.0}, {2, 0, 2.0}, {2, 1, 3.0}});
  const CsrMatrix upper = block(3, 3, {{0, 1, 4.0}, {0, 2, 5.0}, {1, 2, 6.0}});
  const int h_lower = system.declare(0, 0, lower), h_upper = system.declare(0, 0, upper);
  system.finalize();
  system.set_zero();
  system.add(h_upper, upper, 1.0);
  system.add(h_lower, lower, -1.0);
  const Eigen::MatrixXd expected = Eigen::MatrixXd(upper) - Eigen::MatrixXd(lower);
  EXPECT_EQ(Eigen::MatrixXd(system.matrix()), expected);
  EXPECT_EQ(system.matrix().nonZeros(), 9) << "the union of both patterns and the diagonal";
  DofLayout small;
  small.add_field("u", 2);
  SystemMatrix two(small);
  const int h = two.declare(0, 0, block(2, 2, {{0, 1, 1.0}}));
  two.finalize();
  EXPECT_THROW(two.add(h, block(2, 2, {{1, 0, 1.0}}), 1.0), Error) << "(1, 0) is outside the declared pattern";
}

// The same sums into values held apart: add_to() into a matrix of the same pattern gives what add() gives,
// and add_to_rows() gives exactly the held rows' slots of it, refusing an entry on a row it does not hold.
TEST(SystemMatrix, SumsIntoAMatrixOfItsPatternOrIntoSomeOfItsRowsAlone) {
  DofLayout layout;
  layout.add_field("u", 3);
  SystemMatrix system(layout);
  const CsrMatrix full = block(3, 3, {{0, 0, 1.0}, {0, 2, 2.0}, {1, 1, 3.0}, {2, 0, 4.0}, {2, 2, 5.0}});
  const CsrMatrix corner = block(3, 3, {{2, 0, 0.5}, {2, 2, 0.25}});  // row 2 alone
  const int h_full = system.declare(0, 0, full), h_corner = system.declare(0, 0, corner);
  system.finalize();
  system.set_zero();
  system.add(h_full, full, 1.0);
  system.add(h_corner, corner, 4.0);
  CsrMatrix apart = system.matrix();
  std::fill(apart.valuePtr(), apart.valuePtr() + apart.nonZeros(), 0.0);
  system.add_to(h_full, full, 1.0, apart);
  system.add_to(h_corner, corner, 4.0, apart);
  EXPECT_EQ(Eigen::MatrixXd(apart), Eigen::MatrixXd(system.matrix()));

  // Row 2 alone: its slots in the pattern are columns 0 and 2.
  const int* outer = system.matrix().outerIndexPtr();
  const std::vector<long> row_start{-1, -1, 0};
  std::vector<double> values(size_t(outer[3] - outer[2]), 0.0);
  system.add_to_rows(h_corner, corner, 4.0, row_start, values);
  ASSERT_EQ(values.size(), 2u);
  EXPECT_EQ(values[0], 2.0);  // (2, 0)
  EXPECT_EQ(values[1], 1.0);  // (2, 2)
  EXPECT_THROW(system.add_to_rows(h_full, full, 1.0, row_start, values), Error) << "rows 0 and 1 are not held";
  CsrMatrix other(3, 3);
  EXPECT_THROW(system.add_to(h_full, full, 1.0, other), Error) << "a matrix of another pattern";
}

}  // namespace
}  // namespace pc

// The global matrix of a system on the free dofs (assembly/system_matrix.hpp): blocks land in their global
// slots with their factors, constrained rows and columns drop out, and a block with no free entry at all
// (a frozen field's) adds nothing.
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

}  // namespace
}  // namespace pc

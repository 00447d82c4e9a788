// Numbering of the unknowns (assembly/dof_layout.hpp) with constrained dofs and tied groups: a tied
// group is one unknown, so the global system is the field system restricted by the prolongation P
// (P[d, g(d)] = 1 on free dofs): its matrix is P^T K P, residuals sum over a group and a step moves a
// group's dofs alike. Overlapping or constrained groups are refused.
#include <gtest/gtest.h>

#include "assembly/dof_layout.hpp"
#include "assembly/error.hpp"
#include "assembly/system_matrix.hpp"

namespace pc {
namespace {

// Field 5 dofs: dof 0 constrained, {1, 4} and {3, 2} tied (the second group's leader, its smallest dof,
// comes after one of its members): global unknowns {1,4}, {2,3}.
DofLayout tied_layout() {
  DofLayout layout;
  layout.add_field("phi", 5, {0}, {{1, 4}, {3, 2}});
  return layout;
}

Eigen::MatrixXd prolongation(const DofLayout& layout) {
  const auto global = layout.global_indices(0);
  Eigen::MatrixXd p = Eigen::MatrixXd::Zero(int(global.size()), layout.size());
  for (int d = 0; d < int(global.size()); ++d)
    if (global[d] >= 0) p(d, global[d]) = 1;
  return p;
}

TEST(DofLayout, TiedGroupsShareOneGlobalIndexAndKeepTheFieldBlocksConsecutive) {
  const DofLayout layout = tied_layout();
  ASSERT_EQ(layout.size(), 2);
  EXPECT_EQ(layout.num_free(0), 2);
  const auto g = layout.global_indices(0);
  EXPECT_EQ(g[0], -1);
  EXPECT_EQ(g[1], g[4]);
  EXPECT_EQ(g[2], g[3]);
  EXPECT_NE(g[1], g[2]);
  DofLayout two;
  two.add_field("v", 3, {2});
  two.add_field("phi", 5, {0}, {{1, 4}, {3, 2}});
  EXPECT_EQ(two.size(), 4);
  for (int d = 1; d < 5; ++d) EXPECT_GE(two.global_indices(1)[d], 2) << "the second field starts after the first";
}

TEST(DofLayout, ResidualsSumOverAGroupValuesCopyAndStepsMoveAGroupAlike) {
  const DofLayout layout = tied_layout();
  const auto g = layout.global_indices(0);
  Eigen::VectorXd residual(5), sum = Eigen::VectorXd::Zero(2);
  residual << 100, 1, 2, 4, 8;
  layout.add_to_global(0, residual, sum);
  EXPECT_EQ(sum[g[1]], 1 + 8);
  EXPECT_EQ(sum[g[2]], 2 + 4);
  Eigen::VectorXd values(5), x = Eigen::VectorXd::Zero(2);
  values << 7, 3, 5, 5, 3;
  layout.copy_to_global(0, values, x);
  EXPECT_EQ(x[g[1]], 3);
  EXPECT_EQ(x[g[2]], 5);
  Eigen::VectorXd step(2);
  step << 0.5, -0.25;
  layout.add_from_global(0, step, values);
  EXPECT_EQ(values[0], 7) << "a constrained dof is untouched";
  EXPECT_EQ(values[1], values[4]);
  EXPECT_EQ(values[2], values[3]);
  EXPECT_EQ(values[1], 3 + step[g[1]]);
}

TEST(DofLayout, SystemMatrixOfTiedDofsIsTheGalerkinRestrictionOfTheFieldMatrix) {
  const DofLayout layout = tied_layout();
  // A full symmetric field block, so every row meets a tied column behind the one before it.
  Eigen::MatrixXd k(5, 5);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) k(i, j) = 1.0 / (1 + i + j) + (i == j ? 3 : 0);
  CsrMatrix block = k.sparseView();
  block.makeCompressed();
  SystemMatrix system(layout);
  const int h = system.declare(0, 0, block);
  system.finalize();
  system.set_zero();
  system.add(h, block, 2.0);
  const Eigen::MatrixXd p = prolongation(layout);
  const Eigen::MatrixXd expected = 2.0 * p.transpose() * k * p;
  EXPECT_LT((Eigen::MatrixXd(system.matrix()) - expected).norm(), 1e-14 * expected.norm());
  EXPECT_LT((expected - expected.transpose()).norm(), 1e-15) << "tying keeps a symmetric matrix symmetric";
}

TEST(DofLayout, RefusesATiedDofThatIsConstrainedOrInTwoGroups) {
  DofLayout a, b, c;
  EXPECT_THROW(a.add_field("phi", 4, {1}, {{0, 1}}), Error);
  EXPECT_THROW(b.add_field("phi", 4, {}, {{0, 1}, {1, 2}}), Error);
  EXPECT_THROW(c.add_field("phi", 4, {}, {{0, 4}}), Error);
}

}  // namespace
}  // namespace pc

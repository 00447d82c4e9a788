// The dense inverse the Schur path keeps of its contact block (LAPACK's LU): exact where the inverse is
// known in closed form, A A^-1 = 1 to round-off on a matrix with pivoting, and refused, with nothing
// returned, for a singular matrix or one closer to singular than the caller allows.
#include <gtest/gtest.h>

#include <cmath>

#include "assembly/dense_inverse.hpp"

namespace pc {
namespace {

TEST(DenseInverse, IsTheClosedFormInverseOfATwoByTwo) {
  Eigen::MatrixXd a(2, 2);
  a << 4, 7, 2, 6;  // det 10
  const auto inverse = inverse_if_regular(a, 0.0);
  ASSERT_TRUE(inverse.has_value());
  Eigen::MatrixXd expected(2, 2);
  expected << 0.6, -0.7, -0.2, 0.4;
  EXPECT_LT((*inverse - expected).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(DenseInverse, InvertsAMatrixThatNeedsPivotingToRoundOff) {
  const int n = 200;
  Eigen::MatrixXd a(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) a(i, j) = std::sin(1.0 + i + 3.0 * j * j) + (i == (j + 7) % n ? 5.0 : 0.0);
  a(0, 0) = 0;  // a zero first pivot: LU without row exchanges would divide by it
  const auto inverse = inverse_if_regular(a, 1e-8);
  ASSERT_TRUE(inverse.has_value());
  EXPECT_LT((a * *inverse - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(DenseInverse, RefusesSingularAndNearlySingularMatrices) {
  Eigen::MatrixXd rank_one(3, 3);
  rank_one << 1, 2, 3, 2, 4, 6, 3, 6, 9;
  EXPECT_FALSE(inverse_if_regular(rank_one, 0.0).has_value());
  // diag(1, 1e-10): its smallest singular value is 1e-10, which the condition estimate finds.
  Eigen::MatrixXd nearly = Eigen::MatrixXd::Identity(2, 2);
  nearly(1, 1) = 1e-10;
  EXPECT_FALSE(inverse_if_regular(nearly, 1e-9).has_value());
  const auto inverse = inverse_if_regular(nearly, 1e-11);
  ASSERT_TRUE(inverse.has_value());
  EXPECT_DOUBLE_EQ((*inverse)(1, 1), 1e10);
  Eigen::MatrixXd not_finite = Eigen::MatrixXd::Identity(2, 2);
  not_finite(0, 1) = std::nan("");
  EXPECT_FALSE(inverse_if_regular(not_finite, 0.0).has_value());
}

}  // namespace
}  // namespace pc

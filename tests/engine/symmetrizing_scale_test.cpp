// The row scaling that makes a matrix symmetric (assembly/symmetrizing_scale.hpp): found back on
// symmetric matrices whose rows were weighted over twelve decades and both signs, on the piezoelectric
// block form [K C; c C^T -G], component by component; refused on nonsymmetric values and patterns, while
// a disagreement at the round-off of a row passes.
#include "assembly/symmetrizing_scale.hpp"

#include <gtest/gtest.h>

#include "assembly/error.hpp"
#include "support/test_matrices.hpp"

namespace pc {
namespace {

using namespace testing::matrices;

// The largest |s_i A_ij - s_j A_ji| relative to the largest |s_i A_ij|.
double asymmetry(const CsrMatrix& a, const Eigen::VectorXd& s) {
  const Eigen::MatrixXd scaled = s.asDiagonal() * Eigen::MatrixXd(a);
  return (scaled - scaled.transpose()).cwiseAbs().maxCoeff() / scaled.cwiseAbs().maxCoeff();
}

TEST(SymmetrizingRowScale, FindsTheInverseOfTheWeightsOfWeightedSymmetricRows) {
  for (const CsrMatrix& symmetric : {laplacian_2d(7), saddle_point(6)}) {
    const Eigen::VectorXd d = mixed_weights(symmetric.rows());
    const CsrMatrix a = row_scaled(symmetric, d);
    const std::optional<Eigen::VectorXd> s = symmetrizing_row_scale(a);
    ASSERT_TRUE(s.has_value());
    EXPECT_LT(asymmetry(a, *s), 1e-14);
    // s_i d_i is one constant: the weights undone, up to the component's normalisation (s_0 = 1).
    EXPECT_DOUBLE_EQ((*s)[0], 1.0);
    for (Eigen::Index i = 0; i < a.rows(); ++i) EXPECT_NEAR((*s)[i] * d[i] / d[0], 1.0, 1e-12) << "row " << i;
  }
}

// [K C; c C^T -G] with K, G SPD Laplacians on an m x m grid (n = m^2 rows each) and a coupling C of row i
// to row n + i + 1, c the time scheme's factor.
CsrMatrix piezoelectric_form(int m, double c) {
  const int n = m * m;
  Triplets t;
  for (const auto& e : stencil_2d(m, 0.0)) {
    t.emplace_back(e.row(), e.col(), 1e9 * e.value());
    t.emplace_back(n + e.row(), n + e.col(), -1e-8 * e.value());
  }
  for (int i = 0; i + 1 < n; ++i) {
    t.emplace_back(i, n + i + 1, 17.0);
    t.emplace_back(n + i + 1, i, c * 17.0);
  }
  return from_triplets(2 * n, 2 * n, t);
}

TEST(SymmetrizingRowScale, UndoesTheTimeSchemeFactorOfThePiezoelectricGaussLaw) {
  // c = 1e-3 (a step): s = 1 on the first block, 1/c on the second.
  const int m = 5, n = m * m;
  const double c = 1e-3;
  const CsrMatrix a = piezoelectric_form(m, c);
  const std::optional<Eigen::VectorXd> s = symmetrizing_row_scale(a);
  ASSERT_TRUE(s.has_value());
  for (int i = 0; i < n; ++i) EXPECT_NEAR((*s)[i], 1.0, 1e-14);
  for (int i = n + 1; i < 2 * n; ++i) EXPECT_NEAR((*s)[i] * c, 1.0, 1e-12);
  EXPECT_LT(asymmetry(a, *s), 1e-15);
}

// The scale of the sum of the processes' shares (on one process, the whole matrix is the one share): each
// component normalised by its row of the largest scale, so that every share of a distributed matrix
// gives the same numbers on the rows it holds. Distributed, tests/mpi/ run it on 2 and 3 processes.
TEST(SymmetrizingRowScale, TheScaleOfSharesIsNormalisedByItsLargestRow) {
  const int m = 5, n = m * m;
  const double c = 1e-3;
  const CsrMatrix a = piezoelectric_form(m, c);
  const RowSymmetrizer symmetrizer(a);
  const std::optional<Eigen::VectorXd> s = symmetrizer.scale_of_shares(a);
  ASSERT_TRUE(s.has_value());
  // Row n, coupled to nothing by a strong entry, keeps 1; the others are c and 1.
  for (int i = 0; i < n; ++i) EXPECT_NEAR((*s)[i], c, 1e-17) << i;
  for (int i = n; i < 2 * n; ++i) EXPECT_NEAR((*s)[i], 1.0, 1e-12) << i;
  EXPECT_LT(asymmetry(a, *s), 1e-15);
  // Values that lose the symmetry: no scale, as scale() says.
  CsrMatrix b = a;
  b.coeffRef(0, n + 1) *= 1.5;
  EXPECT_FALSE(RowSymmetrizer(b).scale_of_shares(b).has_value());
}

TEST(SymmetrizingRowScale, GivesEachConnectedComponentItsOwnScale) {
  // Two uncoupled weighted Laplacians: each component's first row keeps the scale 1.
  const CsrMatrix block = laplacian_2d(4);
  Triplets t;
  for (int k = 0; k < block.outerSize(); ++k)
    for (CsrMatrix::InnerIterator it(block, k); it; ++it) {
      t.emplace_back(it.row(), it.col(), it.value());
      t.emplace_back(16 + it.row(), 16 + it.col(), -3.0 * it.value());
    }
  const std::optional<Eigen::VectorXd> s = symmetrizing_row_scale(from_triplets(32, 32, t));
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(s->isOnes(1e-14));
}

TEST(SymmetrizingRowScale, SymmetrizesConstantConvectionDiffusion) {
  // A constant convection in x is self-adjoint in a weighted product: s(x + h) / s(x) = (1 - c) / (1 + c),
  // 3/7 for the stencil's c = 0.4 (s_i a_i,i+1 = s_i+1 a_i+1,i with a = -1 + c and -1 - c).
  const int m = 6;
  const CsrMatrix a = convection_diffusion_2d(m);
  const std::optional<Eigen::VectorXd> s = symmetrizing_row_scale(a);
  ASSERT_TRUE(s.has_value());
  for (int row = 0; row < m; ++row)
    for (int col = 0; col + 1 < m; ++col) EXPECT_NEAR((*s)[row * m + col + 1] / (*s)[row * m + col], 3.0 / 7.0, 1e-14);
  EXPECT_LT(asymmetry(a, *s), 1e-14);
}

TEST(SymmetrizingRowScale, RefusesNonsymmetricValuesAndPatterns) {
  // One entry of a Laplacian changed: the grid's cycles through it no longer close.
  CsrMatrix changed = laplacian_2d(5);
  changed.coeffRef(0, 1) = -1.5;
  EXPECT_FALSE(symmetrizing_row_scale(changed).has_value());
  // One entry without its mirror.
  Triplets t = stencil_2d(4, 0.0);
  t.emplace_back(0, 15, 0.5);
  EXPECT_FALSE(symmetrizing_row_scale(from_triplets(16, 16, t)).has_value());
  // A cycle whose weights do not close: a_01 a_12 a_20 != a_10 a_21 a_02, no diagonal scaling exists
  // although every single pair could be matched.
  const CsrMatrix cycle = from_triplets(
      3, 3, {{0, 0, 4}, {1, 1, 4}, {2, 2, 4}, {0, 1, 1}, {1, 0, 2}, {1, 2, 1}, {2, 1, 1}, {2, 0, 1}, {0, 2, 1}});
  EXPECT_FALSE(symmetrizing_row_scale(cycle).has_value());
  // A non-finite entry.
  CsrMatrix nan = laplacian_2d(3);
  nan.valuePtr()[1] = std::nan("");
  EXPECT_FALSE(symmetrizing_row_scale(nan).has_value());
}

TEST(SymmetrizingRowScale, AcceptsRoundOffOfARowAndRefusesMore) {
  // An entry that is a sum with cancellation, 1e-4 of its row's largest: a relative disagreement of 1e-10
  // of the entry is 1e-14 of the row (passes); one of 1e-4 of the entry is 1e-8 of the row (fails).
  for (const auto& [gap, symmetric] : {std::pair{1e-10, true}, std::pair{1e-4, false}}) {
    Triplets t = stencil_2d(4, 0.0);
    t.emplace_back(0, 10, 4e-4);
    t.emplace_back(10, 0, 4e-4 * (1 + gap));
    EXPECT_EQ(symmetrizing_row_scale(from_triplets(16, 16, t)).has_value(), symmetric) << "gap " << gap;
  }
}

// One RowSymmetrizer per pattern serves every matrix of it: symmetric values get their scale, others none,
// and a matrix of another size is refused by name.
TEST(RowSymmetrizer, ServesEveryMatrixOfItsPattern) {
  const CsrMatrix symmetric = row_scaled(saddle_point(5), mixed_weights(saddle_point(5).rows()));
  const RowSymmetrizer symmetrizer(symmetric);
  EXPECT_TRUE(symmetrizer.scale(symmetric).has_value());
  EXPECT_FALSE(symmetrizer.scale(one_entry_changed(symmetric)).has_value());
  const CsrMatrix doubled = row_scaled(symmetric, Eigen::VectorXd::Constant(symmetric.rows(), 2.0));
  const std::optional<Eigen::VectorXd> s = symmetrizer.scale(doubled);
  ASSERT_TRUE(s.has_value());
  EXPECT_LT(asymmetry(doubled, *s), 1e-14);
  EXPECT_FALSE(symmetrizer.has_pattern(laplacian_2d(3)));
  EXPECT_THROW(symmetrizer.scale(laplacian_2d(3)), Error);
}

}  // namespace
}  // namespace pc

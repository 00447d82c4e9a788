// Static condensation by MUMPS (assembly/schur_complement.hpp) against dense linear algebra: the Schur
// complement S = A_cc - A_ci A_ii^-1 A_ic of a nonsymmetric matrix, reduce + interface solve + expand
// giving A^-1 b, a modified interface system (S + D) giving the solution of A + P^T D P, and a matrix
// that is singular while its interior block is not.
#include "assembly/schur_complement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "assembly/error.hpp"
#include "assembly/sparse.hpp"
#include "support/test_matrices.hpp"

namespace pc {
namespace {

using namespace testing::matrices;

struct Split {
  std::vector<int> interface, interior;
};

// Every 7th unknown, out of order, as the interface.
Split split(int n) {
  Split s;
  for (int i = n - 1; i >= 0; --i) (i % 7 == 3 ? s.interface : s.interior).push_back(i);
  return s;
}

TEST(SchurComplement, MatchesTheDenseSchurComplementOfANonsymmetricMatrix) {
  const CsrMatrix a = convection_diffusion_2d(9);
  const Eigen::MatrixXd dense(a);
  const Split s = split(int(a.rows()));
  SchurComplement schur;
  schur.analyze(a, s.interface);
  schur.factorize(a);
  const Eigen::MatrixXd expected =
      dense(s.interface, s.interface) -
      dense(s.interface, s.interior) *
          Eigen::MatrixXd(dense(s.interior, s.interior)).lu().solve(Eigen::MatrixXd(dense(s.interior, s.interface)));
  EXPECT_LT((schur.schur() - expected).norm(), 1e-12 * expected.norm());
  EXPECT_GT((expected - expected.transpose()).norm(), 0.1 * expected.norm()) << "the test needs a nonsymmetric S";
}

// A symmetric indefinite matrix with rows weighted over twelve decades is condensed by LDL^T on the
// weighted rows: the Schur complement and the solution are those of the matrix as given; values that lose
// the symmetry on the same pattern are condensed by LU after a new analysis.
TEST(SchurComplement, CondensesRowWeightedSymmetricMatricesByLdltAndOthersByLu) {
  const CsrMatrix symmetric = row_scaled(saddle_point(7), mixed_weights(saddle_point(7).rows()));
  const CsrMatrix general = one_entry_changed(symmetric);
  const Split s = split(int(symmetric.rows()));
  SchurComplement schur;
  schur.analyze(symmetric, s.interface);
  for (const CsrMatrix* a : {&symmetric, &general, &symmetric}) {
    schur.factorize(*a);
    EXPECT_EQ(schur.symmetric(), a == &symmetric);
    const Eigen::MatrixXd dense(*a);
    const Eigen::MatrixXd expected =
        dense(s.interface, s.interface) -
        dense(s.interface, s.interior) *
            Eigen::MatrixXd(dense(s.interior, s.interior)).lu().solve(Eigen::MatrixXd(dense(s.interior, s.interface)));
    EXPECT_LT((schur.schur() - expected).norm(), 1e-10 * expected.norm());
    const Eigen::VectorXd b = rhs_for(*a);
    const Eigen::VectorXd x = schur.expand(b, schur.schur().lu().solve(schur.reduce(b)));
    EXPECT_LT((*a * x - b).norm(), 1e-10 * b.norm());
  }
}

TEST(SchurComplement, ReduceSolveExpandSolvesTheWholeSystemAndItsContactModification) {
  const CsrMatrix a = saddle_point(8);  // indefinite, with a zero diagonal block
  const Split s = split(int(a.rows()));
  SchurComplement schur;
  schur.analyze(a, s.interface);
  schur.factorize(a);
  const Eigen::VectorXd b = rhs_for(a);
  const Eigen::VectorXd x = schur.expand(b, schur.schur().lu().solve(schur.reduce(b)));
  EXPECT_LT((a * x - b).norm(), 1e-12 * b.norm());

  // A + P^T D P with a dense D on the interface: the interface system becomes S + D, nothing else changes.
  const int m = int(s.interface.size());
  const Eigen::MatrixXd d = Eigen::MatrixXd::Random(m, m) * 3.0;
  Eigen::MatrixXd modified(a);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) modified(s.interface[i], s.interface[j]) += d(i, j);
  const Eigen::VectorXd y = schur.expand(b, (schur.schur() + d).lu().solve(schur.reduce(b)));
  EXPECT_LT((modified * y - b).norm(), 1e-11 * b.norm());
}

TEST(SchurComplement, SingularMatrixWithARegularInteriorCondenses) {
  // A pure-Neumann-like matrix: the 1D Laplacian with both ends free is singular (constants), but with
  // one unknown on the interface the interior is regular; S is then zero, and S + D is regular.
  Triplets t;
  const int n = 12;
  for (int i = 0; i + 1 < n; ++i) {
    t.emplace_back(i, i, 1.0);
    t.emplace_back(i + 1, i + 1, 1.0);
    t.emplace_back(i, i + 1, -1.0);
    t.emplace_back(i + 1, i, -1.0);
  }
  const CsrMatrix a = from_triplets(n, n, t);
  SchurComplement schur;
  schur.analyze(a, {0});
  schur.factorize(a);
  EXPECT_NEAR(schur.schur()(0, 0), 0.0, 1e-12);
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1, 2);
  const double spring = 5.0;  // ... held at unknown 0 by a spring
  Eigen::VectorXd reduced = schur.reduce(b);
  const Eigen::VectorXd x = schur.expand(b, reduced / (schur.schur()(0, 0) + spring));
  Eigen::MatrixXd held(a);
  held(0, 0) += spring;
  EXPECT_LT((held * x - b).norm(), 1e-12 * b.norm());
}

TEST(SchurComplement, RefactorizesNewValuesAndRejectsMisuse) {
  CsrMatrix a = convection_diffusion_2d(6);
  const Split s = split(int(a.rows()));
  SchurComplement schur;
  EXPECT_THROW(schur.factorize(a), Error);
  EXPECT_THROW(schur.analyze(a, {0, 0}), Error);
  EXPECT_THROW(schur.analyze(a, {int(a.rows())}), Error);
  schur.analyze(a, s.interface);
  EXPECT_TRUE(schur.is_analyzed_for(a, s.interface));
  EXPECT_FALSE(schur.is_analyzed_for(a, {0}));
  schur.factorize(a);
  const Eigen::MatrixXd first = schur.schur();
  a *= 2.0;
  schur.factorize(a);
  EXPECT_LT((schur.schur() - 2.0 * first).norm(), 1e-12 * first.norm());
  EXPECT_THROW(schur.reduce(Eigen::VectorXd::Ones(3)), Error);
  EXPECT_THROW(schur.expand(rhs_for(a), Eigen::VectorXd::Ones(1)), Error);
}

// The condensation keeps no copy of the matrix: it reads the values while it factorises and solves with
// the factors alone, so the caller may change or free its matrix afterwards; another pattern is told apart.
TEST(SchurComplement, SolvesWithTheFactorsAloneAfterTheMatrixIsGone) {
  const CsrMatrix a = saddle_point(8);
  const Split s = split(int(a.rows()));
  const Eigen::VectorXd b = rhs_for(a);
  SchurComplement schur;
  {
    CsrMatrix copy = a;
    schur.analyze(copy, s.interface);
    schur.factorize(copy);
    std::fill_n(copy.valuePtr(), copy.nonZeros(), std::nan(""));  // what MUMPS must not read any more
  }
  const Eigen::VectorXd x = schur.expand(b, schur.schur().lu().solve(schur.reduce(b)));
  EXPECT_LT((a * x - b).norm(), 1e-12 * b.norm());
  EXPECT_TRUE(schur.is_analyzed_for(a, s.interface));
  CsrMatrix other = a;
  other.coeffRef(0, int(a.cols()) - 1) += 1.0;  // a new entry: another pattern
  other.makeCompressed();
  EXPECT_FALSE(schur.is_analyzed_for(other, s.interface));
  EXPECT_THROW(schur.factorize(other), Error);
  // The handle keeps a fingerprint of the pattern, not its coordinates: a pattern with as many entries,
  // one mirrored pair moved to another column, is told apart too.
  const int row = int(a.rows()) - 1;
  int from = -1, to = -1;
  for (int col = 0; col < row; ++col) {
    const bool present = find_slot(a, row, col) >= 0;
    if (present && from < 0) from = col;
    if (!present && to < 0) to = col;
  }
  ASSERT_GE(from, 0);
  ASSERT_GE(to, 0);
  Eigen::SparseMatrix<double, Eigen::RowMajor> moved_entries(a.rows(), a.cols());
  std::vector<Eigen::Triplet<double>> entries;
  for (int r = 0; r < a.rows(); ++r)
    for (CsrMatrix::InnerIterator e(a, r); e; ++e) {
      int i = r, j = int(e.col());
      if (i == row && j == from) j = to;
      if (j == row && i == from) i = to;
      entries.emplace_back(i, j, e.value());
    }
  moved_entries.setFromTriplets(entries.begin(), entries.end());
  ASSERT_EQ(moved_entries.nonZeros(), a.nonZeros());
  EXPECT_FALSE(schur.is_analyzed_for(moved_entries, s.interface));
  EXPECT_THROW(schur.factorize(moved_entries), Error);
  // The same pattern again: the coordinates are made anew from it, and the factors are right.
  schur.factorize(a);
  const Eigen::VectorXd y = schur.expand(b, schur.schur().lu().solve(schur.reduce(b)));
  EXPECT_LT((a * y - b).norm(), 1e-12 * b.norm());
}

}  // namespace
}  // namespace pc

// The sparse direct solvers on matrices built here: an SPD Laplacian, a nonsymmetric
// convection-diffusion operator and an indefinite saddle-point matrix.
#include "assembly/linear_solver.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "assembly/error.hpp"
#include "assembly/sparse.hpp"
#include "support/test_helpers.hpp"
#include "support/test_matrices.hpp"

namespace pc {
namespace {

using namespace testing::matrices;

double relative_residual(const CsrMatrix& matrix, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  return (matrix * x - b).norm() / b.norm();
}

using testing::error_of;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::vector<std::string> lu_solvers() { return {"eigen-lu", "umfpack", "mumps"}; }

class EverySolver : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<LinearSolver> solver = make_linear_solver(GetParam());
};

INSTANTIATE_TEST_SUITE_P(Solvers, EverySolver, ::testing::ValuesIn(linear_solver_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

TEST_P(EverySolver, SolvesTheSpdLaplacian) {
  const CsrMatrix matrix = laplacian_2d(20);
  const Eigen::VectorXd b = rhs_for(matrix);
  EXPECT_EQ(solver->name(), GetParam());
  EXPECT_LT(relative_residual(matrix, solver->solve_once(matrix, b), b), 1e-12);
}

TEST_P(EverySolver, RefactorizesNewValuesOnTheAnalyzedPattern) {
  CsrMatrix matrix = laplacian_2d(12);
  const Eigen::VectorXd b = rhs_for(matrix);
  solver->analyze(matrix);
  solver->factorize(matrix);
  const Eigen::VectorXd first = solver->solve(b);
  EXPECT_LT(relative_residual(matrix, first, b), 1e-12);

  // Same pattern, new values (still SPD): a stiffer diagonal, growing with the row.
  for (int row = 0; row < matrix.rows(); ++row)
    for (CsrMatrix::InnerIterator entry(matrix, row); entry; ++entry)
      entry.valueRef() *= entry.col() == row ? 2.0 + 0.01 * row : 1.0;
  ASSERT_TRUE(solver->is_analyzed_for(matrix));
  solver->factorize(matrix);
  const Eigen::VectorXd second = solver->solve(b);
  EXPECT_LT(relative_residual(matrix, second, b), 1e-12);
  EXPECT_GT((second - first).norm(), 0.1 * first.norm());
}

TEST_P(EverySolver, KeepsItsOwnCopyOfTheFactorizedMatrix) {
  CsrMatrix matrix = laplacian_2d(8);
  const CsrMatrix original = matrix;
  const Eigen::VectorXd b = rhs_for(matrix);
  solver->analyze(matrix);
  solver->factorize(matrix);
  matrix.coeffs().setConstant(std::numeric_limits<double>::quiet_NaN());  // the caller reassembles
  EXPECT_LT(relative_residual(original, solver->solve(b), b), 1e-12);
}

TEST_P(EverySolver, SolveOnceReusesTheAnalysisOfTheSamePattern) {
  const CsrMatrix matrix = laplacian_2d(6);
  EXPECT_FALSE(solver->is_analyzed_for(matrix));
  const Eigen::VectorXd b = rhs_for(matrix);
  EXPECT_LT(relative_residual(matrix, solver->solve_once(matrix, b), b), 1e-12);
  EXPECT_TRUE(solver->is_analyzed_for(matrix));
  EXPECT_FALSE(solver->is_analyzed_for(laplacian_2d(5)));
  const CsrMatrix other = laplacian_2d(7);
  const Eigen::VectorXd other_b = rhs_for(other);
  EXPECT_LT(relative_residual(other, solver->solve_once(other, other_b), other_b), 1e-12);
}

TEST_P(EverySolver, ThrowsOnAZeroRowAndColumnThenRecovers) {
  const CsrMatrix regular = laplacian_2d(6);
  CsrMatrix singular = regular;
  const int zero = 14;
  for (int row = 0; row < singular.rows(); ++row)
    for (CsrMatrix::InnerIterator entry(singular, row); entry; ++entry)
      if (row == zero || entry.col() == zero) entry.valueRef() = 0.0;
  solver->analyze(singular);
  const std::string message = error_of([&] { solver->factorize(singular); });
  EXPECT_TRUE(contains(message, GetParam() + ": the ")) << message;
  // A failed factorization leaves nothing to solve with, but the analysis stays usable (a Newton loop
  // may meet a singular tangent and go on with a damped one).
  const Eigen::VectorXd b = rhs_for(regular);
  EXPECT_TRUE(contains(error_of([&] { solver->solve(b); }), "needs a successful factorize()"));
  solver->factorize(regular);
  EXPECT_LT(relative_residual(regular, solver->solve(b), b), 1e-12);
}

TEST_P(EverySolver, ThrowsOnThePureNeumannLaplacianWithAnUnbalancedLoad) {
  // Row sums zero: the constants span the kernel, and a uniform load has no solution (a floating body
  // pushed one way). Only round-off separates the last pivot from zero, so the error comes from the
  // factorization or from the residual check of solve().
  Triplets triplets;
  const int m = 6;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const int node = i * m + j;
      const auto couple = [&](int other) {
        triplets.emplace_back(node, other, -1.0);
        triplets.emplace_back(node, node, 1.0);
      };
      if (j > 0) couple(node - 1);
      if (j + 1 < m) couple(node + 1);
      if (i > 0) couple(node - m);
      if (i + 1 < m) couple(node + m);
    }
  const CsrMatrix matrix = from_triplets(m * m, m * m, triplets);
  const std::string message = error_of([&] { solver->solve_once(matrix, Eigen::VectorXd::Ones(m * m)); });
  EXPECT_TRUE(contains(message, GetParam() + ": the ")) << message;
}

TEST_P(EverySolver, RejectsMisuseWithClearMessages) {
  const CsrMatrix matrix = laplacian_2d(4);
  const Eigen::VectorXd b = rhs_for(matrix);
  EXPECT_TRUE(contains(error_of([&] { solver->factorize(matrix); }), "factorize() needs a successful analyze()"));
  EXPECT_TRUE(contains(error_of([&] { solver->solve(b); }), "solve() needs a successful factorize()"));

  const CsrMatrix rectangular = from_triplets(3, 4, {{0, 0, 1.0}, {1, 1, 1.0}, {2, 2, 1.0}});
  EXPECT_TRUE(contains(error_of([&] { solver->analyze(rectangular); }), "3 x 4, not square"));

  solver->analyze(matrix);
  const std::string size_message = error_of([&] { solver->factorize(laplacian_2d(5)); });
  EXPECT_TRUE(contains(size_message, "25 x 25") && contains(size_message, "16 x 16")) << size_message;

  CsrMatrix more_entries = matrix;
  more_entries.coeffRef(0, 15) = 1.0;
  more_entries.makeCompressed();
  const std::string nnz_message = error_of([&] { solver->factorize(more_entries); });
  EXPECT_TRUE(contains(nnz_message, std::to_string(more_entries.nonZeros())) &&
              contains(nnz_message, std::to_string(matrix.nonZeros())))
      << nnz_message;

  // Same size and entry count, one entry moved from (0, 1) to (0, 2).
  Triplets moved;
  for (int row = 0; row < matrix.rows(); ++row)
    for (CsrMatrix::InnerIterator entry(matrix, row); entry; ++entry)
      moved.emplace_back(row, row == 0 && entry.col() == 1 ? 2 : entry.col(), entry.value());
  EXPECT_TRUE(contains(error_of([&] { solver->factorize(from_triplets(16, 16, moved)); }), "another pattern"));

  CsrMatrix with_nan = matrix;
  with_nan.coeffRef(5, 6) = std::numeric_limits<double>::quiet_NaN();
  const std::string nan_message = error_of([&] { solver->factorize(with_nan); });
  EXPECT_TRUE(contains(nan_message, "matrix contains NaN/Inf at row 5 (column 6)")) << nan_message;

  solver->factorize(matrix);
  Eigen::VectorXd with_inf = b;
  with_inf[7] = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(contains(error_of([&] { solver->solve(with_inf); }), "right-hand side contains NaN/Inf at row 7"));
  const std::string rhs_size_message = error_of([&] { solver->solve(Eigen::VectorXd::Ones(3)); });
  EXPECT_TRUE(contains(rhs_size_message, "3 rows") && contains(rhs_size_message, "16")) << rhs_size_message;
  EXPECT_LT(relative_residual(matrix, solver->solve(b), b), 1e-12);  // still usable after the errors
}

TEST(LinearSolvers, LuSolversSolveNonsymmetricAndIndefiniteSystemsAndAgree) {
  for (const CsrMatrix& matrix : {laplacian_2d(20), convection_diffusion_2d(20), saddle_point(20)}) {
    const Eigen::VectorXd b = rhs_for(matrix);
    const Eigen::VectorXd reference = make_linear_solver("eigen-lu")->solve_once(matrix, b);
    for (const std::string& name : lu_solvers()) {
      const Eigen::VectorXd x = make_linear_solver(name)->solve_once(matrix, b);
      EXPECT_LT(relative_residual(matrix, x, b), 1e-12) << name << ", " << matrix.rows() << " rows";
      EXPECT_LT((x - reference).norm(), 1e-10 * reference.norm()) << name << ", " << matrix.rows() << " rows";
    }
  }
}

// MUMPS factorises a matrix that a row scaling makes symmetric as LDL^T, any other as LU, deciding on each
// factorisation's values: both routes give the reference solution, the symmetric one with about half the
// stored entries (its estimate counts L twice, as a solve reads it), and values that lose their symmetry
// on the same pattern switch it back to LU.
TEST(LinearSolvers, MumpsFactorisesRowWeightedSymmetricMatricesAsLdlt) {
  const CsrMatrix symmetric = row_scaled(saddle_point(20), mixed_weights(saddle_point(20).rows()));
  const CsrMatrix general = one_entry_changed(symmetric);
  const Eigen::VectorXd b = rhs_for(symmetric);
  const auto mumps = make_linear_solver("mumps");
  double stored[2] = {0, 0};
  for (const CsrMatrix* matrix : {&symmetric, &general}) {
    const bool is_symmetric = matrix == &symmetric;
    mumps->analyze(*matrix);
    mumps->factorize(*matrix);
    const Eigen::VectorXd x = mumps->solve(rhs_for(*matrix));
    const Eigen::VectorXd reference = make_linear_solver("eigen-lu")->solve_once(*matrix, rhs_for(*matrix));
    EXPECT_LT((x - reference).norm(), 1e-10 * reference.norm()) << (is_symmetric ? "LDL^T" : "LU");
    EXPECT_EQ(mumps->factor_estimate().symmetric, is_symmetric);
    stored[is_symmetric] = mumps->factor_estimate().entries / (is_symmetric ? 2 : 1);
  }
  EXPECT_LT(stored[1], 0.7 * stored[0]) << "LDL^T stores " << stored[1] << " entries, LU " << stored[0];
  // The same pattern refactorised: symmetric values, then nonsymmetric ones, each solved right.
  const auto refactorised = make_linear_solver("mumps");
  refactorised->analyze(symmetric);
  for (const CsrMatrix* matrix : {&symmetric, &general, &symmetric}) {
    refactorised->factorize(*matrix);
    EXPECT_LT(relative_residual(*matrix, refactorised->solve(b), b), 1e-12);
    EXPECT_EQ(refactorised->factor_estimate().symmetric, matrix == &symmetric);
  }
}

TEST(LinearSolvers, CholmodAgreesWithTheLuSolversOnTheSpdLaplacian) {
  const CsrMatrix matrix = laplacian_2d(30);
  const Eigen::VectorXd b = rhs_for(matrix);
  const Eigen::VectorXd x = make_linear_solver("cholmod")->solve_once(matrix, b);
  for (const std::string& name : lu_solvers())
    EXPECT_LT((x - make_linear_solver(name)->solve_once(matrix, b)).norm(), 1e-10 * x.norm()) << name;
}

TEST(LinearSolvers, CholmodRejectsIndefiniteAndUnsymmetricMatrices) {
  const CsrMatrix saddle = saddle_point(5);
  const std::string indefinite = error_of([&] { make_linear_solver("cholmod")->solve_once(saddle, rhs_for(saddle)); });
  EXPECT_TRUE(contains(indefinite, "cholmod: the matrix is not positive definite")) << indefinite;

  const CsrMatrix convection = convection_diffusion_2d(5);
  const std::string unsymmetric =
      error_of([&] { make_linear_solver("cholmod")->solve_once(convection, rhs_for(convection)); });
  EXPECT_TRUE(contains(unsymmetric, "cholmod: the matrix is not symmetric: A(0, 1) = -0.6 but A(1, 0) = -1.4"))
      << unsymmetric;
}

TEST(LinearSolvers, UnknownNameListsTheKnownOnes) {
  const std::string message = error_of([] { make_linear_solver("superlu"); });
  EXPECT_TRUE(contains(message, "unknown linear solver 'superlu'")) << message;
  for (const char* name : {"eigen-lu", "umfpack", "mumps", "cholmod"}) EXPECT_TRUE(contains(message, name)) << message;
  EXPECT_EQ(make_linear_solver()->name(), "umfpack");
}

TEST(FindSlot, FindsStoredEntriesOnly) {
  const CsrMatrix matrix = laplacian_2d(3);  // row 4 (the centre) holds columns 1, 3, 4, 5, 7
  const int slot = find_slot(matrix, 4, 5);
  ASSERT_GE(slot, 0);
  EXPECT_EQ(matrix.innerIndexPtr()[slot], 5);
  EXPECT_EQ(slot, matrix.outerIndexPtr()[4] + 3);
  EXPECT_EQ(find_slot(matrix, 4, 0), -1);
  EXPECT_EQ(find_slot(matrix, 0, 8), -1);
  EXPECT_EQ(find_slot(matrix, 9, 0), -1);
  EXPECT_EQ(find_slot(matrix, 8, 8), matrix.nonZeros() - 1);
}

}  // namespace
}  // namespace pc

// The products of one column that MUMPS's solves make (assembly/blas_vector_forwarding.hpp): dgemm with
// N = 1 and dtrsm with one column give what their definitions say, by every transposition and triangle,
// and they are the process's routines, through which a MUMPS solve goes.
#include "assembly/blas_vector_forwarding.hpp"

#include <gtest/gtest.h>

#include <cstddef>

#include <Eigen/Dense>

#include "assembly/linear_solver.hpp"
#include "support/test_matrices.hpp"

extern "C" {
void dgemm_(const char*, const char*, const int*, const int*, const int*, const double*, const double*, const int*,
            const double*, const int*, const double*, double*, const int*, std::size_t, std::size_t);
void dtrsm_(const char*, const char*, const char*, const char*, const int*, const int*, const double*, const double*,
            const int*, double*, const int*, std::size_t, std::size_t, std::size_t, std::size_t);
}

namespace pc {
namespace {

TEST(BlasVectorForwarding, OneColumnProductsAreTheDefinitionsProducts) {
  const int m = 37, k = 23, lda = 41, ldb = 5;
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(lda, 41);  // leading dimension larger than the rows used
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(ldb, 41);  // a row of it is op(B) when B is transposed
  const double alpha = 0.7, beta = -1.3;
  for (const char* transa : {"N", "T", "n", "t"})
    for (const char* transb : {"N", "T"}) {
      const bool a_transposed = *transa == 'T' || *transa == 't';
      const Eigen::MatrixXd op_a =
          a_transposed ? Eigen::MatrixXd(a.topLeftCorner(k, m).transpose()) : Eigen::MatrixXd(a.topLeftCorner(m, k));
      const Eigen::VectorXd x =
          *transb == 'N' ? Eigen::VectorXd(b.reshaped().head(k)) : Eigen::VectorXd(b.row(0).head(k).transpose());
      const Eigen::VectorXd c0 = Eigen::VectorXd::Random(m);
      Eigen::VectorXd c = c0;
      const int one = 1;
      const int b_ld = *transb == 'N' ? k : ldb;
      dgemm_(transa, transb, &m, &one, &k, &alpha, a.data(), &lda, b.data(), &b_ld, &beta, c.data(), &m, 1, 1);
      const Eigen::VectorXd expected = alpha * op_a * x + beta * c0;
      EXPECT_LT((c - expected).norm(), 1e-13 * expected.norm()) << transa << transb;
    }
  // beta = 0: C is not read (it may hold NaN), as the BLAS promises.
  Eigen::VectorXd c = Eigen::VectorXd::Constant(m, std::nan(""));
  const double zero = 0;
  const int one = 1;
  dgemm_("N", "N", &m, &one, &k, &alpha, a.data(), &lda, b.data(), &k, &zero, c.data(), &m, 1, 1);
  EXPECT_TRUE(c.allFinite());
}

TEST(BlasVectorForwarding, OneColumnTriangularSolvesAreTheDefinitionsSolves) {
  const int m = 29, lda = 33;
  Eigen::MatrixXd a = Eigen::MatrixXd::Random(lda, m);
  a.diagonal().array() += 4;  // well conditioned
  for (const char* uplo : {"L", "U"})
    for (const char* trans : {"N", "T"})
      for (const char* diag : {"N", "U"}) {
        Eigen::MatrixXd t = a.topRows(m);
        t = *uplo == 'L' ? Eigen::MatrixXd(t.triangularView<Eigen::Lower>())
                         : Eigen::MatrixXd(t.triangularView<Eigen::Upper>());
        if (*diag == 'U') t.diagonal().setOnes();  // the stored diagonal is not read
        const Eigen::MatrixXd op = *trans == 'N' ? t : Eigen::MatrixXd(t.transpose());
        const Eigen::VectorXd rhs = Eigen::VectorXd::Random(m);
        Eigen::VectorXd x = rhs;
        const int one = 1;
        const double unit = 1;
        dtrsm_("L", uplo, trans, diag, &m, &one, &unit, a.data(), &lda, x.data(), &m, 1, 1, 1, 1);
        EXPECT_LT((op * x - rhs).norm(), 1e-13 * rhs.norm()) << uplo << trans << diag;
      }
}

// The process's dgemm_ and dtrsm_ are the forwarding ones, and a MUMPS solve of a 2D problem (whose fronts
// are dense blocks) calls them with one column.
TEST(BlasVectorForwarding, MumpsSolvesGoThroughIt) {
  ASSERT_TRUE(blas_vector_forwarding_active()) << "a BLAS was bound before the library: MUMPS calls it directly";
  const CsrMatrix a = testing::matrices::convection_diffusion_2d(60);
  auto solver = make_linear_solver("mumps");
  solver->analyze(a);
  solver->factorize(a);
  const long before = blas_vector_forwarded_calls();
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(a.rows());
  const Eigen::VectorXd x = solver->solve(b);
  EXPECT_GT(blas_vector_forwarded_calls(), before);
  EXPECT_LT((a * x - b).norm(), 1e-10 * b.norm());
}

}  // namespace
}  // namespace pc

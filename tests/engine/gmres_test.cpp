// Restarted, right-preconditioned GMRES (assembly/gmres.hpp) against closed-form facts: in exact
// arithmetic it ends after at most as many iterations as the operator has distinct eigenvalues (the
// identity plus a rank-r update: r + 1), an exact preconditioner makes it one iteration, and restarting
// still reaches the direct solution of a nonsymmetric system.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "assembly/error.hpp"
#include "assembly/gmres.hpp"

namespace pc {
namespace {

LinearOperator product_with(const Eigen::MatrixXd& a) {
  return [a](const Eigen::VectorXd& x) -> Eigen::VectorXd { return a * x; };
}
const LinearOperator kIdentity = [](const Eigen::VectorXd& x) { return x; };

TEST(Gmres, IdentityPlusRankRConvergesInAtMostRPlusOneIterations) {
  const int n = 60;
  for (const int rank : {1, 3, 7}) {
    const Eigen::MatrixXd u = Eigen::MatrixXd::Random(n, rank), w = Eigen::MatrixXd::Random(n, rank);
    const Eigen::MatrixXd a = Eigen::MatrixXd::Identity(n, n) + 0.3 * u * w.transpose();  // nonsymmetric
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    const GmresResult r = gmres(product_with(a), kIdentity, b);
    ASSERT_TRUE(r.converged) << rank;
    EXPECT_LE(r.iterations, rank + 1) << rank;
    EXPECT_GE(r.iterations, rank) << rank << ": fewer iterations than the update's rank cannot span it";
    EXPECT_LT((a * r.x - b).norm(), 1e-12 * b.norm()) << rank;
  }
}

TEST(Gmres, AnExactPreconditionerTakesOneIteration) {
  const int n = 40;
  // Convection-diffusion: nonsymmetric, tridiagonal.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    a(i, i) = 2;
    if (i > 0) a(i, i - 1) = -1.4;
    if (i + 1 < n) a(i, i + 1) = -0.6;
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(a);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1, 2);
  const GmresResult r = gmres(
      product_with(a), [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return lu.solve(v); }, b);
  ASSERT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_LT((r.x - lu.solve(b)).norm(), 1e-12 * lu.solve(b).norm());
}

TEST(Gmres, RestartedGmresReachesTheDirectSolutionOfANonsymmetricSystem) {
  const int n = 80;
  Eigen::MatrixXd a = Eigen::MatrixXd::Random(n, n) / std::sqrt(double(n));
  a.diagonal().array() += 3;  // eigenvalues in a disc around 3 of radius about 1: GMRES(5) converges
  const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
  const Eigen::VectorXd direct = a.partialPivLu().solve(b);
  GmresOptions options;
  options.restart = 5;
  options.max_iterations = 400;
  const GmresResult restarted = gmres(product_with(a), kIdentity, b, options);
  ASSERT_TRUE(restarted.converged);
  EXPECT_GT(restarted.iterations, options.restart) << "the test must restart at least once";
  EXPECT_LT((restarted.x - direct).norm(), 1e-10 * direct.norm());
  EXPECT_LT(restarted.relative_residual, 1e-12);
  // Unrestarted, never more iterations than restarted.
  options.restart = 400;
  const GmresResult full = gmres(product_with(a), kIdentity, b, options);
  ASSERT_TRUE(full.converged);
  EXPECT_LE(full.iterations, restarted.iterations);
}

TEST(Gmres, StopsAtTheIterationCapAndSaysItDidNotConverge) {
  const int n = 50;
  const Eigen::MatrixXd a = Eigen::VectorXd::LinSpaced(n, 1, 1000).asDiagonal();  // 50 distinct eigenvalues
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  GmresOptions options;
  options.max_iterations = 5;
  const GmresResult r = gmres(product_with(a), kIdentity, b, options);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 5);
  EXPECT_GT(r.relative_residual, 1e-6);
  EXPECT_LT(r.relative_residual, 1) << "GMRES minimises the residual: it cannot grow";
}

TEST(Gmres, AZeroRightHandSideAndBadOptions) {
  const Eigen::MatrixXd a = Eigen::MatrixXd::Identity(3, 3);
  const GmresResult r = gmres(product_with(a), kIdentity, Eigen::VectorXd::Zero(3));
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(r.x, Eigen::VectorXd::Zero(3));
  GmresOptions bad;
  bad.restart = 0;
  EXPECT_THROW(gmres(product_with(a), kIdentity, Eigen::VectorXd::Ones(3), bad), Error);
}

}  // namespace
}  // namespace pc

#pragma once
// Restarted GMRES with right preconditioning (Saad, Iterative Methods for Sparse Linear Systems, 9.3.2):
// solves A x = b from x = 0 for an operator A and a preconditioner M ~ A given as functions, so that a
// sparse matrix, a matrix-free operator or a factorisation of another matrix all fit. Right
// preconditioning minimises the true residual ||b - A x||, which is what the caller's tolerance is on.
// Modified Gram-Schmidt with one reorthogonalisation when it loses accuracy, Givens rotations for the
// least-squares problem.
#include <functional>

#include <Eigen/Core>

namespace pc {

using LinearOperator = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

struct GmresOptions {
  double relative_tolerance = 1e-12;  // stop at ||b - A x|| <= relative_tolerance ||b||
  int max_iterations = 100;           // applications of the preconditioner, over all restarts
  int restart = 50;                   // Krylov basis size between restarts
};

struct GmresResult {
  Eigen::VectorXd x;
  int iterations = 0;            // preconditioner applications (and products with A, plus one per restart)
  double relative_residual = 0;  // ||b - A x|| / ||b||, recomputed from x at the end
  bool converged = false;
};

GmresResult gmres(const LinearOperator& apply_a, const LinearOperator& apply_preconditioner_inverse,
                  const Eigen::VectorXd& b, const GmresOptions& options = {});

}  // namespace pc

#pragma once
// The Newton step by GMRES on the full Jacobian J, preconditioned by the factorisation of an earlier J of
// the same problem (a lagged Jacobian: PETSc's -snes_lag_preconditioner, with the lag chosen by cost).
// From iteration to iteration and step to step only the contact rows of J change, and only where a node's
// state or its law's slope changes: J_ref^-1 J is then the identity plus a correction of low rank, and
// GMRES converges in a few iterations of one solve with the kept factors each. The factorisation is renewed
//   - when the problem or its linear part A changed (a new step size),
//   - when the last solve's iterations cost more than a factorisation (the lag no longer pays),
//   - and at once, with a direct solve, when GMRES does not converge within half a factorisation's worth
//     of iterations; the next 1, 3, 7, ... steps (after 1, 2, 3, ... such failures, each success taking one
//     back) are then direct too: where the contact state changes at every iteration the path is a
//     factorisation per iteration, plus a small share of lost GMRES work.
// Unlike the dense condensations (models/solvers/condensed_solve.hpp) nothing grows with the number of
// contact dofs m: memory is the factors and the Krylov basis, the work per iteration a few solves, so it is
// the path for contact sets of thousands to millions of dofs.
#include <cstdint>
#include <memory>
#include <string>

#include <Eigen/Core>

#include "assembly/gmres.hpp"
#include "assembly/linear_solver.hpp"
#include "models/solvers/linear_solve_cost.hpp"
#include "models/solvers/nonlinear_problem.hpp"

namespace pc {

struct KrylovStep {
  Eigen::VectorXd dx;
  LinearSolveCost cost;
  int iterations = 0;  // GMRES iterations (0: a direct solve with a new factorisation)
};

class KrylovSolve {
 public:
  // relative_tolerance: of GMRES on ||J dx - b|| / ||b||, far below Newton's, so that the Newton iterates
  // are those of exact steps to within round-off of the residual test.
  explicit KrylovSolve(std::string linear_solver, double relative_tolerance = 1e-12);
  // dx with J dx = b for the problem's current (assembled) Jacobian. A singular J throws pc::Error from the
  // linear solver, as a full step would.
  KrylovStep step(NonlinearProblem& problem, const Eigen::VectorXd& b);
  // The symbolic analysis of J's pattern (done once per pattern; step() would do it too), and what it
  // predicts of the factors: the cost model's input.
  FactorEstimate analyze(const CsrMatrix& J);
  // Frees the factorisation, the analysis and the solver's copy of J (when another strategy was chosen
  // after analyze() gave its estimate); step() makes them again.
  void release();

 private:
  Eigen::VectorXd direct_step(const CsrMatrix& J, const Eigen::VectorXd& b, LinearSolveCost& cost);

  std::string linear_solver_name_;
  double relative_tolerance_;
  std::unique_ptr<LinearSolver> factors_;  // of J_ref
  const NonlinearProblem* problem_ = nullptr;
  std::uint64_t version_ = 0;  // of the linear part when J_ref was factorised
  bool renew_ = true;
  double factorize_seconds_ = 0;  // the last factorisation's time
  double iteration_seconds_ = 0;  // the last GMRES iteration's (a solve and a product with J)
  int backoff_exponent_ = 0;      // +1 per failure of GMRES, -1 per success
  int direct_steps_left_ = 0;     // before GMRES is tried again
};

}  // namespace pc

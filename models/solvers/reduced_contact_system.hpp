#pragma once
// Newton on the contact dofs alone: nonlinear static condensation of a problem whose interior is linear.
//
// Outside its nonlinear dofs c (the contact boundary's) the residual is linear, R_i(x) = (A x)_i + const,
// and N(x), the nonlinear terms on the rows c, reads only x_c. With the interior solved exactly for the
// contact values, the whole residual is zero on the interior and, on c,
//   rho(x_c) = rho_0 + S_c (x_c - x_c0) + N(x_c) - N(x_c0),   rho_0 = R_c(x0) - A_ci A_ii^-1 R_i(x0),
// where S_c = A_cc - A_ci A_ii^-1 A_ic is the Schur complement the condensed solve keeps. Newton on rho with
// the tangent S_c + D (D = dN/dx_c) takes the very iterates of Newton on the whole system from x0 while it
// takes full steps (its first step lands on the interior's solution, and every step after keeps it there),
// and each block's norm of rho is that of the whole residual. A backtracking line search differs: on the
// contact dofs it weighs rho, the residual with the interior solved, not the whole residual partway to it.
// So the iterations in between need no sparse solve and no residual of
// the whole system: a solve is one forward substitution (reduce) at the start and one backward
// substitution (expand) at the end, and an iteration is the contact bricks' element loops and dense work
// on the contact dofs. The whole residual is assembled again at the end, to verify.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "models/solvers/condensed_solve.hpp"
#include "models/solvers/linear_solve_cost.hpp"
#include "models/solvers/nonlinear_problem.hpp"

namespace pc {

class ReducedContactSystem {
 public:
  // Reduces the problem at its current free values x0, whose residual (with tangent) is assembled: the
  // forward substitution of -R(x0) through `condensed`. Null when that does not apply: not the Schur
  // method, no nonlinear dofs, an interior that cannot be factorised, or a problem that cannot assemble its
  // nonlinear rows alone (NonlinearProblem::assemble_nonlinear_rows).
  static std::unique_ptr<ReducedContactSystem> reduce(NonlinearProblem& problem, CondensedSolve& condensed,
                                                      LinearSolveCost& cost);

  // The problem's blocks restricted to the contact dofs (a block without any has size 0).
  const std::vector<ProblemBlock>& blocks() const { return blocks_; }
  // rho at the current contact values (the problem's nonlinear rows assembled there, with their tangent).
  void assemble();
  const Eigen::VectorXd& residual() const { return rho_; }
  // The contact values x_c, and their update; the problem's contact dofs follow, its interior dofs stay
  // at x0 until expand().
  Eigen::VectorXd free_values() const;
  void set_free_values(const Eigen::VectorXd& x_c);
  void add_to_free_values(const Eigen::VectorXd& step);
  // (S_c + D) dx_c = rhs, D at the last assemble().
  Eigen::VectorXd step(const Eigen::VectorXd& rhs, LinearSolveCost& cost);
  // Sets the problem's free values to the whole solution at the current contact values, the interior
  // solved: the backward substitution. The problem must then be assembled again.
  void expand(LinearSolveCost& cost);

 private:
  ReducedContactSystem(NonlinearProblem& problem, CondensedSolve& condensed);
  void move_contact_values(const Eigen::VectorXd& new_shift);

  NonlinearProblem& problem_;
  CondensedSolve& condensed_;
  std::vector<int> contact_;  // the nonlinear dofs, sorted
  std::vector<ProblemBlock> blocks_;
  Eigen::VectorXd x0_;          // the whole free values at the reduction
  Eigen::VectorXd b_;           // -R(x0), the reduced and expanded right-hand side
  Eigen::VectorXd rho0_;        // rho at x0's contact values
  Eigen::VectorXd nonlinear0_;  // N at x0
  Eigen::VectorXd shift_;       // x_c - x_c0
  Eigen::VectorXd nonlinear_;   // N at the current contact values
  Eigen::VectorXd rho_;
};

}  // namespace pc

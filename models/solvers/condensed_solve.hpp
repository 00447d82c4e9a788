#pragma once
// The Newton step through a small system on the contact dofs. Inside a time step only the nonlinear bricks
// change, and they fill the rows and columns of a few dofs (the contact boundary's,
// NonlinearProblem::nonlinear_dofs):
//   J = A + P^T D P,   A the linear part (NonlinearProblem::linear_jacobian), D the nonlinear part on those m dofs.
// A is factorised once per change of its values (once per step size), and each iteration solves J dx = b
// through that factorisation and a dense system on the active dofs (those where D is non-zero). Two methods:
//   Schur    MUMPS factorises A with the m dofs eliminated last and returns the Schur complement S_c of the
//            interior (assembly/schur_complement.hpp); S_c^-1 is formed once. An iteration is a reduction
//            (forward substitution), the Woodbury formula on S_c + D with S_c^-1 (a dense solve on the
//            active dofs) and an expansion (backward substitution): one solve's worth of sparse work.
//            Only the interior must be regular (A may be singular: a body held by its contact only).
//   Columns  any linear solver: the columns of S = P A^-1 P^T by one solve per active dof (cached per
//            factorisation), then the Woodbury formula: two solves per iteration. A must be regular.
// A linear strategy of Newton: it says whether it applies to a problem, and returns each step with its cost;
// a step whose factorisation (or solve) with A fails comes back empty, and the problem is then solved in
// full and not condensed again.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SparseCore>

#include "assembly/linear_solver.hpp"
#include "assembly/schur_complement.hpp"
#include "models/solvers/linear_solve_cost.hpp"
#include "models/solvers/linear_strategy.hpp"
#include "models/solvers/nonlinear_problem.hpp"

namespace pc {

struct CondensedStep {
  std::optional<Eigen::VectorXd> dx;  // empty: A (for Schur, its interior) could not be factorised
  LinearSolveCost cost;
};

class CondensedSolve {
 public:
  // Applies to problems whose nonlinear dofs are at most max_fraction of all (0: to none) and at most
  // max_dofs in number: the dense work on them grows as their cube, so past a few thousand a full
  // factorisation per iteration is the cheaper path.
  // method: LinearStrategy::Schur or Columns.
  CondensedSolve(LinearStrategy method, std::string linear_solver, double max_fraction, int max_dofs);
  // Whether the problem's nonlinear dofs are few enough and its linear part has not failed to condense.
  bool applies(NonlinearProblem& problem) const;
  // The same without the cap on their number (the cost model of "auto" weighs that).
  bool applies_in_proportion(NonlinearProblem& problem) const;
  // The step dx with J dx = b for the problem's current (assembled) Jacobian.
  CondensedStep step(NonlinearProblem& problem, const Eigen::VectorXd& b);
  LinearStrategy method() const { return method_; }

  // The Schur step in its three parts, for Newton on the interface alone (reduced_contact_system.hpp),
  // which reduces once, solves on the interface at every iteration and expands once.
  // reduce: r = b_c - A_ci A_ii^-1 b_i, factorising A first where needed; empty when this is not the Schur
  // method, the problem has no nonlinear dofs, or its interior cannot be factorised (as step()).
  std::optional<Eigen::VectorXd> reduce(NonlinearProblem& problem, const Eigen::VectorXd& b, LinearSolveCost& cost);
  // (S_c + D) x_c = r, with D the problem's nonlinear part at its last assembly.
  Eigen::VectorXd solve_interface(NonlinearProblem& problem, const Eigen::VectorXd& r, LinearSolveCost& cost);
  // The whole solution of A' x = b with x_c on the interface: the backward substitution of the last reduce(),
  // whose b this must be.
  Eigen::VectorXd expand(const Eigen::VectorXd& b, const Eigen::VectorXd& x_c, LinearSolveCost& cost);
  // S_c, the interface matrix of the last reduce().
  const Eigen::MatrixXd& interface_matrix() const { return schur_->schur(); }

 private:
  // Refactorises A when the problem, its linear part or its nonlinear dofs changed.
  void prepare(NonlinearProblem& problem, LinearSolveCost& cost);
  Eigen::VectorXd solve(NonlinearProblem& problem, const Eigen::VectorXd& b, LinearSolveCost& cost);
  // D = J - A on the nonlinear dofs, as its non-zero entries (positions among the nonlinear dofs).
  struct NonlinearPart {
    std::vector<Eigen::Triplet<double, int>> entries;
    std::vector<int> active;  // the nonlinear dofs with a non-zero row or column of D, in order
    // D_II, sparse: a contact node's tangent couples its own few dofs, so products with it cost its
    // non-zeros, not the cube of the active dofs.
    Eigen::SparseMatrix<double, Eigen::RowMajor> on_active() const;
    Eigen::MatrixXd whole(int m) const;  // D, m x m
  };
  // schur_->reduce(b), its time counted as the solve's.
  Eigen::VectorXd timed_reduce(const Eigen::VectorXd& b, LinearSolveCost& cost);
  // D from the problem's last assembly.
  NonlinearPart nonlinear_part(NonlinearProblem& problem, LinearSolveCost& cost);
  Eigen::VectorXd schur_step(const NonlinearPart& D, const Eigen::VectorXd& b, LinearSolveCost& cost);
  // (S_c + D) x_c = r.
  Eigen::VectorXd interface_step(const NonlinearPart& D, const Eigen::VectorXd& r, LinearSolveCost& cost);
  Eigen::VectorXd columns_step(const NonlinearPart& D, const Eigen::VectorXd& b, LinearSolveCost& cost);

  LinearStrategy method_;
  std::string linear_solver_name_;
  double max_fraction_;
  int max_dofs_;
  // The problem whose linear part could not be condensed (singular): it is solved in full from then on.
  const NonlinearProblem* uncondensable_ = nullptr;
  const NonlinearProblem* problem_ = nullptr;
  std::uint64_t version_ = 0;
  std::vector<int> nonlinear_;
  std::vector<int> position_;             // position of a global dof among the nonlinear dofs, or -1
  std::vector<double> nonlinear_values_;  // J - A on the nonlinear rows (NonlinearProblem::nonlinear_part)
  // Schur: the factorisation, and S_c^-1 when S_c is regular (else S_c + D is factorised per iteration).
  std::unique_ptr<SchurComplement> schur_;
  Eigen::MatrixXd schur_inverse_;
  bool schur_regular_ = false;
  // The Woodbury system's factorisation, 1 + D_II S_c^-1[I, I], kept while the active set and D_II stay
  // the same (linear laws in a settled contact state: most iterations of the shipped scenes).
  std::vector<int> woodbury_active_;
  std::vector<Eigen::Triplet<double, int>> woodbury_d_;  // D's entries it was formed with
  Eigen::PartialPivLU<Eigen::MatrixXd> woodbury_lu_;
  bool woodbury_valid_ = false;
  // Columns: A's factorisation and the columns of S computed so far.
  std::unique_ptr<LinearSolver> linear_;
  std::vector<Eigen::VectorXd> columns_;
};

}  // namespace pc

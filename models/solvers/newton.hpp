#pragma once
// Monolithic Newton on all free values of a NonlinearProblem (for the paper's Model, (29)-(30): velocity and
// potential together), with backtracking line search and convergence judged per block, since the
// mechanical and electric residuals have different units.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "assembly/linear_solver.hpp"
#include "models/solvers/condensed_solve.hpp"
#include "models/solvers/krylov_solve.hpp"
#include "models/solvers/linear_solve_cost.hpp"
#include "models/solvers/linear_strategy.hpp"
#include "models/solvers/nonlinear_problem.hpp"
#include "models/solvers/reduced_contact_system.hpp"
#include "models/solvers/strategy_cost_model.hpp"

namespace pc {

// The residual's round-off floor: block b's residual cannot be resolved below
//   floor_b = kRoundOffFloorFactor * eps * NonlinearProblem::round_off_scales()[b]
// (for a Model, the gross size |K| |x| of the terms it sums, at the current iterate). Measured residuals
// that stagnate at round-off are 0.2 to 0.85 eps times that scale (the paper's scene in P1 and P2,
// triangles and quadrilaterals, c_nu up to 1e16, every side clamped, the strip and the 3D box), so 8
// leaves a safety factor of about 10.
inline constexpr double kRoundOffFloorFactor = 8;
// The smallest meaningful relative tolerance, kRoundOffFloorFactor machine epsilons (1.8e-15): a smaller
// one asks a block whose terms do not cancel for a residual below its floor. The scene reader refuses it.
double min_relative_tolerance();

struct NewtonOptions {
  int max_iterations = 25;
  // Block b has converged when ||R_b|| <= max(absolute, relative * reference_b, floor_b), where
  // reference_b is the larger of the block's first residual and the scale of the forces that balance in
  // it (the largest single term, NonlinearProblem::residual_scales), and floor_b is its round-off floor
  // above: a residual cannot drop below round-off of the terms it sums, however small the first residual
  // of a step was or however much those terms cancel (every side clamped: the net terms are round-off
  // themselves). A relative tolerance below min_relative_tolerance() does not count the floor: a residual
  // that stagnates there above the tolerance ends the solve as RoundOffFloor, which no smaller time step
  // can mend.
  double relative_tolerance = 1e-10;
  double absolute_tolerance = 1e-14;
  std::map<std::string, double> absolute_tolerances;  // per block, overriding absolute_tolerance
  // ... or when a full step changed every block by at most this much relative to the block's size.
  double increment_tolerance = 1e-12;
  // Globalisation. With line_search, a step is taken in full as long as the scaled residual stays finite
  // and below the divergence bound (a watchdog, Chamberlain et al. 1982): a node crossing the kink of a
  // contact law makes the residual jump even when the step is right, so Armijo backtracking at every
  // iteration would stall there. When `watchdog` full steps in a row have not improved on the best
  // iterate so far (by the Armijo fraction), Newton returns to that iterate and backtracks from it.
  // watchdog = 0 gives classical Armijo backtracking at every iteration.
  bool line_search = true;
  int watchdog = 8;
  int max_backtracks = 12;
  double backtrack_factor = 0.5;
  double armijo = 1e-4;
  // The scaled residual growing by this factor over the first one (or over 1, the size of the block's
  // reference, if the first was smaller) means divergence.
  double divergence_factor = 1e12;
  std::string linear_solver = "mumps";
  // Condensed and Krylov steps (models/solvers/linear_strategy.hpp): when only a few dofs carry nonlinear
  // terms (the contact boundary), a kept factorisation serves many iterations instead of a new one each.
  // Used when the nonlinear dofs are at most this fraction of all; 0 disables them (a full factorisation
  // per iteration).
  double condensed_max_fraction = 0.25;
  // The dense condensations (schur, columns) only up to this many nonlinear dofs, whose cube their work
  // grows as (1600: every mesh of the fast-path study up to 480 x 160); past it "auto" takes krylov and a
  // named dense method a full factorisation per iteration.
  int condensed_max_dofs = 1600;
  // The linear strategy (models/solvers/linear_strategy.hpp): "auto" (by the cost model), "schur" (MUMPS's
  // Schur complement of the interior: one solve's worth of work per iteration), "columns" (any
  // linear_solver: two solves per iteration, plus one per newly active dof and factorisation) or "krylov"
  // (GMRES preconditioned by a kept factorisation of an earlier J: a few solves per iteration, nothing
  // dense, so it applies whatever the number of contact dofs).
  std::string condensation = "auto";
  // "auto" keeps the dense matrices of schur within this many bytes (0: no limit); scenes set a quarter of
  // the memory available.
  double dense_memory_budget_bytes = 0;
  // On the schur path, iterate on the contact dofs alone (models/solvers/reduced_contact_system.hpp): one
  // forward and one backward substitution and two residuals of the whole system per solve, whatever its
  // number of iterations, where each iteration of the whole system costs a solve and a residual. The
  // iterates are the same; false iterates on the whole system (to compare, or for a problem whose
  // interior must be seen at every iteration).
  bool contact_newton = true;
};

enum class NewtonOutcome { Converged, MaxIterations, Diverged, SingularTangent, RoundOffFloor };
std::string to_string(NewtonOutcome outcome);

struct NewtonIteration {
  std::vector<double> residual_norms;   // per block, after the iteration (iteration 0: before any step)
  std::vector<double> increment_norms;  // per block, of the accepted step
  double step_length = 0;
  int backtracks = 0;
  bool restarted = false;  // the watchdog returned to the best iterate before this step
};

// The linear solves' cost (analyze, factorize, solve and condensation seconds, factorizations) is the
// base, so that a strategy's cost adds into it.
struct NewtonReport : LinearSolveCost {
  NewtonOutcome outcome = NewtonOutcome::MaxIterations;
  int iterations = 0;
  std::vector<std::string> blocks;       // the problem's blocks, in order
  std::vector<NewtonIteration> history;  // history[0] is the initial residual
  double assembly_seconds = 0, total_seconds = 0;
  // The part of assembly_seconds the problem spent on the Jacobian (NonlinearProblem::jacobian_assembly_seconds);
  // the rest is the residual's.
  double jacobian_seconds = 0;
  bool condensed = false;                          // whether a condensed or Krylov step was used
  LinearStrategy strategy = LinearStrategy::Full;  // of the last iteration
  int krylov_iterations = 0;                       // GMRES iterations, over the solve
  // Of `iterations`, those made on the contact dofs alone (NewtonOptions::contact_newton); the rest, if any,
  // on the whole system after them.
  int contact_iterations = 0;
  std::map<std::string, double> diagnostics;  // the problem's, at the end
  std::string message;
  bool converged() const { return outcome == NewtonOutcome::Converged; }
};

class NewtonSolver {
 public:
  explicit NewtonSolver(NewtonOptions options = {});
  // The options are fixed here: the linear solver and the condensed solve are built from them.
  const NewtonOptions& options() const { return options_; }
  // Solves R(x) = 0 from the problem's current free values; the problem is left at the last iterate.
  NewtonReport solve(NonlinearProblem& problem);
  // Symbolic analyses done so far (one per sparsity pattern).
  int analyses() const { return analyses_; }
  // What "auto" chose and why (the cost model's line), once it has chosen; empty otherwise.
  const std::string& strategy_explanation() const { return explanation_; }
  // What the solver of full factorisations predicted at its last analysis (zeros before one, and while the
  // condensed or Krylov paths solve without it).
  FactorEstimate full_factor_estimate() const { return linear_->factor_estimate(); }
  // Solves J dx = rhs with the problem's tangent at its last assembly, by the path the last solve took
  // (the condensed and Krylov paths reuse what they keep; the full path factorises J again): what the
  // time error estimate propagates the error with.
  Eigen::VectorXd solve_tangent(NonlinearProblem& problem, const Eigen::VectorXd& rhs, LinearSolveCost& cost);
  // Called after every iteration with the report so far (its history's last entry is the iteration):
  // progress for a long solve.
  void set_iteration_callback(std::function<void(const NewtonReport&)> on_iteration) {
    on_iteration_ = std::move(on_iteration);
  }

 private:
  // J dx = rhs (a Newton step: rhs = -R): through the condensed system where it applies, else by a full
  // factorisation.
  Eigen::VectorXd step(NonlinearProblem& problem, const Eigen::VectorXd& rhs, NewtonReport& report);
  Eigen::VectorXd step_by_strategy(NonlinearProblem& problem, const Eigen::VectorXd& rhs, NewtonReport& report);
  Eigen::VectorXd full_step(NonlinearProblem& problem, const Eigen::VectorXd& rhs, NewtonReport& report);
  // The problem reduced to its contact dofs at its current (assembled) iterate, where contact_newton and
  // the schur path apply; null otherwise.
  std::unique_ptr<ReducedContactSystem> reduce_to_contact(NonlinearProblem& problem, NewtonReport& report);
  // One call of solve(): its report so far, its convergence test and its phases (newton.cpp).
  struct Run;

  NewtonOptions options_;
  std::function<void(const NewtonReport&)> on_iteration_;
  std::unique_ptr<LinearSolver> linear_;
  const CsrMatrix* analyzed_matrix_ = nullptr;
  long analyzed_nonzeros_ = -1;
  int analyses_ = 0;
  // The strategy for this problem: the named one, or the cost model's choice (kept while the problem and
  // its nonlinear dofs stay the same).
  LinearStrategy strategy_for(NonlinearProblem& problem);

  LinearStrategy named_strategy_;
  // auto's choice, for the problem and nonlinear dofs it was made for.
  const NonlinearProblem* chosen_for_ = nullptr;
  std::vector<int> chosen_nonlinear_;
  LinearStrategy chosen_ = LinearStrategy::Full;
  std::string explanation_;
  CondensedSolve condensed_;
  KrylovSolve krylov_;
};

}  // namespace pc

#include "models/solvers/newton.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "assembly/error.hpp"
#include "assembly/processes.hpp"
#include "models/solvers/reduced_contact_system.hpp"

namespace pc {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Norms of the blocks of a vector of free values.
std::vector<double> block_norms(const std::vector<ProblemBlock>& blocks, const Eigen::VectorXd& x) {
  std::vector<double> norms;
  for (const ProblemBlock& b : blocks) norms.push_back(x.segment(b.begin, b.size).norm());
  return norms;
}

// The first block whose norm is not finite (an entry is inf or NaN, or the norm overflows), or -1. A norm
// that overflows is no measure of convergence: every comparison with it would be meaningless.
int non_finite_block(const std::vector<double>& norms) {
  for (size_t b = 0; b < norms.size(); ++b)
    if (!std::isfinite(norms[b])) return int(b);
  return -1;
}

double merit(const std::vector<double>& norms, const std::vector<double>& reference) {
  double m = 0;
  for (size_t b = 0; b < norms.size(); ++b) m += (norms[b] / reference[b]) * (norms[b] / reference[b]);
  return m;
}

// Newton's convergence test, per block since the blocks' residuals have different units: block b has
// converged when its residual is within its tolerance max(absolute_b, relative * reference_b), or within
// the larger of that and its round-off floor where the relative tolerance lets the floor count
// (NewtonOptions::relative_tolerance).
class ConvergenceTest {
 public:
  // From the first residual's block norms and the scales of the forces that balance in the blocks.
  ConvergenceTest(const NewtonOptions& options, const NonlinearProblem& problem, std::vector<std::string> blocks,
                  const std::vector<double>& norms, const std::vector<double>& scales);
  // Reference of each block: its first residual (or its absolute tolerance, if that is larger), so that
  // the merit function weighs the blocks alike whatever their units.
  const std::vector<double>& reference() const { return reference_; }
  double tolerance(int b) const { return std::max(absolute_[b], options_.relative_tolerance * reference_[b]); }
  // Whether the relative tolerance is at least min_relative_tolerance(), so that a block's floor meets the test.
  bool floor_counts() const { return floor_counts_; }
  // The round-off floor of each block at the last assembled iterate (kRoundOffFloorFactor); a floor that
  // is not finite is none, so that it never declares convergence.
  std::vector<double> round_off_floors() const;
  // Every block within its tolerance, or within the larger of its tolerance and its floor.
  bool within(const std::vector<double>& r, const std::vector<double>& floors, bool or_floor) const;
  bool converged(const std::vector<double>& r, const std::vector<double>& floors) const {
    return within(r, floors, floor_counts_);
  }
  // Why a residual met the test: its tolerance, or a block's round-off floor.
  std::string converged_message(const std::vector<double>& r, const std::vector<double>& floors, std::string met) const;
  // With a tolerance below the floor, the residual of every block within its floor (twice in a row, so that
  // a step that still lands lower is taken) but above its tolerance stagnates there: the solve stops.
  bool at_floor(const std::vector<double>& r, const std::vector<double>& floors);
  void restart_floor_count() { iterates_at_floor_ = 0; }
  // Why a residual that stagnates at its floor ends the solve (NewtonOutcome::RoundOffFloor).
  std::string floor_message(const std::vector<double>& r, const std::vector<double>& floors) const;

 private:
  const NewtonOptions& options_;
  const NonlinearProblem& problem_;
  std::vector<std::string> blocks_;
  std::vector<double> absolute_, reference_;
  bool floor_counts_;
  int iterates_at_floor_ = 0;
};

ConvergenceTest::ConvergenceTest(const NewtonOptions& options, const NonlinearProblem& problem,
                                 std::vector<std::string> blocks, const std::vector<double>& norms,
                                 const std::vector<double>& scales)
    : options_(options),
      problem_(problem),
      blocks_(std::move(blocks)),
      absolute_(blocks_.size(), options.absolute_tolerance),
      reference_(blocks_.size()),
      floor_counts_(options.relative_tolerance >= min_relative_tolerance()) {
  const int n_blocks = int(blocks_.size());
  for (int b = 0; b < n_blocks; ++b)
    if (options.absolute_tolerances.count(blocks_[b])) absolute_[b] = options.absolute_tolerances.at(blocks_[b]);
  for (int b = 0; b < n_blocks; ++b) reference_[b] = std::max({norms[b], scales[b], absolute_[b], 1e-300});
}

std::vector<double> ConvergenceTest::round_off_floors() const {
  std::vector<double> floors = problem_.round_off_scales();
  for (double& f : floors) f = std::isfinite(f) ? kRoundOffFloorFactor * std::numeric_limits<double>::epsilon() * f : 0;
  return floors;
}

bool ConvergenceTest::within(const std::vector<double>& r, const std::vector<double>& floors, bool or_floor) const {
  for (int b = 0; b < int(blocks_.size()); ++b)
    if (r[b] > std::max(tolerance(b), or_floor ? floors[b] : 0.0)) return false;
  return true;
}

std::string ConvergenceTest::converged_message(const std::vector<double>& r, const std::vector<double>& floors,
                                               std::string met) const {
  for (int b = 0; b < int(blocks_.size()); ++b)
    if (r[b] > tolerance(b))
      return message(met, " at the round-off floor of block '", blocks_[b], "' (residual ", r[b], ", floor ", floors[b],
                     ", tolerance ", tolerance(b), ")");
  return met;
}

bool ConvergenceTest::at_floor(const std::vector<double>& r, const std::vector<double>& floors) {
  iterates_at_floor_ = !floor_counts_ && within(r, floors, true) ? iterates_at_floor_ + 1 : 0;
  return iterates_at_floor_ >= 2;
}

std::string ConvergenceTest::floor_message(const std::vector<double>& r, const std::vector<double>& floors) const {
  int worst = 0;
  for (int b = 0; b < int(blocks_.size()); ++b)
    if (r[b] / std::max(tolerance(b), 1e-300) > r[worst] / std::max(tolerance(worst), 1e-300)) worst = b;
  return message("the residual of block '", blocks_[worst], "' (", r[worst], ") stagnates at its round-off floor ",
                 floors[worst], " (", kRoundOffFloorFactor,
                 " eps times the gross size of its terms), above the tolerance ", tolerance(worst),
                 " (relative_tolerance ", options_.relative_tolerance, " times ", reference_[worst],
                 "); a relative tolerance below ", min_relative_tolerance(),
                 " cannot be met, and no smaller time step lowers a round-off floor");
}

// How a run of iterations ends: with the solve's verdict, or without one (on the contact dofs, whose whole
// residual is then judged).
struct Ending {
  std::optional<NewtonReport> verdict;
};

// A run of iterations' state: the last residual's block norms, the bound past which it diverges, and the
// watchdog's best iterate so far and the full steps taken since it was last improved on.
struct IterationState {
  std::vector<double> norms;
  double divergence_bound = 0;
  bool watchdog = false;
  Eigen::VectorXd best;
  double best_merit = 0;
  int since_best = 0;
};

// The step a line search took: its length, the backtracks to it, and the residual's block norms there.
struct LineSearchStep {
  double alpha = 1;
  int backtracks = 0;
  std::vector<double> norms;
};

// The contact dofs, as `iterate` sees a system: its assembly and steps timed into the report.
struct OnContact {
  ReducedContactSystem& system;
  NonlinearProblem& problem;
  NewtonReport& report;
  void assemble() {
    const auto t = Clock::now();
    system.assemble();
    report.assembly_seconds += seconds_since(t);
  }
  const Eigen::VectorXd& residual() const { return system.residual(); }
  Eigen::VectorXd free_values() const { return system.free_values(); }
  void set_free_values(const Eigen::VectorXd& x) { system.set_free_values(x); }
  void add_to_free_values(const Eigen::VectorXd& step) { system.add_to_free_values(step); }
  Eigen::VectorXd step(const Eigen::VectorXd& rhs, NewtonReport& r) {
    const double jacobian_before = problem.jacobian_assembly_seconds();
    Eigen::VectorXd dx = system.step(rhs, r);
    const double formed = problem.jacobian_assembly_seconds() - jacobian_before;
    r.jacobian_seconds += formed;
    r.assembly_seconds += formed;
    return dx;
  }
};

}  // namespace

double min_relative_tolerance() { return kRoundOffFloorFactor * std::numeric_limits<double>::epsilon(); }

std::string to_string(NewtonOutcome outcome) {
  switch (outcome) {
    case NewtonOutcome::Converged: return "converged";
    case NewtonOutcome::MaxIterations: return "max_iterations";
    case NewtonOutcome::Diverged: return "diverged";
    case NewtonOutcome::SingularTangent: return "singular_tangent";
    case NewtonOutcome::RoundOffFloor: return "round_off_floor";
  }
  return "unknown";
}

NewtonSolver::NewtonSolver(NewtonOptions options)
    : options_(std::move(options)),
      named_strategy_(linear_strategy_from_string(options_.condensation)),
      condensed_(named_strategy_, options_.linear_solver, options_.condensed_max_fraction, options_.condensed_max_dofs),
      krylov_(options_.linear_solver) {
  require(options_.max_iterations >= 1, "Newton: max_iterations must be >= 1, got ", options_.max_iterations);
  require(options_.relative_tolerance >= 0 && options_.absolute_tolerance >= 0 && options_.increment_tolerance >= 0,
          "Newton: tolerances must be >= 0");
  require(options_.watchdog >= 0, "Newton: watchdog must be >= 0, got ", options_.watchdog);
  require(options_.backtrack_factor > 0 && options_.backtrack_factor < 1,
          "Newton: backtrack_factor must be in (0, 1), got ", options_.backtrack_factor);
  linear_ = make_model_solver(options_.linear_solver);
}

LinearStrategy NewtonSolver::strategy_for(NonlinearProblem& problem) {
  if (options_.condensed_max_fraction <= 0) return LinearStrategy::Full;
  // The condensed and Krylov paths factorise and multiply a whole matrix of this process; a distributed
  // model has one share of it per process, which only MUMPS's distributed input sums.
  if (processes::distributed()) {
    if (named_strategy_ != LinearStrategy::Full && explanation_.empty())
      explanation_ = message("distributed over ", processes::count(),
                             " processes: a factorisation of J per "
                             "iteration, by MUMPS from each process's share (solver.condensation = '",
                             to_string(named_strategy_), "' needs the whole matrix on one process)");
    return LinearStrategy::Full;
  }
  if (named_strategy_ == LinearStrategy::Krylov) return LinearStrategy::Krylov;
  if (named_strategy_ != LinearStrategy::Auto)
    return condensed_.applies(problem) ? condensed_.method() : LinearStrategy::Full;
  // auto: where most dofs are nonlinear, J changes everywhere and only a factorisation per iteration applies.
  if (!condensed_.applies_in_proportion(problem)) return LinearStrategy::Full;
  const std::vector<int>& nonlinear = problem.nonlinear_dofs();
  if (chosen_for_ == &problem && chosen_nonlinear_ == nonlinear) return chosen_;
  chosen_for_ = &problem;
  chosen_nonlinear_ = nonlinear;
  if (nonlinear.empty()) {
    // A linear problem: A's factorisation, kept from solve to solve.
    chosen_ = condensed_.method();
    return chosen_;
  }
  StrategyCostInputs inputs;
  inputs.dofs = double(problem.residual().size());
  inputs.nonlinear_dofs = double(nonlinear.size());
  // The linear part has J's pattern, and asking for it forms no Jacobian.
  inputs.jacobian_nonzeros = double(problem.linear_jacobian().nonZeros());
  inputs.factors = krylov_.analyze(problem.linear_jacobian());
  inputs.memory_budget_bytes = options_.dense_memory_budget_bytes;
  const StrategyCosts costs = predict_strategy_costs(inputs);
  // The dense methods also keep to solver.condensed_max_dofs.
  chosen_ = costs.choice == LinearStrategy::Schur && condensed_.applies(problem) ? LinearStrategy::Schur
                                                                                 : LinearStrategy::Krylov;
  explanation_ = costs.explanation;
  if (chosen_ == LinearStrategy::Schur) krylov_.release();  // its analysis served the estimate only
  if (chosen_ != costs.choice)
    explanation_ +=
        message(", but ", nonlinear.size(),
                " contact dofs exceed solver.condensed_max_dofs = ", options_.condensed_max_dofs, ": krylov");
  return chosen_;
}

Eigen::VectorXd NewtonSolver::step(NonlinearProblem& problem, const Eigen::VectorXd& rhs, NewtonReport& report) {
  // A problem may form its Jacobian, or the part a condensed solve reads, when a path first asks for it
  // (Model does): that time is the Jacobian's assembly, not the solve's.
  const double jacobian_before = problem.jacobian_assembly_seconds();
  Eigen::VectorXd dx = step_by_strategy(problem, rhs, report);
  const double formed = problem.jacobian_assembly_seconds() - jacobian_before;
  report.jacobian_seconds += formed;
  report.assembly_seconds += formed;
  return dx;
}

Eigen::VectorXd NewtonSolver::step_by_strategy(NonlinearProblem& problem, const Eigen::VectorXd& rhs,
                                               NewtonReport& report) {
  const LinearStrategy strategy = strategy_for(problem);
  report.strategy = strategy;
  if (strategy == LinearStrategy::Krylov) {
    KrylovStep krylov = krylov_.step(problem, rhs);
    report += krylov.cost;
    report.condensed = true;
    report.krylov_iterations += krylov.iterations;
    return std::move(krylov.dx);
  }
  if (strategy != LinearStrategy::Full) {
    CondensedStep condensed = condensed_.step(problem, rhs);
    report += condensed.cost;
    report.condensed = condensed.dx.has_value();
    if (condensed.dx) return std::move(*condensed.dx);
    // The linear part (or, for the Schur method, its interior) is singular: the condensed solve no longer
    // applies to this problem, which is solved in full; a genuinely singular J then fails there with the
    // solver's message.
    report.strategy = LinearStrategy::Full;
  }
  return full_step(problem, rhs, report);
}

Eigen::VectorXd NewtonSolver::solve_tangent(NonlinearProblem& problem, const Eigen::VectorXd& rhs,
                                            LinearSolveCost& cost) {
  NewtonReport report;
  Eigen::VectorXd dx = step(problem, rhs, report);
  cost += report;
  return dx;
}

Eigen::VectorXd NewtonSolver::full_step(NonlinearProblem& problem, const Eigen::VectorXd& rhs, NewtonReport& report) {
  const CsrMatrix& J = problem.jacobian();
  if (analyzed_matrix_ != &J || analyzed_nonzeros_ != J.nonZeros()) {
    const auto t = Clock::now();
    linear_->analyze(J);
    report.analyze_seconds += seconds_since(t);
    analyzed_matrix_ = &J;
    analyzed_nonzeros_ = J.nonZeros();
    ++analyses_;
  }
  auto t = Clock::now();
  linear_->factorize(J);
  report.factorize_seconds += seconds_since(t);
  ++report.factorizations;
  t = Clock::now();
  Eigen::VectorXd dx = linear_->solve(rhs);
  report.solve_seconds += seconds_since(t);
  return dx;
}

// One call of solve(): the report so far, the convergence test set from the initial residual, and the phases.
struct NewtonSolver::Run {
  // Assembles the problem at its initial iterate and sets the convergence test up from its residual.
  Run(NewtonSolver& solver, NonlinearProblem& problem);
  // Assembles the problem at its current free values, timed into the report.
  void assemble();
  // The report, ended with this outcome and message, the problem's diagnostics and the solve's time.
  NewtonReport finish(NewtonOutcome outcome, std::string message);
  // Convergence is never declared on a non-finite residual, increment or iterate: each is Diverged,
  // naming the block.
  std::optional<NewtonReport> not_finite(const std::vector<double>& block_values, const std::string& what);
  NewtonReport floor_report(const std::vector<double>& r, const std::vector<double>& floors) {
    return finish(NewtonOutcome::RoundOffFloor, test->floor_message(r, floors));
  }
  // The initial state's verdict, if it has one (not finite, converged, or at its round-off floor).
  std::optional<NewtonReport> judge_initial_state();
  // The iterations on the contact dofs, then the whole residual at their last values judged: the verdict,
  // or none when the whole system's iterations go on.
  std::optional<NewtonReport> solve_on_contact(ReducedContactSystem& reduced);

  // The iterations, on the whole system or on the contact dofs (ReducedContactSystem: the same iterates,
  // with the interior solved once). `system` gives residual(), free values and step(rhs) in its own
  // coordinates, `space` its blocks there. On the contact dofs, a residual that meets the test, a small
  // step, the round-off floor and the last iteration end the iterations without a verdict (nullopt): the
  // whole residual is then assembled and judged. `stagnated` says the floor ended them.
  template <class System>
  std::optional<NewtonReport> iterate(System& system, const std::vector<ProblemBlock>& space, bool on_contact);
  template <class System> IterationState start_iterations(System& system, const std::vector<ProblemBlock>& space);
  template <class System>
  std::optional<Ending> iterate_once(System& system, const std::vector<ProblemBlock>& space, bool on_contact,
                                     int iteration, IterationState& state);
  template <class System>
  LineSearchStep line_search(System& system, const std::vector<ProblemBlock>& space, const Eigen::VectorXd& dx,
                             bool armijo, double merit_before, double divergence_bound);
  template <class System>
  std::optional<Ending> stop(System& system, const std::vector<ProblemBlock>& space, bool on_contact, int iteration,
                             double alpha, const std::vector<double>& steps, IterationState& state);

  // The problem itself, as `iterate` sees a system.
  struct Whole {
    Run& run;
    void assemble() { run.assemble(); }
    const Eigen::VectorXd& residual() const { return run.problem.residual(); }
    Eigen::VectorXd free_values() const { return run.problem.free_values(); }
    void set_free_values(const Eigen::VectorXd& x) { run.problem.set_free_values(x); }
    void add_to_free_values(const Eigen::VectorXd& step) { run.problem.add_to_free_values(step); }
    Eigen::VectorXd step(const Eigen::VectorXd& rhs, NewtonReport& r) { return run.solver.step(run.problem, rhs, r); }
  };

  NewtonSolver& solver;
  const NewtonOptions& options;
  NonlinearProblem& problem;
  const Clock::time_point start = Clock::now();
  NewtonReport report;
  std::vector<ProblemBlock> blocks;
  std::vector<double> initial_norms;    // of the residual at the initial iterate, per block
  std::vector<double> scales;           // of the terms summed in that residual, per block
  std::optional<ConvergenceTest> test;  // set from the initial residual, once it is assembled
  double merit0 = 0;                    // the initial scaled residual
  bool stagnated = false;               // the round-off floor ended the last iterations
};

NewtonSolver::Run::Run(NewtonSolver& solver, NonlinearProblem& problem)
    : solver(solver), options(solver.options_), problem(problem) {
  assemble();
  blocks = problem.blocks();
  for (const ProblemBlock& b : blocks) report.blocks.push_back(b.name);
  initial_norms = block_norms(blocks, problem.residual());
  report.history.push_back({initial_norms, {}, 0, 0});
  scales = problem.residual_scales();
  test.emplace(options, problem, report.blocks, initial_norms, scales);
}

void NewtonSolver::Run::assemble() {
  const auto t = Clock::now();
  const double jacobian_before = problem.jacobian_assembly_seconds();
  problem.assemble(true);
  report.assembly_seconds += seconds_since(t);
  report.jacobian_seconds += problem.jacobian_assembly_seconds() - jacobian_before;
}

NewtonReport NewtonSolver::Run::finish(NewtonOutcome outcome, std::string message) {
  report.outcome = outcome;
  report.message = std::move(message);
  report.diagnostics = problem.diagnostics();
  report.total_seconds = seconds_since(start);
  return report;
}

std::optional<NewtonReport> NewtonSolver::Run::not_finite(const std::vector<double>& block_values,
                                                          const std::string& what) {
  const int b = non_finite_block(block_values);
  if (b < 0) return std::nullopt;
  return finish(NewtonOutcome::Diverged,
                message(what, " of block '", report.blocks[b], "' is not finite (",
                        std::isnan(block_values[b]) ? "its norm is not a number" : "its norm overflows", ")"));
}

std::optional<NewtonReport> NewtonSolver::Run::judge_initial_state() {
  if (auto r = not_finite(initial_norms, "the initial residual")) return r;
  if (auto r = not_finite(block_norms(blocks, problem.free_values()), "the initial iterate")) return r;
  if (auto r = not_finite(scales, "the size of the terms summed in the initial residual")) return r;
  if (problem.residual().size() == 0) return finish(NewtonOutcome::Converged, "initial state satisfies the tolerances");
  if (const std::vector<double> floors = test->round_off_floors(); test->converged(initial_norms, floors))
    return finish(NewtonOutcome::Converged,
                  test->converged_message(initial_norms, floors, "initial state satisfies the tolerances"));
  else if (test->at_floor(initial_norms, floors))
    return floor_report(initial_norms, floors);
  merit0 = merit(initial_norms, test->reference());
  return std::nullopt;
}

// Newton's iterations on `system` from its current iterate, up to max_iterations over the solve.
template <class System>
std::optional<NewtonReport> NewtonSolver::Run::iterate(System& system, const std::vector<ProblemBlock>& space,
                                                       bool on_contact) {
  IterationState state = start_iterations(system, space);
  for (int iteration = report.iterations + 1; iteration <= options.max_iterations; ++iteration) {
    report.iterations = iteration;
    if (std::optional<Ending> end = iterate_once(system, space, on_contact, iteration, state)) return end->verdict;
  }
  if (on_contact) return std::nullopt;
  return finish(NewtonOutcome::MaxIterations, message("no convergence in ", options.max_iterations, " iterations"));
}

// The state a run of iterations starts from: the system's residual, its divergence bound, the watchdog's
// best iterate (the current one).
template <class System>
IterationState NewtonSolver::Run::start_iterations(System& system, const std::vector<ProblemBlock>& space) {
  IterationState state;
  state.norms = block_norms(space, system.residual());
  // Growth past this is divergence. On the contact dofs the first residual is that of the interior
  // solved exactly, which can be far larger than the whole system's first (the paper's strip from rest,
  // its potential not yet in equilibrium: 570 against 8e-6 in v): growth counts from the larger.
  state.divergence_bound = options.divergence_factor * std::max({merit0, merit(state.norms, test->reference()), 1.0});
  state.watchdog = options.line_search && options.watchdog > 0;
  if (state.watchdog) state.best = system.free_values();
  state.best_merit = merit(state.norms, test->reference());
  return state;
}

// One iteration: back to the best iterate if the watchdog says so, the Newton step (assembled and solved),
// the line search along it (the update), its history entry, and whether it ends the iterations.
template <class System>
std::optional<Ending> NewtonSolver::Run::iterate_once(System& system, const std::vector<ProblemBlock>& space,
                                                      bool on_contact, int iteration, IterationState& state) {
  bool restarted = false;
  if (state.watchdog && state.since_best >= options.watchdog) {
    system.set_free_values(state.best);
    system.assemble();
    state.norms = block_norms(space, system.residual());
    state.since_best = 0;
    restarted = true;
  }
  Eigen::VectorXd dx;
  try {
    dx = system.step(-system.residual(), report);
  } catch (const Error& e) {
    return Ending{finish(NewtonOutcome::SingularTangent, message("iteration ", iteration, ": ", e.what()))};
  }
  if (auto r = not_finite(block_norms(space, dx), message("iteration ", iteration, ": the Newton increment")))
    return Ending{r};

  // Armijo backtracking on the scaled residual (classical mode, or after a watchdog restart); otherwise
  // the full step, unless it leaves the finite, non-divergent range.
  const bool armijo = options.line_search && (!state.watchdog || restarted);
  const double merit_before = merit(state.norms, test->reference());
  LineSearchStep taken = line_search(system, space, dx, armijo, merit_before, state.divergence_bound);
  state.norms = std::move(taken.norms);
  const std::vector<double> steps = block_norms(space, taken.alpha * dx);
  report.history.push_back({state.norms, steps, taken.alpha, taken.backtracks, restarted});
  if (solver.on_iteration_) solver.on_iteration_(report);
  return stop(system, space, on_contact, iteration, taken.alpha, steps, state);
}

// The line search along dx from the system's iterate, which it leaves at the step taken: Armijo's test when
// `armijo`, else the finite, non-divergent range; the full step without line_search.
template <class System>
LineSearchStep NewtonSolver::Run::line_search(System& system, const std::vector<ProblemBlock>& space,
                                              const Eigen::VectorXd& dx, bool armijo, double merit_before,
                                              double divergence_bound) {
  LineSearchStep taken;
  double applied = 0;
  while (true) {
    system.add_to_free_values((taken.alpha - applied) * dx);
    applied = taken.alpha;
    system.assemble();
    taken.norms = block_norms(space, system.residual());
    const double m = merit(taken.norms, test->reference());
    const bool accept =
        !options.line_search || (armijo ? std::isfinite(m) && m <= (1 - 2 * options.armijo * taken.alpha) * merit_before
                                        : std::isfinite(m) && m <= divergence_bound);
    if (accept || taken.backtracks >= options.max_backtracks) break;
    taken.alpha *= options.backtrack_factor;
    ++taken.backtracks;
  }
  return taken;
}

// The stop decisions after an iteration of step length alpha and block increments `steps`: whether it ends
// the iterations, and how; if not, the watchdog's account of it.
template <class System>
std::optional<Ending> NewtonSolver::Run::stop(System& system, const std::vector<ProblemBlock>& space, bool on_contact,
                                              int iteration, double alpha, const std::vector<double>& steps,
                                              IterationState& state) {
  const std::vector<double>& norms = state.norms;
  if (auto r = not_finite(norms, message("iteration ", iteration, ": the residual"))) return Ending{r};
  const std::vector<double> sizes = block_norms(space, system.free_values());
  if (auto r = not_finite(sizes, message("iteration ", iteration, ": the iterate"))) return Ending{r};
  const std::vector<double> floors = test->round_off_floors();
  if (test->converged(norms, floors))
    return Ending{on_contact ? std::nullopt
                             : std::optional(finish(NewtonOutcome::Converged,
                                                    test->converged_message(norms, floors, "residual tolerance met")))};
  bool small_step = alpha == 1;
  for (int b = 0; b < int(blocks.size()); ++b)
    small_step = small_step && steps[b] <= options.increment_tolerance * std::max(sizes[b], 1e-300);
  if (small_step)
    return Ending{on_contact ? std::nullopt
                             : std::optional(finish(NewtonOutcome::Converged, "increment tolerance met"))};
  if (test->at_floor(norms, floors)) {
    stagnated = true;
    return Ending{on_contact ? std::nullopt : std::optional(floor_report(norms, floors))};
  }
  const double m = merit(norms, test->reference());
  if (m > state.divergence_bound)
    return Ending{finish(
        NewtonOutcome::Diverged,
        message("iteration ", iteration, ": the scaled residual grew by more than ", options.divergence_factor))};
  if (m <= (1 - 2 * options.armijo) * state.best_merit) {
    state.best_merit = m;
    if (state.watchdog) state.best = system.free_values();
    state.since_best = 0;
  } else {
    ++state.since_best;
  }
  return std::nullopt;
}

std::optional<NewtonReport> NewtonSolver::Run::solve_on_contact(ReducedContactSystem& reduced) {
  OnContact on_contact{reduced, problem, report};
  test->restart_floor_count();
  if (auto r = iterate(on_contact, reduced.blocks(), true)) return r;
  report.contact_iterations = report.iterations;
  // The whole solution at the last contact values, and its residual: the verdict is the whole system's.
  try {
    reduced.expand(report);
  } catch (const Error& e) {
    return finish(NewtonOutcome::SingularTangent, message("iteration ", report.iterations, ": ", e.what()));
  }
  assemble();
  const std::vector<double> verified = block_norms(blocks, problem.residual());
  report.history.back().residual_norms = verified;
  if (auto r = not_finite(verified, message("iteration ", report.iterations, ": the residual"))) return r;
  const std::vector<double> floors = test->round_off_floors();
  if (test->converged(verified, floors))
    return finish(NewtonOutcome::Converged, test->converged_message(verified, floors, "residual tolerance met"));
  // Stagnated on the contact dofs, and the whole residual is at its floor too: as on the whole system.
  if (stagnated && !test->floor_counts() && test->within(verified, floors, true)) return floor_report(verified, floors);
  test->restart_floor_count();  // the whole system's iterations go on from here
  return std::nullopt;
}

NewtonReport NewtonSolver::solve(NonlinearProblem& problem) {
  Run run(*this, problem);
  if (std::optional<NewtonReport> verdict = run.judge_initial_state()) return *verdict;
  if (std::unique_ptr<ReducedContactSystem> reduced = reduce_to_contact(problem, run.report)) {
    if (std::optional<NewtonReport> verdict = run.solve_on_contact(*reduced)) return *verdict;
  }
  Run::Whole whole{run};
  return *run.iterate(whole, run.blocks, false);
}

std::unique_ptr<ReducedContactSystem> NewtonSolver::reduce_to_contact(NonlinearProblem& problem, NewtonReport& report) {
  if (!options_.contact_newton || strategy_for(problem) != LinearStrategy::Schur) return nullptr;
  // The nonlinear rows assembled at x0 are the problem's assembly; the rest is the reduction's, which its
  // cost counts.
  const double jacobian_before = problem.jacobian_assembly_seconds();
  const LinearSolveCost before = report;
  const auto t = Clock::now();
  std::unique_ptr<ReducedContactSystem> reduced = ReducedContactSystem::reduce(problem, condensed_, report);
  const double linear = report.analyze_seconds - before.analyze_seconds + report.factorize_seconds -
                        before.factorize_seconds + report.solve_seconds - before.solve_seconds +
                        report.condensation_seconds - before.condensation_seconds;
  report.assembly_seconds += seconds_since(t) - linear;
  report.jacobian_seconds += problem.jacobian_assembly_seconds() - jacobian_before;
  if (reduced) {
    report.strategy = LinearStrategy::Schur;
    report.condensed = true;
  }
  return reduced;
}

}  // namespace pc

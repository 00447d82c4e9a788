#include "models/solvers/newton.hpp"

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
  require(options_.backtrack_factor > 0 && options_.backtrack_factor < 1, "Newton: backtrack_factor must be in (0, 1), got ",
          options_.backtrack_factor);
  linear_ = make_model_solver(options_.linear_solver);
}

LinearStrategy NewtonSolver::strategy_for(NonlinearProblem& problem) {
  if (options_.condensed_max_fraction <= 0) return LinearStrategy::Full;
  // The condensed and Krylov paths factorise and multiply a whole matrix of this process; a distributed
  // model has one share of it per process, which only MUMPS's distributed input sums.
  if (processes::distributed()) {
    if (named_strategy_ != LinearStrategy::Full && explanation_.empty())
      explanation_ = message("distributed over ", processes::count(), " processes: a factorisation of J per "
                             "iteration, by MUMPS from each process's share (solver.condensation = '",
                             to_string(named_strategy_), "' needs the whole matrix on one process)");
    return LinearStrategy::Full;
  }
  if (named_strategy_ == LinearStrategy::Krylov) return LinearStrategy::Krylov;
  if (named_strategy_ != LinearStrategy::Auto) return condensed_.applies(problem) ? condensed_.method() : LinearStrategy::Full;
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
    explanation_ += message(", but ", nonlinear.size(), " contact dofs exceed solver.condensed_max_dofs = ",
                            options_.condensed_max_dofs, ": krylov");
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

Eigen::VectorXd NewtonSolver::solve_tangent(NonlinearProblem& problem, const Eigen::VectorXd& rhs, LinearSolveCost& cost) {
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

NewtonReport NewtonSolver::solve(NonlinearProblem& problem) {
  const auto start = Clock::now();
  NewtonReport report;
  auto assemble = [&] {
    const auto t = Clock::now();
    const double jacobian_before = problem.jacobian_assembly_seconds();
    problem.assemble(true);
    report.assembly_seconds += seconds_since(t);
    report.jacobian_seconds += problem.jacobian_assembly_seconds() - jacobian_before;
  };
  auto finish = [&](NewtonOutcome outcome, std::string message) {
    report.outcome = outcome;
    report.message = std::move(message);
    report.diagnostics = problem.diagnostics();
    report.total_seconds = seconds_since(start);
    return report;
  };

  assemble();
  const std::vector<ProblemBlock> blocks = problem.blocks();
  for (const ProblemBlock& b : blocks) report.blocks.push_back(b.name);
  const int n_blocks = int(blocks.size());
  std::vector<double> absolute(n_blocks, options_.absolute_tolerance);
  for (int b = 0; b < n_blocks; ++b)
    if (options_.absolute_tolerances.count(report.blocks[b])) absolute[b] = options_.absolute_tolerances.at(report.blocks[b]);

  std::vector<double> norms = block_norms(blocks, problem.residual());
  report.history.push_back({norms, {}, 0, 0});
  // Reference of each block: its first residual (or its absolute tolerance, if that is larger), so that
  // the merit function weighs the blocks alike whatever their units.
  const std::vector<double> scales = problem.residual_scales();
  std::vector<double> reference(n_blocks);
  for (int b = 0; b < n_blocks; ++b) reference[b] = std::max({norms[b], scales[b], absolute[b], 1e-300});
  auto tolerance = [&](int b) { return std::max(absolute[b], options_.relative_tolerance * reference[b]); };
  // The round-off floor of each block at the last assembled iterate (kRoundOffFloorFactor); a floor that
  // is not finite is none, so that it never declares convergence.
  auto round_off_floors = [&] {
    std::vector<double> floors = problem.round_off_scales();
    for (double& f : floors)
      f = std::isfinite(f) ? kRoundOffFloorFactor * std::numeric_limits<double>::epsilon() * f : 0;
    return floors;
  };
  const bool floor_counts = options_.relative_tolerance >= min_relative_tolerance();
  // Every block within its tolerance, or within the larger of its tolerance and its floor.
  auto within = [&](const std::vector<double>& r, const std::vector<double>& floors, bool or_floor) {
    for (int b = 0; b < n_blocks; ++b)
      if (r[b] > std::max(tolerance(b), or_floor ? floors[b] : 0.0)) return false;
    return true;
  };
  auto residual_converged = [&](const std::vector<double>& r, const std::vector<double>& floors) {
    return within(r, floors, floor_counts);
  };
  // Why a residual met the test: its tolerance, or a block's round-off floor.
  auto converged_message = [&](const std::vector<double>& r, const std::vector<double>& floors, std::string met) {
    for (int b = 0; b < n_blocks; ++b)
      if (r[b] > tolerance(b))
        return message(met, " at the round-off floor of block '", report.blocks[b], "' (residual ", r[b], ", floor ",
                       floors[b], ", tolerance ", tolerance(b), ")");
    return met;
  };
  // With a tolerance below the floor, the residual of every block within its floor (twice in a row, so that
  // a step that still lands lower is taken) but above its tolerance stagnates there: the solve stops.
  int iterates_at_floor = 0;
  auto at_floor = [&](const std::vector<double>& r, const std::vector<double>& floors) {
    iterates_at_floor = !floor_counts && within(r, floors, true) ? iterates_at_floor + 1 : 0;
    return iterates_at_floor >= 2;
  };
  auto floor_report = [&](const std::vector<double>& r, const std::vector<double>& floors) {
    int worst = 0;
    for (int b = 0; b < n_blocks; ++b)
      if (r[b] / std::max(tolerance(b), 1e-300) > r[worst] / std::max(tolerance(worst), 1e-300)) worst = b;
    return finish(NewtonOutcome::RoundOffFloor,
                  message("the residual of block '", report.blocks[worst], "' (", r[worst],
                          ") stagnates at its round-off floor ", floors[worst], " (", kRoundOffFloorFactor,
                          " eps times the gross size of its terms), above the tolerance ", tolerance(worst),
                          " (relative_tolerance ", options_.relative_tolerance, " times ", reference[worst],
                          "); a relative tolerance below ", min_relative_tolerance(),
                          " cannot be met, and no smaller time step lowers a round-off floor"));
  };
  // Convergence is never declared on a non-finite residual, increment or iterate: each is Diverged,
  // naming the block.
  auto not_finite = [&](const std::vector<double>& block_values, const std::string& what) -> std::optional<NewtonReport> {
    const int b = non_finite_block(block_values);
    if (b < 0) return std::nullopt;
    return finish(NewtonOutcome::Diverged, message(what, " of block '", report.blocks[b], "' is not finite (",
                                                   std::isnan(block_values[b]) ? "its norm is not a number"
                                                                               : "its norm overflows", ")"));
  };
  if (auto r = not_finite(norms, "the initial residual")) return *r;
  if (auto r = not_finite(block_norms(blocks, problem.free_values()), "the initial iterate")) return *r;
  if (auto r = not_finite(scales, "the size of the terms summed in the initial residual")) return *r;
  if (problem.residual().size() == 0) return finish(NewtonOutcome::Converged, "initial state satisfies the tolerances");
  if (const std::vector<double> floors = round_off_floors(); residual_converged(norms, floors))
    return finish(NewtonOutcome::Converged, converged_message(norms, floors, "initial state satisfies the tolerances"));
  else if (at_floor(norms, floors))
    return floor_report(norms, floors);
  const double merit0 = merit(norms, reference);

  // The iterations, on the whole system or on the contact dofs (ReducedContactSystem: the same iterates,
  // with the interior solved once). `system` gives residual(), free values and step(rhs) in its own
  // coordinates, `space` its blocks there. On the contact dofs, a residual that meets the test, a small
  // step, the round-off floor and the last iteration end the iterations without a verdict (nullopt): the
  // whole residual is then assembled and judged. `stagnated` says the floor ended them.
  bool stagnated = false;
  auto iterate = [&](auto& system, const std::vector<ProblemBlock>& space, bool on_contact) -> std::optional<NewtonReport> {
    std::vector<double> norms = block_norms(space, system.residual());
    // Growth past this is divergence. On the contact dofs the first residual is that of the interior
    // solved exactly, which can be far larger than the whole system's first (the paper's strip from rest,
    // its potential not yet in equilibrium: 570 against 8e-6 in v): growth counts from the larger.
    const double divergence_bound = options_.divergence_factor * std::max({merit0, merit(norms, reference), 1.0});
    // Watchdog: the best iterate so far, and the full steps taken since it was last improved on.
    const bool watchdog = options_.line_search && options_.watchdog > 0;
    Eigen::VectorXd best;
    if (watchdog) best = system.free_values();
    double best_merit = merit(norms, reference);
    int since_best = 0;

    for (int iteration = report.iterations + 1; iteration <= options_.max_iterations; ++iteration) {
      report.iterations = iteration;
      bool restarted = false;
      if (watchdog && since_best >= options_.watchdog) {
        system.set_free_values(best);
        system.assemble();
        norms = block_norms(space, system.residual());
        since_best = 0;
        restarted = true;
      }
      Eigen::VectorXd dx;
      try {
        dx = system.step(-system.residual(), report);
      } catch (const Error& e) {
        return finish(NewtonOutcome::SingularTangent, message("iteration ", iteration, ": ", e.what()));
      }
      if (auto r = not_finite(block_norms(space, dx), message("iteration ", iteration, ": the Newton increment"))) return *r;

      // Armijo backtracking on the scaled residual (classical mode, or after a watchdog restart); otherwise
      // the full step, unless it leaves the finite, non-divergent range.
      const bool armijo = options_.line_search && (!watchdog || restarted);
      const double merit_before = merit(norms, reference);
      double alpha = 1, applied = 0;
      int backtracks = 0;
      std::vector<double> new_norms;
      while (true) {
        system.add_to_free_values((alpha - applied) * dx);
        applied = alpha;
        system.assemble();
        new_norms = block_norms(space, system.residual());
        const double m = merit(new_norms, reference);
        const bool accept = !options_.line_search ||
                            (armijo ? std::isfinite(m) && m <= (1 - 2 * options_.armijo * alpha) * merit_before
                                    : std::isfinite(m) && m <= divergence_bound);
        if (accept || backtracks >= options_.max_backtracks) break;
        alpha *= options_.backtrack_factor;
        ++backtracks;
      }
      norms = new_norms;
      const std::vector<double> steps = block_norms(space, alpha * dx);
      report.history.push_back({norms, steps, alpha, backtracks, restarted});
      if (on_iteration_) on_iteration_(report);

      if (auto r = not_finite(norms, message("iteration ", iteration, ": the residual"))) return *r;
      const std::vector<double> sizes = block_norms(space, system.free_values());
      if (auto r = not_finite(sizes, message("iteration ", iteration, ": the iterate"))) return *r;
      const std::vector<double> floors = round_off_floors();
      if (residual_converged(norms, floors))
        return on_contact ? std::nullopt
                          : std::optional(finish(NewtonOutcome::Converged,
                                                 converged_message(norms, floors, "residual tolerance met")));
      bool small_step = alpha == 1;
      for (int b = 0; b < n_blocks; ++b)
        small_step = small_step && steps[b] <= options_.increment_tolerance * std::max(sizes[b], 1e-300);
      if (small_step)
        return on_contact ? std::nullopt : std::optional(finish(NewtonOutcome::Converged, "increment tolerance met"));
      if (at_floor(norms, floors)) {
        stagnated = true;
        return on_contact ? std::nullopt : std::optional(floor_report(norms, floors));
      }
      const double m = merit(norms, reference);
      if (m > divergence_bound)
        return finish(NewtonOutcome::Diverged, message("iteration ", iteration, ": the scaled residual grew by more than ",
                                                       options_.divergence_factor));
      if (m <= (1 - 2 * options_.armijo) * best_merit) {
        best_merit = m;
        if (watchdog) best = system.free_values();
        since_best = 0;
      } else {
        ++since_best;
      }
    }
    if (on_contact) return std::nullopt;
    return finish(NewtonOutcome::MaxIterations, message("no convergence in ", options_.max_iterations, " iterations"));
  };

  // The problem itself, as `iterate` sees a system.
  struct Whole {
    NewtonSolver& solver;
    NonlinearProblem& problem;
    const std::function<void()>& assemble_problem;
    void assemble() { assemble_problem(); }
    const Eigen::VectorXd& residual() const { return problem.residual(); }
    Eigen::VectorXd free_values() const { return problem.free_values(); }
    void set_free_values(const Eigen::VectorXd& x) { problem.set_free_values(x); }
    void add_to_free_values(const Eigen::VectorXd& step) { problem.add_to_free_values(step); }
    Eigen::VectorXd step(const Eigen::VectorXd& rhs, NewtonReport& r) { return solver.step(problem, rhs, r); }
  };
  const std::function<void()> assemble_problem = assemble;
  Whole whole{*this, problem, assemble_problem};

  if (std::unique_ptr<ReducedContactSystem> reduced = reduce_to_contact(problem, report)) {
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
    } on_contact{*reduced, problem, report};
    iterates_at_floor = 0;
    if (auto r = iterate(on_contact, reduced->blocks(), true)) return *r;
    report.contact_iterations = report.iterations;
    // The whole solution at the last contact values, and its residual: the verdict is the whole system's.
    try {
      reduced->expand(report);
    } catch (const Error& e) {
      return finish(NewtonOutcome::SingularTangent, message("iteration ", report.iterations, ": ", e.what()));
    }
    assemble();
    const std::vector<double> verified = block_norms(blocks, problem.residual());
    report.history.back().residual_norms = verified;
    if (auto r = not_finite(verified, message("iteration ", report.iterations, ": the residual"))) return *r;
    const std::vector<double> floors = round_off_floors();
    if (residual_converged(verified, floors))
      return finish(NewtonOutcome::Converged, converged_message(verified, floors, "residual tolerance met"));
    // Stagnated on the contact dofs, and the whole residual is at its floor too: as on the whole system.
    if (stagnated && !floor_counts && within(verified, floors, true)) return floor_report(verified, floors);
    iterates_at_floor = 0;  // the whole system's iterations go on from here
  }
  return *iterate(whole, blocks, false);
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

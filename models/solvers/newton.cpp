#include "models/solvers/newton.hpp"

#include <chrono>
#include <cmath>

#include "assembly/error.hpp"

namespace pc {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Norms of the blocks of a global vector (free dofs of each unknown are numbered consecutively).
std::vector<double> block_norms(const DofLayout& layout, const Eigen::VectorXd& x) {
  std::vector<double> norms;
  int offset = 0;
  for (int f = 0; f < layout.num_fields(); ++f) {
    norms.push_back(x.segment(offset, layout.num_free(f)).norm());
    offset += layout.num_free(f);
  }
  return norms;
}

std::map<std::string, Eigen::VectorXd> unknown_values(const Model& model) {
  std::map<std::string, Eigen::VectorXd> values;
  for (const std::string& u : model.unknowns()) values[u] = model.values(u);
  return values;
}

double merit(const std::vector<double>& norms, const std::vector<double>& reference) {
  double m = 0;
  for (size_t b = 0; b < norms.size(); ++b) m += (norms[b] / reference[b]) * (norms[b] / reference[b]);
  return m;
}

}  // namespace

std::string to_string(NewtonOutcome outcome) {
  switch (outcome) {
    case NewtonOutcome::Converged: return "converged";
    case NewtonOutcome::MaxIterations: return "max_iterations";
    case NewtonOutcome::Diverged: return "diverged";
    case NewtonOutcome::SingularTangent: return "singular_tangent";
  }
  return "unknown";
}

NewtonSolver::NewtonSolver(NewtonOptions options) : options_(std::move(options)) {
  require(options_.max_iterations >= 1, "Newton: max_iterations must be >= 1, got ", options_.max_iterations);
  require(options_.relative_tolerance >= 0 && options_.absolute_tolerance >= 0 && options_.increment_tolerance >= 0,
          "Newton: tolerances must be >= 0");
  require(options_.watchdog >= 0, "Newton: watchdog must be >= 0, got ", options_.watchdog);
  require(options_.backtrack_factor > 0 && options_.backtrack_factor < 1, "Newton: backtrack_factor must be in (0, 1), got ",
          options_.backtrack_factor);
  linear_ = make_linear_solver(options_.linear_solver);
  condensed_ = std::make_unique<CondensedSolve>(condensation_from_string(options_.condensation), options_.linear_solver);
}

Eigen::VectorXd NewtonSolver::full_step(Model& model, NewtonReport& report) {
  const CsrMatrix& J = model.jacobian();
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
  Eigen::VectorXd dx = linear_->solve(-model.residual());
  report.solve_seconds += seconds_since(t);
  return dx;
}

bool NewtonSolver::condensation_applies(Model& model) const {
  if (options_.condensed_max_fraction <= 0) return false;
  if (uncondensable_model_ == &model) return false;
  const double m = double(model.nonlinear_dofs().size());
  // m = 0 (a linear model) also gains: the factorisation of A is kept from step to step.
  return m <= options_.condensed_max_fraction * model.layout().size();
}

Eigen::VectorXd NewtonSolver::condensed_step(Model& model, NewtonReport& report) {
  report.condensed = true;
  try {
    return condensed_->step(model, -model.residual(), report);
  } catch (const Error&) {
    // The linear part (or, for the Schur method, its interior) is singular: solve in full from now on;
    // a genuinely singular J then fails there with the solver's message.
    uncondensable_model_ = &model;
    report.condensed = false;
    return full_step(model, report);
  }
}

NewtonReport NewtonSolver::solve(Model& model) {
  const auto start = Clock::now();
  NewtonReport report;
  auto assemble = [&] {
    const auto t = Clock::now();
    model.assemble(true);
    report.assembly_seconds += seconds_since(t);
  };
  auto finish = [&](NewtonOutcome outcome, std::string message) {
    report.outcome = outcome;
    report.message = std::move(message);
    report.diagnostics = model.diagnostics();
    report.total_seconds = seconds_since(start);
    return report;
  };

  assemble();
  const DofLayout& layout = model.layout();
  for (int f = 0; f < layout.num_fields(); ++f) report.blocks.push_back(layout.field_name(f));
  const int n_blocks = layout.num_fields();
  std::vector<double> absolute(n_blocks, options_.absolute_tolerance);
  for (int b = 0; b < n_blocks; ++b)
    if (options_.absolute_tolerances.count(report.blocks[b])) absolute[b] = options_.absolute_tolerances.at(report.blocks[b]);

  std::vector<double> norms = block_norms(layout, model.residual());
  report.history.push_back({norms, {}, 0, 0});
  // Reference of each block: its first residual (or its absolute tolerance, if that is larger), so that
  // the merit function weighs the blocks alike whatever their units.
  std::vector<double> reference(n_blocks);
  for (int b = 0; b < n_blocks; ++b)
    reference[b] = std::max({norms[b], model.residual_scales().at(report.blocks[b]), absolute[b], 1e-300});
  auto residual_converged = [&](const std::vector<double>& r) {
    for (int b = 0; b < n_blocks; ++b)
      if (r[b] > std::max(absolute[b], options_.relative_tolerance * reference[b])) return false;
    return true;
  };
  if (!model.residual().allFinite()) return finish(NewtonOutcome::Diverged, "the initial residual is not finite");
  if (residual_converged(norms) || layout.size() == 0) return finish(NewtonOutcome::Converged, "initial state satisfies the tolerances");
  const double merit0 = merit(norms, reference);
  const double divergence_bound = options_.divergence_factor * std::max(merit0, 1.0);

  // Watchdog: the best iterate so far, and the full steps taken since it was last improved on.
  const bool watchdog = options_.line_search && options_.watchdog > 0;
  std::map<std::string, Eigen::VectorXd> best;
  if (watchdog) best = unknown_values(model);
  double best_merit = merit0;
  int since_best = 0;

  for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
    report.iterations = iteration;
    bool restarted = false;
    if (watchdog && since_best >= options_.watchdog) {
      for (const auto& [name, values] : best) model.set_values(name, values);
      assemble();
      norms = block_norms(layout, model.residual());
      since_best = 0;
      restarted = true;
    }
    Eigen::VectorXd dx;
    try {
      dx = condensation_applies(model) ? condensed_step(model, report) : full_step(model, report);
    } catch (const Error& e) {
      return finish(NewtonOutcome::SingularTangent, message("iteration ", iteration, ": ", e.what()));
    }
    if (!dx.allFinite()) return finish(NewtonOutcome::SingularTangent, message("iteration ", iteration, ": the Newton step is not finite"));

    // Armijo backtracking on the scaled residual (classical mode, or after a watchdog restart); otherwise
    // the full step, unless it leaves the finite, non-divergent range.
    const bool armijo = options_.line_search && (!watchdog || restarted);
    const double merit_before = merit(norms, reference);
    double alpha = 1, applied = 0;
    int backtracks = 0;
    std::vector<double> new_norms;
    while (true) {
      model.add_to_free_values((alpha - applied) * dx);
      applied = alpha;
      assemble();
      new_norms = block_norms(layout, model.residual());
      const double m = merit(new_norms, reference);
      const bool accept = !options_.line_search ||
                          (armijo ? std::isfinite(m) && m <= (1 - 2 * options_.armijo * alpha) * merit_before
                                  : std::isfinite(m) && m <= divergence_bound);
      if (accept || backtracks >= options_.max_backtracks) break;
      alpha *= options_.backtrack_factor;
      ++backtracks;
    }
    norms = new_norms;
    const std::vector<double> steps = block_norms(layout, alpha * dx);
    report.history.push_back({norms, steps, alpha, backtracks, restarted});

    if (!model.residual().allFinite())
      return finish(NewtonOutcome::Diverged, message("iteration ", iteration, ": the residual is not finite"));
    if (residual_converged(norms)) return finish(NewtonOutcome::Converged, "residual tolerance met");
    const std::vector<double> sizes = block_norms(layout, model.free_values());
    bool small_step = alpha == 1;
    for (int b = 0; b < n_blocks; ++b)
      small_step = small_step && steps[b] <= options_.increment_tolerance * std::max(sizes[b], 1e-300);
    if (small_step) return finish(NewtonOutcome::Converged, "increment tolerance met");
    const double m = merit(norms, reference);
    if (m > divergence_bound)
      return finish(NewtonOutcome::Diverged, message("iteration ", iteration, ": the scaled residual grew by more than ",
                                                     options_.divergence_factor));
    if (m <= (1 - 2 * options_.armijo) * best_merit) {
      best_merit = m;
      if (watchdog) best = unknown_values(model);
      since_best = 0;
    } else {
      ++since_best;
    }
  }
  return finish(NewtonOutcome::MaxIterations, message("no convergence in ", options_.max_iterations, " iterations"));
}

}  // namespace pc

#include "models/newton.hpp"

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
  require(options_.backtrack_factor > 0 && options_.backtrack_factor < 1, "Newton: backtrack_factor must be in (0, 1), got ",
          options_.backtrack_factor);
  linear_ = make_linear_solver(options_.linear_solver);
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

  for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
    report.iterations = iteration;
    const CsrMatrix& J = model.jacobian();
    Eigen::VectorXd dx;
    try {
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
      t = Clock::now();
      dx = linear_->solve(-model.residual());
      report.solve_seconds += seconds_since(t);
    } catch (const Error& e) {
      return finish(NewtonOutcome::SingularTangent, message("iteration ", iteration, ": ", e.what()));
    }
    if (!dx.allFinite()) return finish(NewtonOutcome::SingularTangent, message("iteration ", iteration, ": the Newton step is not finite"));

    // Backtracking on the scaled residual: accept alpha when the merit drops by the Armijo fraction.
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
      const bool accept = !options_.line_search || (std::isfinite(m) && m <= (1 - 2 * options_.armijo * alpha) * merit_before);
      if (accept || backtracks >= options_.max_backtracks) break;
      alpha *= options_.backtrack_factor;
      ++backtracks;
    }
    norms = new_norms;
    const std::vector<double> steps = block_norms(layout, alpha * dx);
    report.history.push_back({norms, steps, alpha, backtracks});

    if (!model.residual().allFinite())
      return finish(NewtonOutcome::Diverged, message("iteration ", iteration, ": the residual is not finite"));
    if (residual_converged(norms)) return finish(NewtonOutcome::Converged, "residual tolerance met");
    const std::vector<double> sizes = block_norms(layout, model.free_values());
    bool small_step = alpha == 1;
    for (int b = 0; b < n_blocks; ++b)
      small_step = small_step && steps[b] <= options_.increment_tolerance * std::max(sizes[b], 1e-300);
    if (small_step) return finish(NewtonOutcome::Converged, "increment tolerance met");
    if (merit(norms, reference) > options_.divergence_factor * merit0)
      return finish(NewtonOutcome::Diverged, message("iteration ", iteration, ": the scaled residual grew by more than ",
                                                     options_.divergence_factor));
  }
  return finish(NewtonOutcome::MaxIterations, message("no convergence in ", options_.max_iterations, " iterations"));
}

}  // namespace pc

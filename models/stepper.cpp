#include "models/stepper.hpp"

#include <chrono>
#include <cmath>
#include <map>

#include "assembly/error.hpp"

namespace pc {
namespace {

std::map<std::string, Eigen::VectorXd> save_unknowns(const Model& model) {
  std::map<std::string, Eigen::VectorXd> saved;
  for (const std::string& u : model.unknowns()) saved[u] = model.values(u);
  return saved;
}

void restore_unknowns(Model& model, const std::map<std::string, Eigen::VectorXd>& saved) {
  for (const auto& [name, values] : saved) model.set_values(name, values);
}

}  // namespace

Stepper::Stepper(StepperOptions options) : options_(std::move(options)) {
  const StepperOptions& o = options_;
  require(std::isfinite(o.start) && std::isfinite(o.end) && o.end > o.start, "time span: end (", o.end,
          ") must be finite and after start (", o.start, ")");
  require(std::isfinite(o.step) && o.step > 0, "time step must be positive and finite, got ", o.step);
  require(o.cutback_factor > 0 && o.cutback_factor < 1, "cutback_factor must be in (0, 1), got ", o.cutback_factor);
  require(o.growth_factor >= 1, "growth_factor must be >= 1, got ", o.growth_factor);
  require(o.output_every >= 1, "output_every must be >= 1, got ", o.output_every);
  require(o.max_attempts >= 0, "max_attempts must be >= 0 (0: no limit), got ", o.max_attempts);
  require(std::isfinite(o.max_wall_seconds) && o.max_wall_seconds >= 0,
          "max_wall_seconds must be finite and >= 0 (0: no limit), got ", o.max_wall_seconds);
  if (options_.min_step <= 0) options_.min_step = o.step * 1e-6;
}

RunSummary Stepper::run(Model& model, TimeScheme& scheme, NewtonSolver& newton, const StepperCallbacks& callbacks) {
  const auto start = std::chrono::steady_clock::now();
  RunSummary summary;
  const StepperOptions& o = options_;
  model.set_time(o.start);
  model.apply_dirichlet();

  StepRecord record;
  record.time = o.start;
  if (callbacks.on_start) {
    record.newton = callbacks.on_start(model);
    if (!record.newton.converged()) {
      summary.message = "the solve at the start did not converge: " + record.newton.message;
      return summary;
    }
  }
  if (callbacks.on_output) callbacks.on_output(model, record);

  const double tiny = 1e-12 * (o.end - o.start);
  double t = o.start, dt = o.step;
  int successes = 0, attempts = 0;
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  while (t < o.end - tiny) {
    if (o.max_attempts > 0 && attempts >= o.max_attempts) {
      summary.message = message("stopped at t = ", t, " after ", attempts, " step attempts (", summary.steps,
                                " accepted): the limit max_attempts = ", o.max_attempts, " was reached");
      break;
    }
    if (o.stop_requested) {
      if (const std::string reason = o.stop_requested(); !reason.empty()) {
        summary.message = message("stopped at t = ", t, " after ", summary.steps, " steps: ", reason);
        break;
      }
    }
    if (o.max_wall_seconds > 0 && elapsed() >= o.max_wall_seconds) {
      summary.message = message("stopped at t = ", t, " after ", summary.steps, " steps: the wall-time limit of ",
                                o.max_wall_seconds, " s was reached");
      break;
    }
    ++attempts;
    // The last step lands on `end`; a remainder within round-off of dt is dt itself, so that a run of equal
    // steps keeps one step size to the end (a new size would refactorise the linear part).
    const double remaining = o.end - t;
    const double attempt = remaining < dt - tiny ? remaining : dt;
    const auto saved = save_unknowns(model);
    scheme.begin_step(model, attempt);
    model.set_time(t + attempt);
    if (o.prediction == Prediction::Zero)
      model.set_values(scheme.fields().velocity, Eigen::VectorXd::Zero(model.space(scheme.fields().velocity).num_dofs()));
    model.apply_dirichlet();
    NewtonReport report = newton.solve(model);
    summary.newton_iterations_total += report.iterations;
    if (!report.converged()) {
      restore_unknowns(model, saved);
      model.set_time(t);
      const std::string failed =
          message("step from t = ", t, " failed (", to_string(report.outcome), ": ", report.message, ")");
      // A residual at its round-off floor above the tolerance stays there at any step size: no cut-back.
      if (report.outcome == NewtonOutcome::RoundOffFloor) {
        summary.message = failed + "; the run stops without cutting the step back";
        break;
      }
      ++record.cutbacks;
      ++summary.cutbacks;
      successes = 0;
      dt = attempt * o.cutback_factor;
      if (dt < o.min_step) {
        summary.message = message(failed, " and the step would fall below the floor ", o.min_step);
        break;
      }
      continue;
    }
    scheme.end_step(model, attempt);
    t = remaining <= dt + tiny ? o.end : t + attempt;
    ++summary.steps;
    summary.newton_iterations_max_per_step = std::max(summary.newton_iterations_max_per_step, report.iterations);
    record.step = summary.steps;
    record.time = t;
    record.dt = attempt;
    record.newton = std::move(report);
    if (callbacks.on_step) callbacks.on_step(model, record);
    const bool last = t >= o.end - tiny;
    if (callbacks.on_output && (record.step % o.output_every == 0 || last)) callbacks.on_output(model, record);
    record.cutbacks = 0;
    if (++successes >= o.successes_before_growth && dt < o.step) {
      dt = std::min(o.step, dt * o.growth_factor);
      successes = 0;
    }
  }
  summary.completed = t >= o.end - tiny;
  summary.wall_seconds = elapsed();
  return summary;
}

}  // namespace pc

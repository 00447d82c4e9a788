#include "models/stepper.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <limits>
#include <optional>

#include "assembly/error.hpp"
#include "assembly/processes.hpp"
#include "models/model_state.hpp"

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

// The local error of a step over the tolerance: accepted at most 1.
double error_ratio(const TimeErrorReport& e, const AdaptiveSteps& a, TimeErrorPropagation p,
                   const std::string& displacement) {
  double local = 0;
  if (p == TimeErrorPropagation::Linearised) {
    local = e.max_local();
  } else {
    const FieldTimeError* u = e.field(displacement);
    require(u != nullptr, "adaptive time steps: the time error estimate has no field '", displacement,
            "' (the scheme's displacement)");
    local = u->local;
  }
  return local / a.tolerance;
}

// Gustafsson's PI controller for an error per step (error ~ k^(p+1)): the factor on the step size after
// an accepted step with error ratio `ratio`, the last one's being `last` (0: none yet).
double controller_factor(const AdaptiveSteps& a, int p, double ratio, double last) {
  if (ratio <= 0) return a.max_growth;  // no error at all (a solution the scheme integrates exactly)
  const double q = p + 1;
  double factor = a.safety * std::pow(1.0 / ratio, 0.3 / q);
  factor *= last > 0 ? std::pow(last / ratio, 0.4 / q) : std::pow(1.0 / ratio, 0.4 / q);
  return std::clamp(factor, a.max_cut, a.max_growth);
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
  require(o.checkpoint_every >= 0, "checkpoint_every must be >= 0 (0: only at a stop), got ", o.checkpoint_every);
  require(o.max_attempts >= 0, "max_attempts must be >= 0 (0: no limit), got ", o.max_attempts);
  if (o.adaptive) {
    const AdaptiveSteps& a = *o.adaptive;
    require(o.estimate_time_error, "adaptive time steps need the time error estimate (estimate_time_error)");
    require(std::isfinite(a.tolerance) && a.tolerance > 0 && a.tolerance < 1,
            "adaptive time steps: the tolerance must be in (0, 1), got ", a.tolerance);
    require(std::isfinite(a.max_step) && a.max_step >= 0, "adaptive time steps: max_step must be >= 0 (0: a tenth of "
            "the span), got ", a.max_step);
    require(a.safety > 0 && a.safety <= 1, "adaptive time steps: safety must be in (0, 1], got ", a.safety);
    require(a.max_growth > 1 && a.max_growth <= 2, "adaptive time steps: max_growth must be in (1, 2], got ",
            a.max_growth);
    require(a.max_cut > 0 && a.max_cut < 1, "adaptive time steps: max_cut must be in (0, 1), got ", a.max_cut);
    require(std::isfinite(a.factorization_cost) && a.factorization_cost >= 0,
            "adaptive time steps: factorization_cost must be >= 0, got ", a.factorization_cost);
    if (a.max_step <= 0) options_.adaptive->max_step = (o.end - o.start) / 10;
  }
  require(std::isfinite(o.max_wall_seconds) && o.max_wall_seconds >= 0,
          "max_wall_seconds must be finite and >= 0 (0: no limit), got ", o.max_wall_seconds);
  if (options_.min_step <= 0) options_.min_step = o.step * 1e-6;
}

double Stepper::controlled_first_step(Model& model, TimeScheme& scheme, NewtonSolver& newton, StepperState& state) const {
  const AdaptiveSteps& a = *options_.adaptive;
  Checkpoint start;
  save_model_state(model, scheme, start);
  StepperOptions probe = options_;
  probe.adaptive->control_first_step = false;
  probe.adaptive->tolerance = 0.999;  // the probe judges the start itself: its second step is not rejected
  probe.checkpoint_every = 0;
  probe.max_wall_seconds = 0;
  probe.resume.reset();
  double first = std::min(options_.step, a.max_step);
  double best = first, best_ratio = std::numeric_limits<double>::infinity();
  // Two accepted steps: the second's estimate covers the first (backward Euler's, and BDF2's start).
  for (int probes = 0; probes < 50; ++probes) {
    probe.step = first;
    probe.end = std::min(options_.end, options_.start + 2.5 * first);
    probe.max_attempts = 2;
    const RunSummary r = Stepper(probe).run(model, scheme, newton);
    restore_model_state(model, scheme, start);
    state.attempts += r.state.attempts;
    state.newton_iterations_total += r.newton_iterations_total;
    // Not judged (a Newton failure cut a probe's step, or the span is one step): the run's own cut-back
    // and controller take it from here.
    if (r.steps < 2) break;
    const double ratio = r.time_error.max_global() / a.tolerance;
    // A smaller step that does not lower the error has met the estimate's floor (Newton's tolerance,
    // divided by the steps' squares in the divided difference): the best step before it is kept.
    if (ratio >= best_ratio) break;
    best = first;
    best_ratio = ratio;
    if (ratio <= 1 || first <= options_.min_step) break;
    first = std::max(options_.min_step, first * std::clamp(a.safety * std::pow(1.0 / ratio, 0.5), a.max_cut, 0.9));
  }
  return best;
}

RunSummary Stepper::run(Model& model, TimeScheme& scheme, NewtonSolver& newton, const StepperCallbacks& callbacks) {
  const auto start = std::chrono::steady_clock::now();
  RunSummary summary;
  const StepperOptions& o = options_;
  std::optional<TimeErrorEstimator> estimator;
  if (o.estimate_time_error) {
    estimator.emplace(model, scheme, o.time_error_propagation, o.time_error_fields);
    estimator->set_filter_local_errors(o.adaptive.has_value());
  }
  // The linearised estimate's solves, with the tangent of the step just solved; their cost is the step's.
  LinearSolveCost estimate_cost;
  const TimeErrorEstimator::TangentSolve tangent_solve = [&](const Eigen::VectorXd& rhs) {
    return newton.solve_tangent(model, rhs, estimate_cost);
  };
  const TimeErrorEstimator::TangentSolve* solve =
      o.time_error_propagation == TimeErrorPropagation::Linearised ? &tangent_solve : nullptr;
  StepRecord record;
  StepperState& state = record.state;
  if (o.resume) {
    state = *o.resume;
    require(std::isfinite(state.time) && state.time >= o.start && state.time <= o.end && state.step_size > 0,
            "resume: the saved time ", state.time, " or step size ", state.step_size, " does not fit the run's span [",
            o.start, ", ", o.end, "]");
    model.set_time(state.time);
    // A checkpoint of a run without the estimate (or of an older version) starts it afresh here.
    if (estimator && state.time_error.times.empty()) state.time_error = estimator->start(model);
    record.step = state.steps;
    record.time = state.time;
  } else {
    state.time = o.start;
    state.step_size = o.step;
    model.set_time(o.start);
    model.apply_dirichlet();
    record.time = o.start;
    if (callbacks.on_start) {
      record.newton = callbacks.on_start(model);
      if (!record.newton.converged()) {
        summary.message = "the solve at the start did not converge: " + record.newton.message;
        summary.state = state;
        return summary;
      }
    }
    if (estimator) state.time_error = estimator->start(model);
    if (o.adaptive && o.adaptive->control_first_step) state.step_size = controlled_first_step(model, scheme, newton, state);
    processes::run_agreed("the initial output", [&] {
      if (callbacks.on_output) callbacks.on_output(model, record);
    });
  }

  const double tiny = 1e-12 * (o.end - o.start);
  double& t = state.time;
  double& dt = state.step_size;
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  while (t < o.end - tiny) {
    if (o.max_attempts > 0 && state.attempts >= o.max_attempts) {
      summary.message = message("stopped at t = ", t, " after ", state.attempts, " step attempts (", state.steps,
                                " accepted): the limit max_attempts = ", o.max_attempts, " was reached");
      break;
    }
    std::string stop;
    if (o.stop_requested) stop = o.stop_requested();
    if (stop.empty() && o.max_wall_seconds > 0 && elapsed() >= o.max_wall_seconds)
      stop = message("the wall-time limit of ", o.max_wall_seconds, " s was reached");
    // The processes of a distributed run stop together, at the same step, whichever of them was asked to.
    if (processes::any(!stop.empty())) {
      if (stop.empty()) stop = "another process of the run was stopped (a signal, or its wall-time limit)";
      summary.message = message("stopped at t = ", t, " after ", state.steps, " steps: ", stop);
      break;
    }
    ++state.attempts;
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
    state.newton_iterations_total += report.iterations;
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
      ++state.cutbacks;
      record.cut_back_cost += report;
      record.cut_back_assembly_seconds += report.assembly_seconds;
      state.successes = 0;
      dt = attempt * o.cutback_factor;
      if (dt < o.min_step) {
        summary.message = message(failed, " and the step would fall below the floor ", o.min_step);
        dt = attempt;  // a resumed run retries this step as it was
        break;
      }
      continue;
    }
    std::optional<TimeErrorStep> estimate;
    if (estimator) {
      estimate_cost = {};
      const auto started = std::chrono::steady_clock::now();
      estimate = estimator->evaluate(model, scheme.local_error_term(attempt), state.time_error, solve);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      static_cast<LinearSolveCost&>(report) += estimate_cost;
      report.assembly_seconds += std::max(0.0, seconds - (estimate_cost.analyze_seconds + estimate_cost.factorize_seconds +
                                                          estimate_cost.solve_seconds + estimate_cost.condensation_seconds));
    }
    double ratio = 0;  // adaptive: the step's error over the tolerance
    if (o.adaptive && estimate->report.estimated) {
      const AdaptiveSteps& a = *o.adaptive;
      ratio = error_ratio(estimate->report, a, o.time_error_propagation, scheme.fields().displacement);
      // Above the tolerance: retried smaller, unless it is at the floor already (then kept, as the best
      // the floor allows).
      if (ratio > 1 && attempt > o.min_step * (1 + 1e-12)) {
        restore_unknowns(model, saved);
        model.set_time(t);
        ++record.rejections;
        ++state.rejections;
        record.cut_back_cost += report;
        record.cut_back_assembly_seconds += report.assembly_seconds;
        const double factor = std::clamp(a.safety * std::pow(1.0 / ratio, 1.0 / (estimate->report.order + 1)), a.max_cut, 0.9);
        dt = std::max(o.min_step, attempt * factor);
        continue;
      }
    }
    scheme.end_step(model, attempt);
    t = remaining <= dt + tiny ? o.end : t + attempt;
    ++state.steps;
    state.newton_iterations_max_per_step = std::max(state.newton_iterations_max_per_step, report.iterations);
    if (estimate) {
      record.time_error = estimate->report;
      TimeErrorEstimator::commit(std::move(*estimate), state.time_error);
    }
    if (o.adaptive) {
      if (record.time_error.estimated) {
        const AdaptiveSteps& a = *o.adaptive;
        double factor = controller_factor(a, record.time_error.order, ratio, state.last_error);
        // No growth right after a rejection (Hairer and Wanner's rule): the error is rising faster than
        // the controller's model of it, and a larger step would be rejected again.
        if (record.rejections > 0) factor = std::min(factor, 1.0);
        state.last_error = ratio;
        const double proposed = std::clamp(attempt * factor, o.min_step, a.max_step);
        // A larger step pays when the steps it saves over the rest of the run outweigh a factorisation.
        const double saved_steps = (o.end - t) / attempt * (1 - attempt / proposed);
        if (proposed < attempt || saved_steps > a.factorization_cost) dt = proposed;
        else dt = std::max(dt, attempt);  // the last step may have been shortened to land on `end`
      }
    } else if (++state.successes >= o.successes_before_growth && dt < o.step) {
      dt = std::min(o.step, dt * o.growth_factor);
      state.successes = 0;
    }
    record.step = state.steps;
    record.time = t;
    record.dt = attempt;
    record.newton = std::move(report);
    // The callbacks write results, on one process of a distributed run for most of them: a failure there
    // (a full disk) is agreed, so that every process stops with it.
    processes::run_agreed("the step's results", [&] {
      if (callbacks.on_step) callbacks.on_step(model, record);
    });
    const bool last = t >= o.end - tiny;
    if (record.step % o.output_every == 0 || last)
      processes::run_agreed("the step's output", [&] {
        if (callbacks.on_output) callbacks.on_output(model, record);
      });
    if (o.checkpoint_every > 0 && record.step % o.checkpoint_every == 0 && !last)
      processes::run_agreed("the checkpoint", [&] {
        if (callbacks.on_checkpoint) callbacks.on_checkpoint(model, state);
      });
    record.cutbacks = 0;
    record.rejections = 0;
    record.cut_back_cost = {};
    record.cut_back_assembly_seconds = 0;
  }
  summary.completed = t >= o.end - tiny;
  if (!summary.completed)
    processes::run_agreed("the checkpoint", [&] {
      if (callbacks.on_checkpoint) callbacks.on_checkpoint(model, state);
    });
  summary.steps = state.steps;
  summary.newton_iterations_total = state.newton_iterations_total;
  summary.newton_iterations_max_per_step = state.newton_iterations_max_per_step;
  summary.cutbacks = state.cutbacks;
  summary.rejections = state.rejections;
  summary.time_error = record.time_error;
  summary.wall_seconds = elapsed();
  summary.state = state;
  return summary;
}

}  // namespace pc

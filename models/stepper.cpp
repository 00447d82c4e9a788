#include "models/stepper.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "assembly/error.hpp"
#include "assembly/processes.hpp"
#include "models/model_state.hpp"

namespace pc {
namespace {

// The values of a model's unknowns, to put an attempt back.
using Unknowns = std::map<std::string, Eigen::VectorXd>;

Unknowns save_unknowns(const Model& model) {
  Unknowns saved;
  for (const std::string& u : model.unknowns()) saved[u] = model.values(u);
  return saved;
}

void restore_unknowns(Model& model, const Unknowns& saved) {
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
    require(std::isfinite(a.max_step) && a.max_step >= 0,
            "adaptive time steps: max_step must be >= 0 (0: a tenth of "
            "the span), got ",
            a.max_step);
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

double Stepper::controlled_first_step(Model& model, TimeScheme& scheme, NewtonSolver& newton,
                                      StepperState& state) const {
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

// One call of run(): the model and solvers it steps, the time error estimator, the record of the step in
// progress (whose state is the run's) and the phases.
struct Stepper::Run {
  // Sets the time error estimator up.
  Run(const Stepper& stepper, Model& model, TimeScheme& scheme, NewtonSolver& newton,
      const StepperCallbacks& callbacks);
  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); }
  // From a stopped run's state (StepperOptions::resume): no start hook and no output of step 0.
  void resume();
  // From options.start: its Dirichlet values, the start hook, the first step's size and the output of step 0.
  // False when the start hook's solve did not converge (the summary says so).
  bool start();
  // A budget or a stop request ends the run before the next attempt: the summary's message says which.
  bool stopped();
  // One step attempt from the current time: cut back if Newton fails, rejected if its error is too large,
  // else accepted with its results written. False when the run stops there.
  bool attempt_step();
  // The step of size `attempt` set up and solved.
  NewtonReport solve_step(double attempt);
  // A failed step: the next attempt smaller. False when no smaller step can mend it.
  bool cut_back(const NewtonReport& report, double attempt, const Unknowns& saved);
  // The step's time error estimate, its cost added to the step's report; none without the estimator.
  std::optional<TimeErrorStep> estimate_error(NewtonReport& report, double attempt);
  // A step whose error is above the tolerance: retried smaller, by the controller's factor for its order.
  void reject(const NewtonReport& report, double attempt, double ratio, int order, const Unknowns& saved);
  // The model back at the last accepted step, and the discarded attempt's work counted as the next step's.
  void put_back(const Unknowns& saved);
  void count_discarded(const NewtonReport& report);
  // The step of size `attempt` taken: the time, the counts and the estimate's history move on.
  void accept(double attempt, double remaining, std::optional<TimeErrorStep>& estimate, int iterations);
  // The size the next attempt tries after an accepted step: the controller's, or regrowth toward options.step.
  void next_step_size(double attempt, double ratio);
  // The accepted step's record, given to the step, output and checkpoint callbacks.
  void write_step(double attempt, NewtonReport report);
  void output(const std::string& what);
  void checkpoint();
  // Where the run ended, with a checkpoint if it stopped before its end.
  RunSummary summarise();

  const Stepper& stepper;
  const StepperOptions& o;
  Model& model;
  TimeScheme& scheme;
  NewtonSolver& newton;
  const StepperCallbacks& callbacks;
  const std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
  RunSummary summary;
  std::optional<TimeErrorEstimator> estimator;
  // The linearised estimate's solves, with the tangent of the step just solved; their cost is the step's.
  LinearSolveCost estimate_cost;
  TimeErrorEstimator::TangentSolve tangent_solve;
  const TimeErrorEstimator::TangentSolve* solve = nullptr;
  StepRecord record;
  StepperState& state = record.state;
  const double tiny = 1e-12 * (o.end - o.start);
};

Stepper::Run::Run(const Stepper& stepper, Model& model, TimeScheme& scheme, NewtonSolver& newton,
                  const StepperCallbacks& callbacks)
    : stepper(stepper), o(stepper.options_), model(model), scheme(scheme), newton(newton), callbacks(callbacks) {
  if (o.estimate_time_error) {
    estimator.emplace(model, scheme, o.time_error_propagation, o.time_error_fields);
    estimator->set_filter_local_errors(o.adaptive.has_value());
  }
  tangent_solve = [this](const Eigen::VectorXd& rhs) {
    return this->newton.solve_tangent(this->model, rhs, estimate_cost);
  };
  solve = o.time_error_propagation == TimeErrorPropagation::Linearised ? &tangent_solve : nullptr;
}

void Stepper::Run::resume() {
  state = *o.resume;
  require(std::isfinite(state.time) && state.time >= o.start && state.time <= o.end && state.step_size > 0,
          "resume: the saved time ", state.time, " or step size ", state.step_size, " does not fit the run's span [",
          o.start, ", ", o.end, "]");
  model.set_time(state.time);
  // A checkpoint of a run without the estimate (or of an older version) starts it afresh here.
  if (estimator && state.time_error.times.empty()) state.time_error = estimator->start(model);
  record.step = state.steps;
  record.time = state.time;
}

bool Stepper::Run::start() {
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
      return false;
    }
  }
  if (estimator) state.time_error = estimator->start(model);
  if (o.adaptive && o.adaptive->control_first_step)
    state.step_size = stepper.controlled_first_step(model, scheme, newton, state);
  output("the initial output");
  return true;
}

bool Stepper::Run::stopped() {
  if (o.max_attempts > 0 && state.attempts >= o.max_attempts) {
    summary.message = message("stopped at t = ", state.time, " after ", state.attempts, " step attempts (", state.steps,
                              " accepted): the limit max_attempts = ", o.max_attempts, " was reached");
    return true;
  }
  std::string stop;
  if (o.stop_requested) stop = o.stop_requested();
  if (stop.empty() && o.max_wall_seconds > 0 && elapsed() >= o.max_wall_seconds)
    stop = message("the wall-time limit of ", o.max_wall_seconds, " s was reached");
  // The processes of a distributed run stop together, at the same step, whichever of them was asked to.
  if (processes::any(!stop.empty())) {
    if (stop.empty()) stop = "another process of the run was stopped (a signal, or its wall-time limit)";
    summary.message = message("stopped at t = ", state.time, " after ", state.steps, " steps: ", stop);
    return true;
  }
  return false;
}

bool Stepper::Run::attempt_step() {
  ++state.attempts;
  // The last step lands on `end`; a remainder within round-off of dt is dt itself, so that a run of equal
  // steps keeps one step size to the end (a new size would refactorise the linear part).
  const double remaining = o.end - state.time;
  const double attempt = remaining < state.step_size - tiny ? remaining : state.step_size;
  const Unknowns saved = save_unknowns(model);
  NewtonReport report = solve_step(attempt);
  if (!report.converged()) return cut_back(report, attempt, saved);
  std::optional<TimeErrorStep> estimate = estimate_error(report, attempt);
  double ratio = 0;  // adaptive: the step's error over the tolerance
  if (o.adaptive && estimate->report.estimated) {
    ratio = error_ratio(estimate->report, *o.adaptive, o.time_error_propagation, scheme.fields().displacement);
    // Above the tolerance: retried smaller, unless it is at the floor already (then kept, as the best
    // the floor allows).
    if (ratio > 1 && attempt > o.min_step * (1 + 1e-12)) {
      reject(report, attempt, ratio, estimate->report.order, saved);
      return true;
    }
  }
  accept(attempt, remaining, estimate, report.iterations);
  next_step_size(attempt, ratio);
  write_step(attempt, std::move(report));
  return true;
}

NewtonReport Stepper::Run::solve_step(double attempt) {
  scheme.begin_step(model, attempt);
  model.set_time(state.time + attempt);
  if (o.prediction == Prediction::Zero)
    model.set_values(scheme.fields().velocity, Eigen::VectorXd::Zero(model.space(scheme.fields().velocity).num_dofs()));
  model.apply_dirichlet();
  NewtonReport report = newton.solve(model);
  state.newton_iterations_total += report.iterations;
  return report;
}

bool Stepper::Run::cut_back(const NewtonReport& report, double attempt, const Unknowns& saved) {
  put_back(saved);
  const std::string failed =
      message("step from t = ", state.time, " failed (", to_string(report.outcome), ": ", report.message, ")");
  // A residual at its round-off floor above the tolerance stays there at any step size: no cut-back.
  if (report.outcome == NewtonOutcome::RoundOffFloor) {
    summary.message = failed + "; the run stops without cutting the step back";
    return false;
  }
  ++record.cutbacks;
  ++state.cutbacks;
  count_discarded(report);
  state.successes = 0;
  state.step_size = attempt * o.cutback_factor;
  if (state.step_size < o.min_step) {
    summary.message = message(failed, " and the step would fall below the floor ", o.min_step);
    state.step_size = attempt;  // a resumed run retries this step as it was
    return false;
  }
  return true;
}

std::optional<TimeErrorStep> Stepper::Run::estimate_error(NewtonReport& report, double attempt) {
  if (!estimator) return std::nullopt;
  estimate_cost = {};
  const auto begun = std::chrono::steady_clock::now();
  std::optional<TimeErrorStep> estimate =
      estimator->evaluate(model, scheme.local_error_term(attempt), state.time_error, solve);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
  static_cast<LinearSolveCost&>(report) += estimate_cost;
  report.assembly_seconds +=
      std::max(0.0, seconds - (estimate_cost.analyze_seconds + estimate_cost.factorize_seconds +
                               estimate_cost.solve_seconds + estimate_cost.condensation_seconds));
  return estimate;
}

void Stepper::Run::reject(const NewtonReport& report, double attempt, double ratio, int order, const Unknowns& saved) {
  const AdaptiveSteps& a = *o.adaptive;
  put_back(saved);
  ++record.rejections;
  ++state.rejections;
  count_discarded(report);
  const double factor = std::clamp(a.safety * std::pow(1.0 / ratio, 1.0 / (order + 1)), a.max_cut, 0.9);
  state.step_size = std::max(o.min_step, attempt * factor);
}

void Stepper::Run::put_back(const Unknowns& saved) {
  restore_unknowns(model, saved);
  model.set_time(state.time);
}

void Stepper::Run::count_discarded(const NewtonReport& report) {
  record.cut_back_cost += report;
  record.cut_back_assembly_seconds += report.assembly_seconds;
}

void Stepper::Run::accept(double attempt, double remaining, std::optional<TimeErrorStep>& estimate, int iterations) {
  scheme.end_step(model, attempt);
  state.time = remaining <= state.step_size + tiny ? o.end : state.time + attempt;
  ++state.steps;
  state.newton_iterations_max_per_step = std::max(state.newton_iterations_max_per_step, iterations);
  if (estimate) {
    record.time_error = estimate->report;
    TimeErrorEstimator::commit(std::move(*estimate), state.time_error);
  }
}

void Stepper::Run::next_step_size(double attempt, double ratio) {
  double& dt = state.step_size;
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
      const double saved_steps = (o.end - state.time) / attempt * (1 - attempt / proposed);
      if (proposed < attempt || saved_steps > a.factorization_cost)
        dt = proposed;
      else
        dt = std::max(dt, attempt);  // the last step may have been shortened to land on `end`
    }
  } else if (++state.successes >= o.successes_before_growth && dt < o.step) {
    dt = std::min(o.step, dt * o.growth_factor);
    state.successes = 0;
  }
}

void Stepper::Run::write_step(double attempt, NewtonReport report) {
  record.step = state.steps;
  record.time = state.time;
  record.dt = attempt;
  record.newton = std::move(report);
  // The callbacks write results, on one process of a distributed run for most of them: a failure there
  // (a full disk) is agreed, so that every process stops with it.
  processes::run_agreed("the step's results", [&] {
    if (callbacks.on_step) callbacks.on_step(model, record);
  });
  const bool last = state.time >= o.end - tiny;
  if (record.step % o.output_every == 0 || last) output("the step's output");
  if (o.checkpoint_every > 0 && record.step % o.checkpoint_every == 0 && !last) checkpoint();
  record.cutbacks = 0;
  record.rejections = 0;
  record.cut_back_cost = {};
  record.cut_back_assembly_seconds = 0;
}

void Stepper::Run::output(const std::string& what) {
  processes::run_agreed(what, [&] {
    if (callbacks.on_output) callbacks.on_output(model, record);
  });
}

void Stepper::Run::checkpoint() {
  processes::run_agreed("the checkpoint", [&] {
    if (callbacks.on_checkpoint) callbacks.on_checkpoint(model, state);
  });
}

RunSummary Stepper::Run::summarise() {
  summary.completed = state.time >= o.end - tiny;
  if (!summary.completed) checkpoint();
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

RunSummary Stepper::run(Model& model, TimeScheme& scheme, NewtonSolver& newton, const StepperCallbacks& callbacks) {
  Run run(*this, model, scheme, newton, callbacks);
  if (options_.resume)
    run.resume();
  else if (!run.start())
    return run.summary;
  while (run.state.time < options_.end - run.tiny) {
    if (run.stopped() || !run.attempt_step()) break;
  }
  return run.summarise();
}

}  // namespace pc

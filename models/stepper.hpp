#pragma once
// The time loop: one Newton solve per step, step cut-back on failure (down to a floor; but a residual
// stagnating at its round-off floor, NewtonOutcome::RoundOffFloor, stops the run at once), regrowth toward
// the nominal step after successes, a progress callback after every step and an output callback every N
// steps (and at the start and the end), so that a long run writes its results as it goes. What a recipe
// solves before the first step (the piezoelectric model's initial potential) is its own start hook.
// Every accepted step carries an estimate of the time discretisation's error (models/time_error_estimate.hpp);
// with StepperOptions::adaptive a controller chooses the step sizes from it.
#include <functional>
#include <optional>
#include <string>

#include "models/solvers/newton.hpp"
#include "models/time_error_estimate.hpp"
#include "models/time_scheme.hpp"

namespace pc {

enum class Prediction {
  Zero,      // v = 0 at the start of each step, as in the paper
  Previous,  // v = v_{n-1}
};

// Where the time loop stands between two steps: enough, with the model's state (models/model_state.hpp),
// to continue a run exactly as if it had not stopped (StepperOptions::resume).
struct StepperState {
  double time = 0;
  double step_size = 0;  // the size the next attempt tries
  int steps = 0;         // accepted steps so far
  int successes = 0;     // good steps since the last cut-back or growth
  int attempts = 0;      // step attempts so far, accepted and cut back
  int cutbacks = 0;
  int newton_iterations_total = 0;
  int newton_iterations_max_per_step = 0;
  int rejections = 0;     // adaptive steps: attempts whose estimated error was above the tolerance
  double last_error = 0;  // adaptive steps: the last accepted step's error over its allowance
  TimeErrorHistory time_error;
};

// Adaptive time steps: a PI controller (Gustafsson's) on the estimated local error per step: a step is
// accepted when its relative local error is at most `tolerance` (per step, as CVODE and DASSL control it:
// a tolerance per unit step would chase every contact event's kink down to min_step, since a kink's local
// error does not shrink with k; the run's global error is reported beside it). The error controlled is the largest of
// the reported fields' under the linearised estimate (filtered: stiff modes do not shrink the step), the displacement's
// under the summed one (whose raw velocity error would chase the stiff modes); a step above it is rejected and retried
// smaller. The step grows at most by max_growth a step (BDF2 stays zero-stable) and only when the steps a larger size
// saves over the rest of the run are worth the factorisation a new size costs (factorization_cost, in
// steps); a rejection and a Newton failure (the stepper's cut-back) both shrink it.
struct AdaptiveSteps {
  double tolerance = 1e-3;  // relative RMS time error the run aims at (each field's)
  double max_step = 0;      // 0: (end - start) / 10
  double safety = 0.9;
  double max_growth = 2;          // a step at most this many times the last
  double max_cut = 0.2;           // a rejected step is retried at least this large a fraction of itself
  double factorization_cost = 2;  // a new step size costs about this many steps' work
  // The run's first steps carry no estimate of their own (too early for a divided difference): judged
  // once the first estimate covers them, by a probe before the run, and the first step cut until their
  // error is within the tolerance (Stepper::controlled_first_step).
  bool control_first_step = true;
};

struct StepperOptions {
  double start = 0;
  double end = 1;
  double step = 0.1;
  double cutback_factor = 0.5;  // a failed step is retried this much smaller ...
  double min_step = 0;          // ... down to this floor (0: step * 1e-6)
  double growth_factor = 2;     // after `successes_before_growth` good steps, grow back toward `step`
  int successes_before_growth = 3;
  int output_every = 1;      // output callback every N accepted steps (and at the start and the end)
  int checkpoint_every = 0;  // checkpoint callback every N accepted steps (0: none) and at a stop
  // Budgets (0: none). A run that hits one stops with a message saying which, its results so far written:
  // a cap on step attempts (accepted and cut back) bounds endless cut-back and regrowth cycles, and a
  // wall-time limit bounds a batch job.
  int max_attempts = 0;
  double max_wall_seconds = 0;
  // Asked before every step attempt: a non-empty answer (a reason, e.g. "interrupted by SIGTERM") stops the
  // run there, like a budget, with that reason in its message.
  std::function<std::string()> stop_requested;
  Prediction prediction = Prediction::Zero;
  // The time error estimate: of these fields (empty: the estimator's default, see TimeErrorEstimator),
  // and with adaptive, the controller that chooses the steps from it (`step` is then the first step).
  bool estimate_time_error = true;
  TimeErrorPropagation time_error_propagation = TimeErrorPropagation::Linearised;
  std::vector<std::string> time_error_fields;
  std::optional<AdaptiveSteps> adaptive;
  // Continue a stopped run from this state, the model restored to the same point: no start hook and no
  // output of step 0 (they were done), and the budgets count on from the state's attempts.
  std::optional<StepperState> resume;
};

struct StepRecord {
  int step = 0;  // accepted steps so far (0: the initial state)
  double time = 0;
  double dt = 0;
  int cutbacks = 0;    // failed attempts before this step was accepted
  int rejections = 0;  // attempts rejected on their estimated error before this one
  NewtonReport newton;
  TimeErrorReport time_error;  // this step's estimate (empty without estimate_time_error)
  // The work of those failed attempts (their Newton solves' assembly and linear solves), so that a run's
  // time per phase counts every solve it did, not only the accepted ones.
  LinearSolveCost cut_back_cost;
  double cut_back_assembly_seconds = 0;
  StepperState state;  // after this step: what a checkpoint saves to continue from here
};

struct RunSummary {
  bool completed = false;
  int steps = 0;
  int newton_iterations_total = 0;
  int newton_iterations_max_per_step = 0;
  int cutbacks = 0;
  int rejections = 0;
  TimeErrorReport time_error;  // at the run's last step
  double wall_seconds = 0;
  std::string message;
  StepperState state;  // where the run ended (a checkpoint at a stop saves it)
};

struct StepperCallbacks {
  // At t = start, after the Dirichlet values are applied and before the output of step 0: a solve that
  // completes the initial state (e.g. models/piezo/initial_potential.hpp). Its report is step 0's; one
  // that did not converge stops the run.
  std::function<NewtonReport(Model&)> on_start;
  std::function<void(const Model&, const StepRecord&)> on_step;    // after each accepted step
  std::function<void(const Model&, const StepRecord&)> on_output;  // at output steps
  // Every options.checkpoint_every accepted steps, after that step's outputs, and when the run stops
  // before its end (a budget, a stop request, a step that failed at the floor), with the model back at the
  // last accepted step: what it is given is what StepperOptions::resume continues from.
  std::function<void(const Model&, const StepperState&)> on_checkpoint;
};

class Stepper {
 public:
  explicit Stepper(StepperOptions options);
  const StepperOptions& options() const { return options_; }
  // Runs from options.start to options.end. The model must be finalized and the scheme attached.
  RunSummary run(Model& model, TimeScheme& scheme, NewtonSolver& newton, const StepperCallbacks& callbacks = {});

 private:
  // The first step of an adaptive run, from the start's state: the steps are taken, without callbacks,
  // until an estimate covers the first one; while its error is above the tolerance the model is put back
  // to the start and the first step cut (by the controller's factor for a first-order error, the start
  // being backward Euler), down to min_step. The model is left at the start. Adds the probes' attempts
  // and Newton iterations to `state`.
  double controlled_first_step(Model& model, TimeScheme& scheme, NewtonSolver& newton, StepperState& state) const;
  // One call of run(): its record of the step in progress and its phases (stepper.cpp).
  struct Run;

  StepperOptions options_;
};

}  // namespace pc

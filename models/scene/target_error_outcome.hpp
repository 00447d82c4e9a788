#pragma once
// What the target-error mode achieved (models/scene/target_error.hpp): a run meets its target when it
// completed and its own estimate (space_error_peak + time_error_peak) is at most the target; a missed
// target is a warning, summary.json's target_error.target_met = false, and `piezocontact run`'s exit
// status kTargetMissedExitStatus.
#include <string>

#include "models/scene/scene_runner.hpp"
#include "models/scene/target_error_choice.hpp"

namespace pc {

// `piezocontact run`'s exit status when every run completed and a target-error run missed its target
// (1: a run stopped or failed, 2: a bad command line).
constexpr int kTargetMissedExitStatus = 3;

// The run's own estimate, and whether it met the choice's target.
double target_estimate(const FoundationRunResult& r);
bool target_met(const TargetErrorChoice& choice, const FoundationRunResult& r);

// The result's line: "target 10 %: predicted 5.31 % (space 2.8 % + time 2.51 %), achieved 6.06 % (...): met".
std::string target_result_line(const TargetErrorChoice& choice, const FoundationRunResult& r);
// "warning: target 10 % not met: the run's estimate is 10.6 %".
std::string target_missed_warning(const TargetErrorChoice& choice, const FoundationRunResult& r);

// What a scene's runs achieved, and the exit status that says it.
struct SceneRunOutcome {
  bool completed = true;   // every run completed
  bool target_met = true;  // and, in the target-error mode, met its target
  int exit_status() const { return !completed ? 1 : target_met ? 0 : kTargetMissedExitStatus; }
};

// Runs the scene as run_scene does (models/scene/scene_runner.cpp) and says what it achieved.
SceneRunOutcome run_scene_outcome(const Scene& scene, const SceneRunOptions& options);

}  // namespace pc

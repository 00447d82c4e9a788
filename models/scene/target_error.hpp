#pragma once
// The target-error mode (`piezocontact run SCENE --target-error 1%`, scene key `target_error`): the
// element order, mesh size, time scheme and number of steps are chosen from the run's own error
// estimates, so that the largest estimated error over the run, spatial plus temporal, is below the target
// at the least predicted cost.
//
// Pilots. Short runs of the scene (each chosen foundation, the worst one counting) with adaptive time
// steps (models/stepper.hpp, AdaptiveSteps, the first step controlled too): P1 with backward Euler and P2
// with BDF2, each on a quarter and on half of the scene's cells along each axis at the tolerance
// min(0.5, target), and on half of them at an eighth of that tolerance: six runs. Each gives the largest
// spatial estimate over its output steps and end (models/space_error_estimate.hpp), the largest time
// error estimate over its steps (models/time_error_estimate.hpp) and its step attempts: the target is on
// the whole run, a transient included, not only on its end (FoundationRunResult::space_error_peak,
// time_error_peak). The steps go where the error is, so a sharp first contact does not make the whole
// run pay for it (uniform steps did: 5120 steps for 1 % on the paper scene).
// Models. Spatial: e(n) = e(n_pilot) (n_pilot / n)^r per order, n the cells along an axis, r measured
// between the pilots a factor 2 apart and kept within [0.25, the order] (a singular solution gives less
// than the theory, a pilot on the coarse side may suggest more). Temporal, per scheme: the error goes as
// tolerance^a with a in [0.25, 1] (the controller aims at proportionality), the step attempts as
// tolerance^-b with b in [1/(q+1), 1] (the local error's order, or faster where a transient is not yet
// resolved), both measured between the tolerances a factor 8 apart. Cost: the runner's own prediction
// (models/scene/time_estimate.hpp) for the candidate's dofs (the pilot's, scaled by the mesh factor to the
// power of the dimension) and predicted attempts. The rates are checked against the theory's
// (models/scene/target_error_rates.hpp): one far below it is a warning, and that order's candidates stay
// within 4 times the finer pilot's cells and 64 times below the pilots' tolerance.
// Choice. Over both order/scheme pairs, meshes 1/2 to 32 times the finer pilot's in steps of 2^(1/2), and
// tolerances from twice the pilots' down in steps of 2^(1/2): the least predicted cost whose spatial and
// temporal estimates add up to at most the target times the safety margin (0.8), run with `time.adaptive`
// at the chosen tolerance. Whether the run met the target: models/scene/target_error_outcome.hpp.
// Candidates that would not fit in memory (the scene's own check, models/scene/memory_estimate.hpp) or
// pass 4 million dofs are left out; when none reaches the target, the mode refuses, naming the candidate
// with the least predicted error. The wall clock does not enter the choice, so a resumed run chooses what
// the stopped one chose (on a machine with as much memory).
//
// What the estimates are, and are not: the spatial estimate is an energy norm of the gradient error
// (effectivity 0.5-0.9 on the paper scene, 0.6 for P2); the temporal one RMS over the dofs relative to
// the field's largest RMS in the run. The target is on these estimates; what that means against a true
// error is measured in benchmarks/speed_accuracy_study.cpp (axis "target") and the README.
#include <string>
#include <vector>

#include "models/scene/scene.hpp"
#include "models/scene/target_error_choice.hpp"

namespace pc {

// Runs the pilots of the scene's foundations (those `only` names; empty: all) and chooses. Throws if the
// scene has no target_error, or a pilot does not complete. progress: a line per pilot on stdout.
TargetErrorChoice choose_for_target_error(const Scene& scene, const std::vector<std::string>& only, bool progress);

// The scene as the choice makes it: reloaded from its file with its overrides and the choice's, and the
// choice kept in Scene::target_choice (the runner writes it into summary.json, next to what was achieved).
Scene scene_for_target_error(const Scene& scene, const std::vector<std::string>& only, bool progress);

}  // namespace pc

#pragma once
// The target-error mode (`piezocontact run SCENE --target-error 1%`, scene key `target_error`): the
// element order, mesh size, time scheme and number of steps are chosen from the run's own error
// estimates, so that the largest estimated error over the run, spatial plus temporal, is below the target
// at the least predicted cost.
//
// Pilots. Short runs of the scene (each chosen foundation, the worst one counting), P1 with backward
// Euler and P2 with BDF2, each on a quarter and on half of the scene's cells along each axis with a
// fifth of its steps (at least 20), and on half of them with twice those steps: six runs. Each gives the
// largest spatial estimate over its output steps and end (models/space_error_estimate.hpp) and the
// largest time error estimate over its steps (models/time_error_estimate.hpp): the target is on the
// whole run, a transient included, not only on its end (FoundationRunResult::space_error_peak,
// time_error_peak).
// Models. Spatial: e(n) = e(n_pilot) (n_pilot / n)^r per order, n the cells along an axis; temporal:
// e(N) = e(N_pilot) (N_pilot / N)^q per scheme. Both rates are measured between the pilots a factor 2
// apart, and kept within [0.25, the theoretical order]: a singular solution, or order reduction by a
// stiff contact (BDF2 reads 0.8 on the paper scene's transient), gives less than the theory; a pilot on
// the coarse side may suggest more. Cost: the runner's own prediction (models/scene/time_estimate.hpp)
// for the candidate's dofs (the pilot's, scaled by the mesh factor to the power of the dimension) and
// steps.
// Choice. Over orders 1 and 2, both schemes, meshes 1/2 to 32 times the finer pilot's in steps of
// 2^(1/2), and steps from half the pilots' (at least 10) up to 2^11 times that in steps of 2^(1/2): the
// least predicted cost whose spatial and temporal estimates add up to at most the target. Candidates
// that would not fit in memory (the scene's own check, models/scene/memory_estimate.hpp) or pass 4
// million dofs are left out; when none reaches the target, the candidate with the least predicted
// error, said so. The wall clock does not enter the choice, so a resumed run chooses what the stopped
// one chose (on a machine with as much memory).
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

#pragma once
// Runs a recipe's model through time as the runner does (the initial potential first), with a callback at
// every accepted state: the closed-form and energy tests' loop.
#include <gtest/gtest.h>

#include <functional>

#include "models/piezo/initial_potential.hpp"
#include "models/piezo/piezo_contact_recipe.hpp"
#include "models/solvers/newton.hpp"
#include "models/stepper.hpp"

namespace pc::testing {

// From 0 to `end` in `steps` steps; `after_step` sees every accepted state, and the initial one where the
// initial potential was solved (an electric model).
inline void run(PiezoContactModel& built, double end, int steps,
                const std::function<void(const Model&)>& after_step = {}) {
  StepperOptions options;
  options.end = end;
  options.step = end / steps;
  NewtonSolver newton;
  StepperCallbacks callbacks;
  if (built.electric) callbacks.on_start = [&](Model& m) { return solve_initial_potential(m, *built.scheme, newton); };
  if (after_step) {
    callbacks.on_output = [&](const Model& m, const StepRecord& r) {
      if (r.step == 0 && built.electric) after_step(m);
    };
    callbacks.on_step = [&](const Model& m, const StepRecord&) { after_step(m); };
  }
  const RunSummary summary = Stepper(options).run(*built.model, *built.scheme, newton, callbacks);
  ASSERT_TRUE(summary.completed) << summary.message;
}

}  // namespace pc::testing

#pragma once
// A model's state between two time steps, saved into and restored from a Checkpoint (the stepper's
// beside it, below): the time, every unknown and data field (the scheme's history fields among them),
// every affine field's map, and what the time scheme keeps beyond the fields. Bricks are stateless, so
// this is all a run needs to continue exactly; restoring refuses a checkpoint of another model (a field
// missing or of another size).
#include "models/model.hpp"
#include "models/output/checkpoint.hpp"
#include "models/stepper.hpp"
#include "models/time_scheme.hpp"

namespace pc {

void save_model_state(const Model& model, const TimeScheme& scheme, Checkpoint& checkpoint);
void restore_model_state(Model& model, TimeScheme& scheme, const Checkpoint& checkpoint);

// The time loop's state beside it: with both, StepperOptions::resume continues the run exactly.
void save_stepper_state(const StepperState& state, Checkpoint& checkpoint);
StepperState restore_stepper_state(const Checkpoint& checkpoint);

}  // namespace pc

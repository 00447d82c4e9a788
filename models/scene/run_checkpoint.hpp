#pragma once
// What a foundation run (models/scene/scene_runner.hpp) keeps in its checkpoint.bin besides the model's and
// the stepper's state: its own totals and the VTU series' steps, so that a resumed run's summary counts the
// whole run and its series lists every step.
#include <utility>
#include <vector>

#include "models/output/checkpoint.hpp"
#include "models/output/result_series.hpp"
#include "models/scene/scene_runner.hpp"

namespace pc {

// The runner's own totals, kept in a checkpoint so that a resumed run's summary counts the whole run.
void save_totals(const FoundationRunResult& r, double wall_seconds, Checkpoint& c);
// And back, with the wall time of the run's part before the checkpoint.
void restore_totals(const Checkpoint& c, FoundationRunResult& r, double& wall_seconds);

// The series' written steps as two vectors of the checkpoint.
void save_series(const ResultSeries& series, Checkpoint& c);
// And back: the steps to continue the series from (ResultSeries::continue_from).
std::vector<std::pair<int, double>> restore_series(const Checkpoint& c);

}  // namespace pc

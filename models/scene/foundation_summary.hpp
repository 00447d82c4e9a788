#pragma once
// summary.json of one run of a foundation (models/scene/scene_runner.hpp; README, "Reading the results"):
// the scene and its mesh, the run's counts, its estimated errors, where its wall time went, the BLAS that
// ran, and the result's numbers (null where not finite).
#include <string>
#include <utility>
#include <vector>

#include "models/scene/scene.hpp"
#include "models/scene/scene_runner.hpp"

namespace pc {

// The result's numbers by name, as summary.json holds them.
std::vector<std::pair<const char*, double>> result_numbers(const FoundationRunResult& r);

// Writes dir/summary.json, atomically, for a run of `steps` steps.
void write_summary(const Scene& scene, const std::string& dir, const FoundationRunResult& r, int steps);

}  // namespace pc

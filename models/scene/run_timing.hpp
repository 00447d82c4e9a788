#pragma once
// Where a run's wall time went, by phase, from what FoundationRunResult measured: summary.json's "timing"
// and benchmarks/step_breakdown_study print it. Every phase is measured; "other" is what remains of the
// wall time outside them (the stepper's bookkeeping, the finiteness checks, progress lines).
#include <string>
#include <vector>

#include "models/scene/scene_runner.hpp"

namespace pc {

struct RunPhase {
  std::string name;  // as summary.json's key, without the "_s"
  double seconds = 0;
};

// assembly_residual, assembly_jacobian, factorize (symbolic analyses included), solve, condensation (the
// dense interface systems), output, other: they sum to r.wall_seconds.
std::vector<RunPhase> run_phases(const FoundationRunResult& r);

}  // namespace pc

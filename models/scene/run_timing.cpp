#include "models/scene/run_timing.hpp"

namespace pc {

std::vector<RunPhase> run_phases(const FoundationRunResult& r) {
  std::vector<RunPhase> phases = {{"assembly_residual", r.assembly_seconds - r.jacobian_seconds},
                                  {"assembly_jacobian", r.jacobian_seconds},
                                  {"factorize", r.factorize_seconds},
                                  {"solve", r.solve_seconds},
                                  {"condensation", r.condensation_seconds},
                                  {"output", r.output_seconds}};
  double measured = 0;
  for (const RunPhase& p : phases) measured += p.seconds;
  phases.push_back({"other", r.wall_seconds - measured});
  return phases;
}

}  // namespace pc

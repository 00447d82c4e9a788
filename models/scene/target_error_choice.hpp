#pragma once
// What the target-error mode chose (models/scene/target_error.hpp), kept with the scene it made.
#include <map>
#include <string>
#include <vector>

namespace pc {

struct TargetErrorChoice {
  double target = 0;
  int order = 1;
  std::string scheme;  // a time.scheme name
  int nx = 0, ny = 0, nz = 0;
  double tolerance = 0;  // of the adaptive time steps (time.adaptive), which control the time error
  int steps = 0;         // predicted: the step attempts the tolerance takes
  int dofs = 0;          // predicted
  double predicted_space = 0, predicted_time = 0, predicted_seconds = 0;
  double margin = 1;  // the choice aims at margin * target (the safety margin)
  // The pilots' wall time per foundation (model builds included), and of all the pilots and the choice.
  std::map<std::string, double> foundation_pilots_seconds;
  double pilots_seconds = 0;
  std::string rates;                  // the pilots' fitted rates against the theory's, one line
  std::vector<std::string> warnings;  // rates far below the theory's, and what the choice did about them
  std::string explanation;            // the choice, the rates and the warnings, for summary.json
  // The scene overrides that make the choice: mesh.nx, ny (nz), mesh.order, time.scheme, time.adaptive,
  // and output.space_error_every = 1 (the spatial estimate's peak over the run, not between output steps).
  std::vector<std::string> overrides() const;
  std::string description() const;  // e.g. "P2 on 30 x 10 cells, bdf2, adaptive 0.00316 (~80 steps)"
  double pilots_seconds_of(const std::string& foundation) const;  // 0 for a foundation without pilots
};

}  // namespace pc

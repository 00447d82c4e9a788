#include "models/piezo/initial_potential.hpp"

namespace pc {

NewtonReport solve_initial_potential(Model& model, TimeScheme& scheme, NewtonSolver& newton,
                                     const std::string& potential) {
  if (!model.has_field(potential) || model.field_kind(potential) != FieldKind::Unknown) {
    NewtonReport report;
    report.outcome = NewtonOutcome::Converged;
    report.message = "no potential unknown '" + potential + "': nothing to solve";
    return report;
  }
  std::vector<std::string> frozen;
  for (const std::string& u : model.unknowns())
    if (u != potential) frozen.push_back(u);
  scheme.freeze_displacement(model);
  model.set_frozen(frozen);
  NewtonReport report = newton.solve(model);
  model.set_frozen({});
  return report;
}

}  // namespace pc

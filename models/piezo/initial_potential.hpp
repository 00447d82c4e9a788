#pragma once
// The paper's phi_0: before the first step, the potential solves the electric equation at the model's
// current time with the mechanical state given (u = u_0, v = v_0), since the initial data give only those.
// A recipe's start hook (StepperCallbacks::on_start):
//   callbacks.on_start = [&](Model& m) { return solve_initial_potential(m, scheme, newton); };
#include <string>

#include "models/model.hpp"
#include "models/solvers/newton.hpp"
#include "models/time_scheme.hpp"

namespace pc {

// Freezes every other unknown and the scheme's displacement at its history (u_0), solves for the potential
// and unfreezes. A model without the potential unknown (purely mechanical) has nothing to solve: the report
// is converged, with no iteration.
NewtonReport solve_initial_potential(Model& model, TimeScheme& scheme, NewtonSolver& newton,
                                     const std::string& potential = "phi");

}  // namespace pc

#pragma once
// How Newton solves J dx = -R (NewtonOptions::condensation, a scene's solver.condensation):
//   full     a factorisation of J per iteration (solver.condensed = false, or where nothing else applies)
//   schur    MUMPS's Schur complement of the interior, dense on the m contact dofs (condensed_solve.hpp)
//   columns  Woodbury columns by solves with any linear solver, dense on the contact dofs (condensed_solve.hpp)
//   krylov   GMRES preconditioned by a kept factorisation of an earlier J: nothing grows with m (krylov_solve.hpp)
//   auto     the cheapest of these by the cost model of strategy_cost_model.hpp
#include <string>

#include "assembly/registry.hpp"

namespace pc {

enum class LinearStrategy { Auto, Full, Schur, Columns, Krylov };

// The names a scene can give: "auto", "schur", "columns", "krylov".
Registry<LinearStrategy>& condensation_registry();
LinearStrategy linear_strategy_from_string(const std::string& name);  // throws listing the registered names
std::string to_string(LinearStrategy strategy);

}  // namespace pc

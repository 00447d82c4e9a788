#pragma once
// The cost model of solver.condensation = "auto": the seconds a Newton iteration costs by each strategy,
// from the sizes of the problem and the factor size the linear solver's symbolic analysis predicts, and
// the bytes each keeps. Rates and the Krylov counts are measured (benchmarks/condensation_crossover_study
// prints the model's prediction next to the measured times), not guessed: see kDenseRate and below.
//   schur   one solve's worth of sparse work (reduce + expand) and, on the m contact dofs, a product with
//           the dense S_c^-1 (2 m^2) and the Woodbury system on the active dofs (2/3 a^3, a <= m: the model
//           takes a = m); forming S_c^-1 once per factorisation (2 m^3), amortised over the iterations that
//           use it. Memory: S_c and S_c^-1, 16 m^2 bytes.
//   krylov  a few GMRES iterations of one solve and one product with J each, and a share of the
//           factorisations of J_ref (renewed as the contact state moves on). Memory: the Krylov basis.
// The choice: schur when its dense matrices fit the memory budget and its iteration is the cheaper, else
// krylov. Both are far cheaper than a factorisation per iteration (solver.condensed = false) whenever the
// contact dofs are a small part of the problem.
#include <string>

#include "assembly/linear_solver.hpp"
#include "models/solvers/linear_strategy.hpp"

namespace pc {

struct StrategyCostInputs {
  double dofs = 0, nonlinear_dofs = 0, jacobian_nonzeros = 0;
  FactorEstimate factors;          // of J's pattern (entries 0: estimated from the Jacobian's nonzeros)
  double memory_budget_bytes = 0;  // for the dense matrices (0: no limit)
};

struct StrategyCosts {
  double full_seconds = 0, schur_seconds = 0, krylov_seconds = 0;  // predicted, per Newton iteration
  double schur_bytes = 0;
  LinearStrategy choice = LinearStrategy::Krylov;
  std::string explanation;  // one line for the run's report
};

StrategyCosts predict_strategy_costs(const StrategyCostInputs& inputs);

}  // namespace pc

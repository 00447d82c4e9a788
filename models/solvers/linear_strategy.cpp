#include "models/solvers/linear_strategy.hpp"

namespace pc {

Registry<LinearStrategy>& condensation_registry() {
  static Registry<LinearStrategy> registry("condensation", "solver.condensation");
  return registry;
}

LinearStrategy linear_strategy_from_string(const std::string& name) {
  return condensation_registry().at(name, "condensation").create;
}

std::string to_string(LinearStrategy strategy) {
  switch (strategy) {
    case LinearStrategy::Auto: return "auto";
    case LinearStrategy::Full: return "full";
    case LinearStrategy::Schur: return "schur";
    case LinearStrategy::Columns: return "columns";
    case LinearStrategy::Krylov: return "krylov";
  }
  return "unknown";
}

}  // namespace pc

PC_REGISTER(pc::condensation_registry(),
            {"auto",
             "the cheapest of schur, krylov and a full factorisation per iteration by the printed cost model",
             {},
             pc::LinearStrategy::Auto})
PC_REGISTER(pc::condensation_registry(),
            {"schur",
             "MUMPS Schur complement of the interior: one solve's worth of work per Newton iteration, "
             "dense in the contact dofs",
             {},
             pc::LinearStrategy::Schur})
PC_REGISTER(pc::condensation_registry(),
            {"columns",
             "Woodbury columns by solves with solver.linear: two solves per iteration, dense in the "
             "contact dofs",
             {},
             pc::LinearStrategy::Columns})
PC_REGISTER(pc::condensation_registry(),
            {"krylov",
             "GMRES on J preconditioned by a kept factorisation of an earlier J: a few solves per "
             "iteration, nothing dense",
             {},
             pc::LinearStrategy::Krylov})

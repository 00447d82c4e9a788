#include "models/solvers/strategy_cost_model.hpp"

#include <algorithm>
#include <cstdio>

#include "assembly/error.hpp"
#include "models/output/duration_text.hpp"

namespace pc {
namespace {

// Rates of this machine's libraries (2-core development machine, reference BLAS), from
// benchmarks/condensation_crossover_study: triangular solves are memory bound, the dense LU and
// products of Eigen are blocked.
constexpr double kSparseSolveRate = 1.0e9;   // flop/s of forward + backward substitution (4 per factor entry)
constexpr double kSparseFactorRate = 1.5e9;  // flop/s of the numeric factorisation
constexpr double kDenseRate = 1.0e10;        // flop/s of Eigen's (blocked, vectorised) LU and products
// Schur: the share of the contact dofs active in the Woodbury system (in compression), over the study's runs.
constexpr double kActiveFraction = 0.25;
// Krylov: GMRES iterations per Newton iteration, and Newton iterations per factorisation of J_ref, as
// measured over the paper's scene and the long strips of the study (medians).
constexpr double kKrylovIterations = 2.0;
constexpr double kNewtonIterationsPerFactorisation = 4.0;
// Newton iterations over which the formation of S_c^-1 is amortised (about one step size's worth).
constexpr double kIterationsPerSchurFactorisation = 20.0;
// Without an estimate from the analysis: factor entries per Jacobian nonzero (2D P1 meshes of the study).
constexpr double kFillWithoutEstimate = 8.0;

std::string mebibytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", bytes / 1048576.0);
  return text;
}

}  // namespace

StrategyCosts predict_strategy_costs(const StrategyCostInputs& in) {
  StrategyCosts c;
  const double m = in.nonlinear_dofs;
  const double entries = in.factors.entries > 0 ? in.factors.entries : kFillWithoutEstimate * in.jacobian_nonzeros;
  const double factor_flops = in.factors.flops > 0 ? in.factors.flops : 10 * entries;
  const double solve = 4 * entries / kSparseSolveRate;
  const double factorise = factor_flops / kSparseFactorRate;
  const double a = kActiveFraction * m;
  c.schur_seconds = solve + (2 * m * m + 2 * m * a + 2.0 / 3.0 * a * a * a) / kDenseRate +
                    (2 * m * m * m / kDenseRate + factorise) / kIterationsPerSchurFactorisation;
  c.krylov_seconds = kKrylovIterations * (solve + 2 * in.jacobian_nonzeros / kSparseSolveRate) +
                     factorise / kNewtonIterationsPerFactorisation;
  c.full_seconds = factorise + solve;
  c.schur_bytes = 16 * m * m;
  const bool fits = in.memory_budget_bytes <= 0 || c.schur_bytes <= in.memory_budget_bytes;
  // Krylov, never worse than about a factorisation per iteration (it backs off to direct steps where the
  // contact state moves too fast), stands for the full path too.
  c.choice = fits && c.schur_seconds <= std::min(c.krylov_seconds, c.full_seconds) ? LinearStrategy::Schur
                                                                                   : LinearStrategy::Krylov;
  c.explanation = message("condensation auto: ", static_cast<long>(m), " contact dofs of ", static_cast<long>(in.dofs),
                          "; predicted per Newton iteration full ", describe_duration(c.full_seconds), ", schur ",
                          describe_duration(c.schur_seconds), " (dense S_c^-1 ", mebibytes(c.schur_bytes), " MiB",
                          fits ? "" : ", over the memory budget", "), krylov ", describe_duration(c.krylov_seconds),
                          ": ", to_string(c.choice));
  return c;
}

}  // namespace pc

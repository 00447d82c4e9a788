// The cost model of solver.condensation = "auto" (models/solvers/strategy_cost_model.hpp): its predictions
// grow as the work they count (the dense Schur work as the cube of the contact dofs, Krylov's not at all
// with them), so that the choice flips from schur to krylov as the contact set grows, and a memory budget
// too small for S_c^-1 rules schur out whatever its speed.
#include <gtest/gtest.h>

#include <cmath>

#include "models/solvers/strategy_cost_model.hpp"

namespace pc {
namespace {

// A 2D P1 problem of the paper scene's proportions: about 20 Jacobian nonzeros and 8x that many factor
// entries per dof, with m contact dofs.
StrategyCostInputs problem(double dofs, double m) {
  StrategyCostInputs in;
  in.dofs = dofs;
  in.nonlinear_dofs = m;
  in.jacobian_nonzeros = 20 * dofs;
  in.factors = {160 * dofs, 3000 * dofs};
  return in;
}

TEST(StrategyCostModel, SchurForAFewContactDofsKrylovForMany) {
  const StrategyCosts few = predict_strategy_costs(problem(15000, 240));
  EXPECT_EQ(few.choice, LinearStrategy::Schur) << few.explanation;
  const StrategyCosts many = predict_strategy_costs(problem(15000 * 50, 240 * 50 * 4));
  EXPECT_EQ(many.choice, LinearStrategy::Krylov) << many.explanation;
  EXPECT_DOUBLE_EQ(many.schur_bytes, 16.0 * 48000 * 48000);
}

TEST(StrategyCostModel, DenseWorkGrowsAsTheCubeOfTheContactDofsAndKrylovsNotAtAll) {
  // Sparse parts held fixed: only m changes.
  const StrategyCosts m1 = predict_strategy_costs(problem(1e6, 2000));
  const StrategyCosts m2 = predict_strategy_costs(problem(1e6, 4000));
  const StrategyCosts m0 = predict_strategy_costs(problem(1e6, 0));
  const double dense1 = m1.schur_seconds - m0.schur_seconds, dense2 = m2.schur_seconds - m0.schur_seconds;
  EXPECT_GT(std::log2(dense2 / dense1), 2.5) << "the m^3 terms dominate at these sizes";
  EXPECT_LE(std::log2(dense2 / dense1), 3.0);
  EXPECT_DOUBLE_EQ(m1.krylov_seconds, m2.krylov_seconds);
  EXPECT_DOUBLE_EQ(m1.full_seconds, m2.full_seconds);
}

TEST(StrategyCostModel, AMemoryBudgetTooSmallForTheDenseMatricesRulesSchurOut) {
  StrategyCostInputs in = problem(15000, 240);
  in.memory_budget_bytes = 16.0 * 240 * 240 - 1;
  const StrategyCosts c = predict_strategy_costs(in);
  EXPECT_EQ(c.choice, LinearStrategy::Krylov);
  EXPECT_NE(c.explanation.find("over the memory budget"), std::string::npos) << c.explanation;
  in.memory_budget_bytes = 16.0 * 240 * 240;
  EXPECT_EQ(predict_strategy_costs(in).choice, LinearStrategy::Schur);
}

TEST(StrategyCostModel, WithoutAnEstimateFromTheAnalysisTheJacobianSizeStandsIn) {
  StrategyCostInputs in = problem(15000, 240);
  in.factors = {};
  const StrategyCosts c = predict_strategy_costs(in);
  EXPECT_TRUE(std::isfinite(c.schur_seconds) && c.schur_seconds > 0);
  EXPECT_TRUE(std::isfinite(c.krylov_seconds) && c.krylov_seconds > 0);
}

}  // namespace
}  // namespace pc

// Unit tests of the foundation law (saturating_conductance.hpp) and of its brick with the harness that the
// installed package ships; the README's "Writing a new foundation law" shows them.
// [snippet test]
#include <gtest/gtest.h>

#include "bricks/conductive_foundation_brick.hpp"
#include "bricks/testing/brick_checker.hpp"
#include "bricks/testing/law_checker.hpp"
#include "saturating_conductance.hpp"

// Parameters of order one, where finite differences resolve the derivatives of tanh.
const SaturatingConductance kLaw{2.0, 0.5, 0.7};

TEST(SaturatingConductance, PassesTheLawChecker) {  // derivatives, dissipative claim, ranges, extremes
  const pc::LawCheckReport report = pc::check_foundation_law(kLaw, {.name = "saturating"});
  EXPECT_TRUE(report.ok()) << report;
}

TEST(SaturatingConductance, ItsBrickPassesTheBrickChecker) {  // tangent, linear/symmetric claims, extremes
  pc::ConductiveFoundationBrick<SaturatingConductance> brick("bottom");
  const pc::ConstantTable constants = pc::ConstantTable().set(pc::law_values(kLaw));
  const pc::BrickCheckReport report = pc::check_brick(brick, constants, pc::BrickCheckSetup::square());
  EXPECT_TRUE(report.ok()) << report;
  EXPECT_GT(report.tangent_checks, 0);
}
// [snippet test end]

// Near phi_f it conducts as the paper's law, k_e (phi - phi_f); far from it the flux is k_e phi_s.
TEST(SaturatingConductance, IsLinearNearPhiFAndSaturatesFarFromIt) {
  EXPECT_NEAR(kLaw(0.5 + 1e-6, 0.0), 2.0 * 1e-6, 1e-14);
  EXPECT_NEAR(kLaw(0.5 - 100.0, 0.0), -2.0 * 0.7, 1e-12);
}

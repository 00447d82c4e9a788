// Unit tests of the user's law and of its brick with the harness that the installed package ships.
// [snippet harness]
#include <gtest/gtest.h>

#include <cmath>

#include "bricks/friction_brick.hpp"
#include "bricks/laws/normal_laws.hpp"
#include "bricks/normal_response_brick.hpp"
#include "bricks/testing/brick_checker.hpp"
#include "bricks/testing/law_checker.hpp"
#include "velocity_weakening.hpp"

// [snippet harness end]
namespace {

// [snippet harness]
const VelocityWeakeningCoulomb kLaw{0.6, 0.3, 0.05, 1e-3};

TEST(VelocityWeakening, PassesTheLawChecker) {
  const pc::LawCheckReport report = pc::check_friction_law(kLaw, {.name = "velocity weakening"});
  EXPECT_TRUE(report.ok()) << report;
}
// [snippet harness end]

// Far above v_c the coefficient is mu_k, near rest (but above eps) it is mu_s: |p_tau| = mu |p_nu|.
TEST(VelocityWeakening, FallsFromStaticToKineticFriction) {
  const double pressure = 2.0;
  for (const auto& [speed, mu] : {std::pair{10.0, 0.3}, std::pair{0.05, 0.3 + 0.3 * std::exp(-1.0)}}) {
    const double r[2] = {speed, 0.0};
    double p[2];
    kLaw(r, 2, pressure, p);
    EXPECT_NEAR(p[0], mu * pressure * speed / std::sqrt(speed * speed + 1e-6), 1e-12) << speed;
    EXPECT_EQ(p[1], 0.0);
  }
}

// The friction brick over the law, paired with a normal brick, passes the brick checker: its tangent
// against finite differences (with the pressure coupling), its claims, finite at extremes.
TEST(VelocityWeakening, ItsBrickPassesTheBrickChecker) {
  const pc::ConstantTable constants =
      pc::ConstantTable().set(pc::law_values(kLaw)).set(pc::law_values(pc::LinearDampedResponse{10.0}));
  auto normal = std::make_shared<pc::NormalResponseBrick<pc::LinearDampedResponse>>("bottom");
  normal->update(constants);
  pc::FrictionBrick<VelocityWeakeningCoulomb> friction("bottom", normal);
  pc::BrickCheckSetup setup = pc::BrickCheckSetup::square();
  setup.ranges["v"] = {-1.0, -0.2};  // pressed into the foundation (outward normal -y) and sliding
  const pc::BrickCheckReport report = pc::check_brick(friction, constants, setup);
  EXPECT_TRUE(report.ok()) << report;
  EXPECT_GT(report.tangent_checks, 0);
}

}  // namespace

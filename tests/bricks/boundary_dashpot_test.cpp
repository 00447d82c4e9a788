// The boundary dashpot, the registered brick that scenes add under "bricks": its residual in closed form,
// its claims through the harness, its coefficient read from the model.
#include <gtest/gtest.h>

#include "assembly/mesh_generators.hpp"
#include "bricks/boundary_dashpot_brick.hpp"
#include "bricks/brick_registry.hpp"
#include "bricks/testing/brick_checker.hpp"
#include "models/model.hpp"

namespace pc {
namespace {

// On the unit square, a uniform velocity v gives the total force c_b |right| v = c_b v on the right side.
TEST(BoundaryDashpot, TotalForceIsTheCoefficientTimesTheSideLengthTimesTheVelocity) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 4, 3, Shape::Triangle));
  Model model(mesh);
  const auto space = std::make_shared<const FESpace>(mesh, 2, 2);
  model.add_unknown("v", space);
  model.set_constant("c_b", 7.5);
  const int brick = model.add_brick(brick_registry().at("boundary_dashpot", "test").create("right"));
  model.finalize();
  model.set_values("v", space->interpolate([](const double*, double* out) { out[0] = 1.0, out[1] = -2.0; }));
  model.assemble(false);
  const Eigen::VectorXd& r = model.field_residual("v");
  double fx = 0, fy = 0;
  for (int s = 0; s < space->num_scalar_dofs(); ++s) fx += r[space->dof(s, 0)], fy += r[space->dof(s, 1)];
  EXPECT_NEAR(fx, 7.5, 1e-12);
  EXPECT_NEAR(fy, -15.0, 1e-12);
  // A new coefficient scales it, re-running the brick's loop once; the term is kept.
  const auto loops = model.elements_assembled(brick);
  model.set_constant("c_b", 15.0);
  model.assemble(false);
  EXPECT_GT(model.elements_assembled(brick), loops);
  fx = 0;
  for (int s = 0; s < space->num_scalar_dofs(); ++s) fx += model.field_residual("v")[space->dof(s, 0)];
  EXPECT_NEAR(fx, 15.0, 1e-12);
}

TEST(BoundaryDashpot, PassesTheBrickCheckerAndRefusesANegativeCoefficient) {
  BoundaryDashpotBrick dashpot("bottom");
  const BrickCheckReport report =
      check_brick(dashpot, ConstantTable().set("c_b", 3.0), BrickCheckSetup::square(Shape::Triangle, 2));
  EXPECT_TRUE(report.ok()) << report;
  EXPECT_TRUE(dashpot.linear());
  EXPECT_TRUE(dashpot.symmetric());
  try {
    dashpot.update(ConstantTable().set("c_b", -1.0));
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("boundary dashpot (c_b) on bottom': c_b must be >= 0, got -1"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace pc

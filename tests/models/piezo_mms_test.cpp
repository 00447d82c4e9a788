// Manufactured solutions of the coupled piezoelectric problem assembled from bricks in a Model:
//  - static (no inertia, no viscosity): -div sigma = f0, div D = q0 with sigma = B eps(u) + E^T grad phi,
//    D = E eps(u) - beta grad phi, solved as one backward Euler step of size 1 from u = 0 (so u = v);
//    measured L2 and H1 rates of u and phi for P1 and P2 (theory p + 1 and p, within 0.15);
//  - in time: rho u'' - div(A eps(u') + B eps(u) + E^T grad phi) = f0 with u = g(t) s(x): backward Euler's
//    error at T is first order in k (measured rate within 0.15 of 1).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "assembly/mesh_generators.hpp"
#include "models/model.hpp"
#include "models/piezo/initial_potential.hpp"
#include "models/solvers/newton.hpp"
#include "models/stepper.hpp"
#include "models/time_scheme.hpp"
#include "support/piezo_mms.hpp"

namespace pc {
namespace {

using testing::PiezoMmsExact;
using testing::PiezoMmsPhysics;
using testing::TimeProfile;

double rate(double coarse, double fine, double ratio) { return std::log(coarse / fine) / std::log(ratio); }

class StaticPiezo : public ::testing::TestWithParam<int> {};

TEST_P(StaticPiezo, CoupledFieldsConvergeAtTheoreticalRates) {
  const int order = GetParam();
  const PiezoMmsExact exact;
  std::vector<testing::PiezoMmsErrors> e;
  const std::vector<int> sizes = order == 1 ? std::vector<int>{8, 16, 32, 64} : std::vector<int>{4, 8, 16, 32};
  const TimeProfile constant{[](double) { return 1.0; }, [](double) { return 1.0; }, [](double) { return 0.0; }};
  for (int n : sizes) {
    auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, n, n, Shape::Triangle));
    // One backward Euler step of size 1 from u_prev = 0: u = v, and the Dirichlet value of v is u.
    auto s = testing::build_piezo_mms_problem(mesh, order, exact, PiezoMmsPhysics{}, std::make_unique<BackwardEuler>(),
                                              constant);
    StepperOptions options;
    options.start = 0;
    options.end = 1;
    options.step = 1;
    NewtonSolver newton;
    const RunSummary run = Stepper(options).run(*s.model, *s.scheme, newton);
    ASSERT_TRUE(run.completed) << run.message;
    EXPECT_EQ(run.newton_iterations_max_per_step, 1) << "a linear model converges in one Newton iteration";
    e.push_back(testing::piezo_mms_errors(*s.model, exact, 1.0));
  }
  for (size_t k = e.size() - 2; k < e.size(); ++k) {
    const double r[4] = {rate(e[k - 1].u_l2, e[k].u_l2, 2), rate(e[k - 1].u_h1, e[k].u_h1, 2),
                         rate(e[k - 1].phi_l2, e[k].phi_l2, 2), rate(e[k - 1].phi_h1, e[k].phi_h1, 2)};
    std::printf("P%d n=%d: rates u L2 %.3f H1 %.3f, phi L2 %.3f H1 %.3f\n", order, sizes[k], r[0], r[1], r[2], r[3]);
    EXPECT_NEAR(r[0], order + 1, 0.15);
    EXPECT_NEAR(r[1], order, 0.15);
    EXPECT_NEAR(r[2], order + 1, 0.15);
    EXPECT_NEAR(r[3], order, 0.15);
  }
}

INSTANTIATE_TEST_SUITE_P(Bricks, StaticPiezo, ::testing::Values(1, 2));

TEST(DynamicPiezo, BackwardEulerIsFirstOrderInTime) {
  const PiezoMmsExact exact;
  const TimeProfile time = testing::sine_profile();
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 6, 6, Shape::Triangle));
  const double T = 1.0;
  std::vector<double> errors;
  const std::vector<int> steps = {8, 16, 32, 64};
  for (int n : steps) {
    auto s = testing::build_piezo_mms_problem(mesh, 2, exact, PiezoMmsPhysics{true, true},
                                              std::make_unique<BackwardEuler>(), time);
    // Exact initial state: u(0) = 0, v(0) = g'(0) U s.
    const Eigen::VectorXd v0 = exact.interpolate_vector(s.model->space("v"), time.g_dot(0));
    s.scheme->set_initial_state(*s.model, Eigen::VectorXd::Zero(v0.size()), v0);
    StepperOptions options;
    options.end = T;
    options.step = T / n;
    options.prediction = Prediction::Previous;
    NewtonSolver newton;
    StepperCallbacks callbacks;
    callbacks.on_start = [&](Model& m) { return solve_initial_potential(m, *s.scheme, newton); };
    const RunSummary run = Stepper(options).run(*s.model, *s.scheme, newton, callbacks);
    ASSERT_TRUE(run.completed) << run.message;
    errors.push_back(testing::piezo_mms_errors(*s.model, exact, time.g(T)).u_l2);
  }
  for (size_t k = 2; k < errors.size(); ++k) {
    const double r = rate(errors[k - 1], errors[k], 2);
    std::printf("backward Euler: %d -> %d steps, error %.3e -> %.3e, rate %.3f\n", steps[k - 1], steps[k],
                errors[k - 1], errors[k], r);
    EXPECT_NEAR(r, 1.0, 0.15);
  }
}

}  // namespace
}  // namespace pc

// Newton's globalisation on a problem with a known failure of full steps: f(u) = u^3 - 2u + 2, whose Newton
// iteration from u = 0 cycles 0 -> 1 -> 0 -> ... for ever (a textbook example), tested with the mass matrix
// on one P1 cell: from a constant start every iterate stays constant, so this is exactly the scalar Newton
// method, and its only root is known. Full steps must cycle; the watchdog must break the cycle by going
// back to the best iterate and backtracking from it, and then converge to the root.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "assembly/mesh_generators.hpp"
#include "bricks/weak_form_brick.hpp"
#include "models/model.hpp"
#include "models/solvers/newton.hpp"

namespace pc {
namespace {

struct CyclingCubic {  // f0 = u^3 - 2u + 2, tested with u
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    const S& u = in.value[0][0];
    out.f0[0][0] = u * u * u - 2.0 * u + 2.0;
  }
};

// The real root of u^3 - 2u + 2, from Cardano's formula.
double cubic_root() { return std::cbrt(-1 + std::sqrt(19.0 / 27)) + std::cbrt(-1 - std::sqrt(19.0 / 27)); }

std::unique_ptr<Model> cubic_model() {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 1, 1, Shape::Quadrilateral));
  auto model = std::make_unique<Model>(mesh);
  model->add_unknown("u", std::make_shared<const FESpace>(mesh, 1, 1));
  model->add_brick(std::make_shared<WeakFormBrick<CyclingCubic>>(
      WeakForm{.name = "cubic", .fields = {{"u"}}, .tests = {"u"}, .couplings = {{"u", "u"}}, .extra_degree = 4},
      CyclingCubic{}));
  model->finalize();
  return model;
}

TEST(NewtonGlobalisation, FullStepsCycleOnTheTextbookCubic) {
  auto model = cubic_model();
  NewtonOptions options;
  options.line_search = false;
  options.max_iterations = 20;
  const NewtonReport report = NewtonSolver(options).solve(*model);
  EXPECT_EQ(report.outcome, NewtonOutcome::MaxIterations);
  EXPECT_NEAR(model->values("u")[0], report.iterations % 2 == 0 ? 0.0 : 1.0, 1e-12) << "not the 0 <-> 1 cycle";
}

TEST(NewtonGlobalisation, WatchdogBreaksTheCycleAndFindsTheRoot) {
  auto model = cubic_model();
  NewtonOptions options;  // the default globalisation
  options.max_iterations = 60;
  const NewtonReport report = NewtonSolver(options).solve(*model);
  ASSERT_TRUE(report.converged()) << report.message;
  int restarts = 0;
  for (const NewtonIteration& it : report.history) restarts += it.restarted;
  EXPECT_GE(restarts, 1);
  for (int i = 0; i < model->values("u").size(); ++i) EXPECT_NEAR(model->values("u")[i], cubic_root(), 1e-12);
  // Until the first restart, the steps are full ones: the watchdog lets the cycle run its course.
  for (const NewtonIteration& it : report.history) {
    if (it.restarted) break;
    if (&it != &report.history.front()) {
      EXPECT_EQ(it.step_length, 1.0);
    }
  }
}

TEST(NewtonGlobalisation, ClassicalBacktrackingAlsoFindsTheRoot) {
  auto model = cubic_model();
  NewtonOptions options;
  options.watchdog = 0;
  options.max_iterations = 60;
  const NewtonReport report = NewtonSolver(options).solve(*model);
  ASSERT_TRUE(report.converged()) << report.message;
  EXPECT_NEAR(model->values("u")[0], cubic_root(), 1e-12);
}

TEST(NewtonGlobalisation, RejectsANegativeWatchdog) {
  NewtonOptions options;
  options.watchdog = -1;
  EXPECT_THROW(NewtonSolver{options}, Error);
}

// Residual entries that are finite but whose norm overflows (f0 = u - 1e300 on one cell): the norm is no
// measure of convergence, so the solve is Diverged, naming the block, and never Converged (issue 11, case 1:
// an infinite tolerance once declared every residual converged).
struct OverflowingLoad {  // f0 = u - 1e300, tested with u
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    out.f0[0][0] = in.value[0][0] - 1e300;
  }
};

TEST(NewtonNonFinite, AnOverflowingResidualNormIsDivergedNamingTheBlock) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 2, 2, Shape::Quadrilateral));
  Model model(mesh);
  model.add_unknown("u", std::make_shared<const FESpace>(mesh, 1, 1));
  model.add_brick(std::make_shared<WeakFormBrick<OverflowingLoad>>(
      WeakForm{.name = "overflow", .fields = {{"u"}}, .tests = {"u"}, .couplings = {{"u", "u"}}, .extra_degree = 2},
      OverflowingLoad{}));
  model.finalize();
  const NewtonReport report = NewtonSolver(NewtonOptions{}).solve(model);
  EXPECT_EQ(report.outcome, NewtonOutcome::Diverged) << to_string(report.outcome) << ": " << report.message;
  EXPECT_NE(report.message.find("block 'u'"), std::string::npos) << report.message;
  EXPECT_NE(report.message.find("not finite"), std::string::npos) << report.message;
  EXPECT_TRUE(model.values("u").allFinite());
}

}  // namespace
}  // namespace pc

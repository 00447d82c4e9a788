// A run moved to a refined mesh mid-way (models/mesh_transfer.hpp), on the dynamic piezoelectric
// manufactured solution (inertia and viscosity, backward Euler, P1): the coarse mesh's state at t = 1/2,
// history fields with it, moves to the mesh bisected twice everywhere without change, and the run goes
// on there. Its error at T = 1 is compared with the coarse run's and the fine run's: it ends near the fine
// run, where a wrong or forgotten history would have it grow past the coarse one.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>

#include "assembly/mesh_bisection.hpp"
#include "assembly/mesh_generators.hpp"
#include "assembly/point_locator.hpp"
#include "models/mesh_transfer.hpp"
#include "models/piezo/initial_potential.hpp"
#include "models/solvers/newton.hpp"
#include "models/stepper.hpp"
#include "support/error_and_temp_dir.hpp"
#include "support/piezo_mms.hpp"

namespace pc {
namespace {

using testing::PiezoMmsExact;
using testing::PiezoMmsPhysics;
using testing::TimeProfile;

const TimeProfile kTime = testing::sine_profile();
constexpr int kSteps = 40;

testing::PiezoMmsProblem problem_on(std::shared_ptr<const Mesh> mesh, const PiezoMmsExact& exact) {
  return testing::build_piezo_mms_problem(mesh, 1, exact, PiezoMmsPhysics{true, true},
                                          std::make_unique<BackwardEuler>(), kTime);
}

// Steps from `from` (the model already there, unless it is the start) to `to`.
void run(testing::PiezoMmsProblem& s, const PiezoMmsExact& exact, double from, double to) {
  StepperOptions options;
  options.start = 0;
  options.end = to;
  options.step = 1.0 / kSteps;
  options.prediction = Prediction::Previous;
  options.estimate_time_error = false;
  NewtonSolver newton;
  StepperCallbacks callbacks;
  if (from == 0) {
    const Eigen::VectorXd v0 = exact.interpolate_vector(s.model->space("v"), kTime.g_dot(0));
    s.scheme->set_initial_state(*s.model, Eigen::VectorXd::Zero(v0.size()), v0);
    callbacks.on_start = [&](Model& m) { return solve_initial_potential(m, *s.scheme, newton); };
  } else {
    StepperState state;
    state.time = from;
    state.step_size = options.step;
    state.steps = int(std::lround(from * kSteps));
    options.resume = state;
  }
  const RunSummary summary = Stepper(options).run(*s.model, *s.scheme, newton, callbacks);
  ASSERT_TRUE(summary.completed) << summary.message;
}

TEST(MeshTransfer, ARunMovedToARefinedMeshMidWayEndsNearTheFineRun) {
  const PiezoMmsExact exact;
  const auto coarse_mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 4, 4, Shape::Triangle));
  std::vector<int> all(coarse_mesh->num_cells());
  for (int c = 0; c < coarse_mesh->num_cells(); ++c) all[c] = c;
  const MeshBisection once = bisect(*coarse_mesh, all, RefinementEdge::Longest);
  std::vector<int> every(once.mesh->num_cells());
  for (int c = 0; c < once.mesh->num_cells(); ++c) every[c] = c;
  MeshBisection twice = bisect(*once.mesh, every);
  for (int& p : twice.parent_cell) p = once.parent_cell[p];
  ASSERT_EQ(twice.mesh->num_cells(), 4 * coarse_mesh->num_cells());

  auto coarse = problem_on(coarse_mesh, exact);
  auto fine = problem_on(twice.mesh, exact);
  auto moved = problem_on(twice.mesh, exact);
  run(coarse, exact, 0, 0.5);
  transfer_model_state(*coarse.model, *coarse.scheme, *moved.model, *moved.scheme, twice.parent_cell);
  EXPECT_EQ(moved.model->time(), coarse.model->time());
  const PointLocator coarse_locator(*coarse_mesh), fine_locator(*twice.mesh);
  for (const std::string& field : coarse.model->field_names()) {
    if (coarse.model->field_kind(field) == FieldKind::Affine) continue;
    for (const std::array<double, 2>& p : {std::array<double, 2>{0.3, 0.7}, std::array<double, 2>{0.81, 0.14}}) {
      const auto a = evaluate_at(coarse.model->space(field), coarse.model->values(field), coarse_locator, p.data());
      const auto b = evaluate_at(moved.model->space(field), moved.model->values(field), fine_locator, p.data());
      for (size_t c = 0; c < a.size(); ++c) EXPECT_NEAR(a[c], b[c], 1e-12 * (1 + std::abs(a[c]))) << field;
    }
  }
  run(coarse, exact, 0.5, 1.0);
  run(moved, exact, 0.5, 1.0);
  run(fine, exact, 0, 1.0);
  const auto error = [&](const Model& m) { return testing::piezo_mms_errors(m, exact, kTime.g(1.0)); };
  const testing::PiezoMmsErrors c = error(*coarse.model), f = error(*fine.model), t = error(*moved.model);
  std::printf("H1 error of u at T: coarse %.4e, moved at T/2 %.4e, fine %.4e; of phi: %.4e, %.4e, %.4e\n", c.u_h1,
              t.u_h1, f.u_h1, c.phi_h1, t.phi_h1, f.phi_h1);
  // Half the mesh size halves the H1 error. The moved run carries the coarse mesh's error of T/2 on in
  // its dynamics (measured: a fifth of the way back to the coarse run for u, none for phi, which has no
  // dynamics of its own); a lost or wrong history would put it far beyond the coarse run.
  EXPECT_LT(f.u_h1, 0.6 * c.u_h1);
  EXPECT_LT(t.u_h1 - f.u_h1, 0.3 * (c.u_h1 - f.u_h1));
  EXPECT_LT(t.phi_h1 - f.phi_h1, 0.05 * (c.phi_h1 - f.phi_h1));
}

TEST(MeshTransfer, AnotherModelIsRefused) {
  const PiezoMmsExact exact;
  const auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 2, 2, Shape::Triangle));
  auto s = problem_on(mesh, exact);
  // Quasi-static: no acceleration, no history of the velocity.
  auto other =
      testing::build_piezo_mms_problem(mesh, 1, exact, PiezoMmsPhysics{}, std::make_unique<BackwardEuler>(), kTime);
  std::vector<int> parents(mesh->num_cells());
  for (int c = 0; c < mesh->num_cells(); ++c) parents[c] = c;
  testing::expect_error_containing(
      [&] { transfer_model_state(*s.model, *s.scheme, *other.model, *other.scheme, parents); },
      {"mesh transfer: the models have different fields"});
}

}  // namespace
}  // namespace pc

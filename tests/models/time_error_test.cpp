// The time error estimate (models/time_error_estimate.hpp) and the adaptive steps (StepperOptions::adaptive),
// on the manufactured piezoelectric problem of support/piezo_mms.hpp (P2, 4 x 4 cells of the unit square).
//
//  - The linearised global estimate of u, v and phi against their true time errors at the end (the same
//    mesh, the reference Richardson-extrapolated from 320 and 640 steps, so that the spatial error
//    cancels), quasi-static (viscosity) and with inertia: effectivities within [0.8, 1.25] (BDF2 with
//    inertia: the floor [0.5, 3]; measured 0.70-0.87), and the same at 20 and 40 steps (the estimate has
//    the scheme's order).
//  - A smoothed step g = tanh((t - 1/4) / 0.01): adaptive steps reach a smaller error than uniform ones
//    for the same number of Newton solves (rejected attempts counted), at most 1 in 10 of them rejected,
//    and put their small steps in the transient.
//  - The controller's settings are refused with their names and values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>

#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"
#include "models/piezo/initial_potential.hpp"
#include "models/solvers/newton.hpp"
#include "models/stepper.hpp"
#include "models/time_error_estimate.hpp"
#include "models/time_scheme.hpp"
#include "support/piezo_mms.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

using testing::PiezoMmsExact;
using testing::PiezoMmsPhysics;
using testing::TimeProfile;

const PiezoMmsPhysics kDynamic{true, true};
const PiezoMmsPhysics kQuasiStatic{false, true};
const TimeProfile kSmooth = testing::sine_profile();

// A smoothed step from -1 to 1 of width w at t0: g = tanh((t - t0) / w).
TimeProfile smoothed_step(double t0, double w) {
  auto sech2 = [=](double t) { return 1 / (std::cosh((t - t0) / w) * std::cosh((t - t0) / w)); };
  return {[=](double t) { return std::tanh((t - t0) / w); }, [=](double t) { return sech2(t) / w; },
          [=](double t) { return -2 * sech2(t) * std::tanh((t - t0) / w) / (w * w); }};
}

using SchemeFactory = std::function<std::unique_ptr<TimeScheme>()>;
const SchemeFactory kBackwardEuler = [] { return std::make_unique<BackwardEuler>(); };
const SchemeFactory kBDF2 = [] { return std::make_unique<BDF2>(); };

struct StepperRun {
  std::map<std::string, Eigen::VectorXd> values;  // at the end
  std::shared_ptr<TimeErrorEstimator> estimator;  // for its norm
  RunSummary summary;
  int solves = 0;          // Newton solves: accepted, rejected and cut-back attempts
  double max_u_error = 0;  // over the accepted steps: L2 error of u against the exact u, over max |g|
  double min_dt = 1e300, max_dt = 0;
  double min_dt_time = 0;  // where the smallest step ended
  double first_dt = 0;
};

std::shared_ptr<const Mesh> square(int n) {
  return std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, n, n, Shape::Triangle));
}

StepperRun run(const SchemeFactory& make, PiezoMmsPhysics physics, const TimeProfile& time, double end, int steps,
               std::optional<AdaptiveSteps> adaptive = {}) {
  PiezoMmsExact exact;
  testing::PiezoMmsProblem p = testing::build_piezo_mms_problem(square(4), 2, exact, physics, make(), time);
  Model& m = *p.model;
  const FESpace& space = m.space("v");
  p.scheme->set_initial_state(m, exact.interpolate_vector(space, time.g(0)),
                              exact.interpolate_vector(space, time.g_dot(0)));
  StepperOptions options;
  options.end = end;
  options.step = end / steps;
  options.prediction = Prediction::Previous;
  options.adaptive = adaptive;
  options.max_attempts = 5000;
  NewtonOptions newton_options;
  newton_options.linear_solver = "eigen-lu";
  NewtonSolver newton(newton_options);
  StepperRun r;
  double g_max = 0;
  StepperCallbacks callbacks;
  callbacks.on_start = [&](Model& model) { return solve_initial_potential(model, *p.scheme, newton); };
  callbacks.on_step = [&](const Model& model, const StepRecord& record) {
    r.max_u_error = std::max(r.max_u_error, testing::piezo_mms_errors(model, exact, time.g(record.time)).u_l2);
    g_max = std::max(g_max, std::abs(time.g(record.time)));
    r.solves += 1 + record.cutbacks + record.rejections;
    if (record.step == 1) r.first_dt = record.dt;
    if (record.dt < r.min_dt) r.min_dt_time = record.time;
    r.min_dt = std::min(r.min_dt, record.dt);
    r.max_dt = std::max(r.max_dt, record.dt);
  };
  r.summary = Stepper(options).run(m, *p.scheme, newton, callbacks);
  EXPECT_TRUE(r.summary.completed) << r.summary.message;
  for (const char* f : {"v", "u", "phi"}) r.values[f] = m.values(f);
  r.estimator = std::make_shared<TimeErrorEstimator>(m, *p.scheme, TimeErrorPropagation::Linearised);
  r.max_u_error /= g_max;
  return r;
}

// Each estimated field's effectivity (estimate over true time error) at the end of an N-step run.
std::map<std::string, double> effectivities(const SchemeFactory& make, int order, PiezoMmsPhysics physics, int steps,
                                            const char* label) {
  const double T = 0.5;
  const StepperRun fine = run(make, physics, kSmooth, T, 320), finer = run(make, physics, kSmooth, T, 640);
  const StepperRun coarse = run(make, physics, kSmooth, T, steps);
  const double two_p = std::pow(2.0, order);
  std::map<std::string, double> out;
  for (const FieldTimeError& f : coarse.summary.time_error.fields) {
    const Eigen::VectorXd reference = (two_p * finer.values.at(f.field) - fine.values.at(f.field)) / (two_p - 1);
    const double truth = coarse.estimator->rms(f.field, coarse.values.at(f.field) - reference) / f.scale;
    out[f.field] = f.global / truth;
    std::printf("%-28s N=%-3d %-2s estimate %.3e  true %.3e  effectivity %.3f\n", label, steps, f.field.c_str(),
                f.global, truth, out[f.field]);
  }
  return out;
}

// Each field's effectivity at 40 steps within [low, high], and within `steady` of its value at 20 steps
// (the estimate has the scheme's order).
void expect_effectivities(const char* label, const SchemeFactory& make, int order, PiezoMmsPhysics physics, double low,
                          double high, double steady) {
  const auto at20 = effectivities(make, order, physics, 20, label);
  const auto at40 = effectivities(make, order, physics, 40, label);
  ASSERT_EQ(at40.size(), 3u) << label << ": u, v and phi";
  for (const char* f : {"u", "v", "phi"}) {
    EXPECT_GE(at40.at(f), low) << label << ", " << f;
    EXPECT_LE(at40.at(f), high) << label << ", " << f;
    EXPECT_NEAR(at40.at(f) / at20.at(f), 1.0, steady) << label << ", " << f;
  }
}

TEST(TimeErrorEstimate, MatchesTheTrueTimeErrorOfEveryFieldQuasiStatically) {
  expect_effectivities("backward Euler, quasi-static", kBackwardEuler, 1, kQuasiStatic, 0.8, 1.25, 0.05);
  expect_effectivities("BDF2, quasi-static", kBDF2, 2, kQuasiStatic, 0.8, 1.25, 0.05);
}

TEST(TimeErrorEstimate, MatchesTheTrueTimeErrorOfEveryFieldWithInertia) {
  expect_effectivities("backward Euler, dynamic", kBackwardEuler, 1, kDynamic, 0.8, 1.25, 0.05);
  expect_effectivities("BDF2, dynamic", kBDF2, 2, kDynamic, 0.5, 3.0, 0.15);
}

// The summed estimate: right for u where the error is not damped away, and blind to the algebraic fields.
TEST(TimeErrorEstimate, TheSummedEstimateReportsTheIntegratedFieldsOnly) {
  PiezoMmsExact exact;
  testing::PiezoMmsProblem p = testing::build_piezo_mms_problem(square(2), 2, exact, kQuasiStatic, kBDF2(), kSmooth);
  EXPECT_EQ(TimeErrorEstimator::default_fields(*p.model, *p.scheme, TimeErrorPropagation::Summed),
            std::vector<std::string>{"u"});
  EXPECT_EQ(TimeErrorEstimator::default_fields(*p.model, *p.scheme, TimeErrorPropagation::Linearised),
            (std::vector<std::string>{"u", "v", "phi"}));
  EXPECT_CONTAINS(testing::error_of([&] {
                    TimeErrorEstimator(*p.model, *p.scheme, TimeErrorPropagation::Summed, {"u", "phi"});
                  }),
                  "'phi' is not integrated in time");
}

TEST(AdaptiveSteps, BeatUniformStepsOnASharpTransientAtEqualCost) {
  const TimeProfile step = smoothed_step(0.25, 0.01);
  for (const auto& [label, make, tolerance] :
       {std::tuple{"BDF2", kBDF2, 1e-4}, std::tuple{"backward Euler", kBackwardEuler, 1e-4}}) {
    AdaptiveSteps a;
    a.tolerance = tolerance;
    const StepperRun adaptive = run(make, kQuasiStatic, step, 0.5, 20, a);
    const StepperRun uniform = run(make, kQuasiStatic, step, 0.5, adaptive.solves);
    std::printf(
        "%-15s tolerance %.0e: adaptive %d steps, %d solves (%d rejected), dt %.2e .. %.2e, error %.3e, "
        "estimate %.3e | uniform %d steps: error %.3e\n",
        label, tolerance, adaptive.summary.steps, adaptive.solves, adaptive.summary.rejections, adaptive.min_dt,
        adaptive.max_dt, adaptive.max_u_error, adaptive.summary.time_error.max_global(), uniform.solves,
        uniform.max_u_error);
    EXPECT_LT(adaptive.max_u_error, uniform.max_u_error / 3) << label;
    EXPECT_LT(adaptive.summary.rejections, adaptive.summary.steps / 10) << label;
    EXPECT_LT(adaptive.min_dt, adaptive.max_dt / 50) << label << ": the steps should follow the transient";
    EXPECT_NEAR(adaptive.min_dt_time, 0.25, 0.03) << label << ": the smallest step belongs in the transient";
  }
}

// A run that starts in its transient: g = tanh(t / 0.02) rises from 0 at once. The first steps have no
// estimate of their own; the probe judges the first one once the second's estimate covers it and cuts it
// until it is within the tolerance. Without it the first step is what the user gave and decides the run's
// error.
TEST(AdaptiveSteps, CutTheFirstStepUntilTheStartIsWithinTheTolerance) {
  const TimeProfile onset = smoothed_step(0.0, 0.02);
  for (const auto& [label, make] : {std::pair{"BDF2", kBDF2}, std::pair{"backward Euler", kBackwardEuler}}) {
    AdaptiveSteps a;
    a.tolerance = 1e-4;
    const StepperRun controlled = run(make, kQuasiStatic, onset, 0.5, 10, a);
    a.control_first_step = false;
    const StepperRun given = run(make, kQuasiStatic, onset, 0.5, 10, a);
    std::printf("%-15s first step %.3e, error %.3e, %d steps | the step given: %.3e, error %.3e, %d steps\n", label,
                controlled.first_dt, controlled.max_u_error, controlled.summary.steps, given.first_dt,
                given.max_u_error, given.summary.steps);
    EXPECT_LT(controlled.first_dt, given.first_dt / 10) << label;
    EXPECT_LT(controlled.max_u_error, given.max_u_error / 3) << label;
  }
}

TEST(AdaptiveSteps, BadSettingsAreRefusedNamingThem) {
  auto refusal = [](auto change) {
    StepperOptions o;
    o.adaptive = AdaptiveSteps{};
    change(o);
    return testing::error_of([&] { Stepper{o}; });
  };
  EXPECT_CONTAINS(refusal([](StepperOptions& o) { o.adaptive->tolerance = 0; }),
                  "the tolerance must be in (0, 1), got 0");
  EXPECT_CONTAINS(refusal([](StepperOptions& o) { o.adaptive->tolerance = 2; }), "got 2");
  EXPECT_CONTAINS(refusal([](StepperOptions& o) { o.adaptive->max_growth = 3; }),
                  "max_growth must be in (1, 2], got 3");
  EXPECT_CONTAINS(refusal([](StepperOptions& o) { o.adaptive->safety = 0; }), "safety must be in (0, 1], got 0");
  EXPECT_CONTAINS(refusal([](StepperOptions& o) { o.adaptive->max_cut = 1; }), "max_cut must be in (0, 1), got 1");
  EXPECT_CONTAINS(refusal([](StepperOptions& o) { o.adaptive->factorization_cost = -1; }),
                  "factorization_cost must be >= 0, got -1");
  EXPECT_CONTAINS(refusal([](StepperOptions& o) { o.estimate_time_error = false; }), "need the time error estimate");
}

}  // namespace
}  // namespace pc

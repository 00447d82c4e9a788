// The time error estimate and adaptive steps as a scene user meets them: time.adaptive read and its bad
// values refused with their path; history.csv's dt and err_time_* columns and summary.json's time_error;
// and the paper's scene (15 x 5, conductive), where the estimates of u, v and phi at the end are checked
// against the true time error (Richardson from 2N and 4N steps on the same mesh: backward Euler is first
// order there) at N = 80 and the scene's 200 steps: effectivities within [0.5, 3] (at 40 steps v's is 3.3).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "models/scene/scene.hpp"
#include "models/scene/scene_runner.hpp"
#include "models/time_error_estimate.hpp"
#include "support/csv_table.hpp"
#include "support/error_and_temp_dir.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";
const std::vector<std::string> kCoarse{"mesh.nx=15", "mesh.ny=5"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(TimeAdaptiveKey, IsReadAsATolerance_OrAnObject_AndBadValuesAreRefusedWithTheirPath) {
  EXPECT_FALSE(load_scene_file(kScene, kCoarse).adaptive.has_value());
  const Scene plain = load_scene_file(kScene, with(kCoarse, {"time.adaptive=1e-3"}));
  ASSERT_TRUE(plain.adaptive.has_value());
  EXPECT_EQ(plain.adaptive->tolerance, 1e-3);
  const Scene full = load_scene_file(
      kScene, with(kCoarse, {R"(time.adaptive={"tolerance": 0.01, "max_step": 0.005, "factorization_cost": 4})"}));
  EXPECT_EQ(full.adaptive->tolerance, 0.01);
  EXPECT_EQ(full.adaptive->max_step, 0.005);
  EXPECT_EQ(full.adaptive->factorization_cost, 4);
  auto problem = [&](const std::string& set) {
    return testing::error_of([&] { load_scene_file(kScene, with(kCoarse, {set})); });
  };
  EXPECT_CONTAINS(problem("time.adaptive=0"), "time.adaptive");
  EXPECT_CONTAINS(problem("time.adaptive=0"), "got 0");
  EXPECT_CONTAINS(problem(R"(time.adaptive="fine")"), "must be a tolerance (e.g. 1e-3) or an object");
  EXPECT_CONTAINS(problem(R"(time.adaptive={"tol": 0.01})"), "tol");
  EXPECT_CONTAINS(problem(R"(time.adaptive={"tolerance": 0.01, "max_step": 5})"), "time.adaptive.max_step");
}

// The run's own u, v at the end, and its estimate.
struct PaperRun {
  std::map<std::string, Eigen::VectorXd> values;
  FoundationRunResult result;
};

PaperRun run_paper(int steps) {
  const Scene scene = load_scene_file(kScene, kCoarse);
  FoundationRun run(scene, find_foundation(scene, "conductive"));
  PaperRun r;
  r.result = run.run("", false, steps);
  EXPECT_TRUE(r.result.completed) << r.result.message;
  for (const char* f : {"u", "v", "phi"}) r.values[f] = run.model().values(f);
  return r;
}

class PaperSceneTimeError : public ::testing::TestWithParam<int> {};

TEST_P(PaperSceneTimeError, TheEstimatesMatchTheTrueTimeError) {
  const int steps = GetParam();
  const PaperRun coarse = run_paper(steps), fine = run_paper(2 * steps), finer = run_paper(4 * steps);
  const Scene scene = load_scene_file(kScene, kCoarse);
  FoundationRun for_norm(scene, find_foundation(scene, "conductive"));
  const BackwardEuler names;
  const TimeErrorEstimator norm(for_norm.model(), names, TimeErrorPropagation::Linearised, {"u", "v", "phi"});
  ASSERT_EQ(coarse.result.time_error.size(), 3u);
  for (const FieldTimeError& f : coarse.result.time_error) {
    const Eigen::VectorXd& y = coarse.values.at(f.field);
    const Eigen::VectorXd reference = 2 * finer.values.at(f.field) - fine.values.at(f.field);
    const double truth = norm.rms(f.field, y - reference) / f.scale;
    std::printf("paper scene (15 x 5, %d steps) %s: estimate %.3e, true %.3e, effectivity %.3f\n", steps,
                f.field.c_str(), f.global, truth, f.global / truth);
    EXPECT_GE(f.global / truth, 0.5) << f.field;
    EXPECT_LE(f.global / truth, 3.0) << f.field;
  }
}

INSTANTIATE_TEST_SUITE_P(Steps, PaperSceneTimeError, ::testing::Values(80, 200));

class AdaptiveSceneRun : public testing::TemporaryDirectoryTest {};

TEST_F(AdaptiveSceneRun, WritesItsStepsAndEstimates) {
  const Scene scene = load_scene_file(kScene, with(kCoarse, {"time.adaptive=0.01", "time.steps=200"}));
  FoundationRun run(scene, find_foundation(scene, "conductive"));
  const FoundationRunResult r = run.run((directory_ / "conductive").string(), false);
  ASSERT_TRUE(r.completed) << r.message;
  const testing::Table history = testing::read_csv(directory_ / "conductive" / "history.csv");
  const int dt = history.column("dt"), u = history.column("err_time_u");
  double smallest = 1e300, largest = 0;
  for (const auto& row : history.rows) {
    smallest = std::min(smallest, row[size_t(dt)]);
    largest = std::max(largest, row[size_t(dt)]);
  }
  std::printf("adaptive paper scene, tolerance 0.01: %d steps, dt %.2e .. %.2e, estimate of u %.3e\n", r.steps,
              smallest, largest, history.rows.back()[size_t(u)]);
  EXPECT_GT(largest, 2 * smallest) << "the controller should have changed the step";
  EXPECT_LT(r.steps, 200) << "the first step was the scene's 1/200 of the span";
  EXPECT_LT(history.rows.back()[size_t(u)], 0.01);
  const std::string summary = testing::read_text(directory_ / "conductive" / "summary.json");
  EXPECT_CONTAINS(summary, "\"time_error\"");
  EXPECT_CONTAINS(summary, "\"tolerance\": 0.01");
}

}  // namespace
}  // namespace pc

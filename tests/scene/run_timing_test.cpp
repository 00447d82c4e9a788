// A run's time by phase (models/scene/run_timing.hpp): every phase is measured and non-negative, they sum
// to the wall time, writing into a folder shows as output, summary.json carries them as "timing", and a
// study sees every accepted step (FoundationRunOptions::after_step).
#include <gtest/gtest.h>

#include "models/scene/run_timing.hpp"
#include "models/scene/scene_runner.hpp"
#include "support/error_and_temp_dir.hpp"

namespace pc {
namespace {

class RunTiming : public testing::TemporaryDirectoryTest {};

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";

TEST_F(RunTiming, PhasesAreMeasuredAndSumToTheWallTime) {
  const Scene scene = load_scene_file(kScene, {"mesh.nx=15", "mesh.ny=5", "time.steps=12", "output.vtu_every=5"});
  FoundationRun run(scene, find_foundation(scene, "conductive"));
  FoundationRunOptions options;
  options.directory = (directory_ / "conductive").string();
  options.progress = false;
  std::vector<int> steps_seen;
  options.after_step = [&](const StepRecord& r) { steps_seen.push_back(r.step); };
  const FoundationRunResult r = run.run(options);
  ASSERT_TRUE(r.completed) << r.message;

  EXPECT_EQ(steps_seen, (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}));
  EXPECT_GT(r.jacobian_seconds, 0.0);
  EXPECT_LT(r.jacobian_seconds, r.assembly_seconds);
  EXPECT_GT(r.output_seconds, 0.0) << "history rows, VTU files and the final tables were written";
  const std::vector<RunPhase> phases = run_phases(r);
  std::vector<std::string> names;
  double sum = 0;
  for (const RunPhase& p : phases) {
    names.push_back(p.name);
    EXPECT_GE(p.seconds, 0.0) << p.name;
    sum += p.seconds;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"assembly_residual", "assembly_jacobian", "factorize", "solve",
                                             "condensation", "output", "other"}));
  EXPECT_NEAR(sum, r.wall_seconds, 1e-12 * r.wall_seconds);

  const Json summary = read_json_file(options.directory + "/summary.json");
  const Json& timing = summary.at("timing");
  double summary_sum = 0;
  for (const RunPhase& p : phases) {
    EXPECT_EQ(timing.at(p.name + "_s").as_number(), p.seconds) << p.name;
    summary_sum += timing.at(p.name + "_s").as_number();
  }
  EXPECT_NEAR(summary_sum, summary.at("wall_s_total").as_number(), 1e-12 * r.wall_seconds);
  EXPECT_EQ(timing.at("factorizations").as_number(), double(r.factorizations));
}

// Without a folder nothing is written, but the history row of each step is still computed (the probes).
TEST_F(RunTiming, ARunWithoutAFolderHasOnlyItsProbesAsOutput) {
  const Scene scene = load_scene_file(kScene, {"mesh.nx=15", "mesh.ny=5", "time.steps=4"});
  const FoundationRunResult r = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
  ASSERT_TRUE(r.completed) << r.message;
  EXPECT_GE(r.output_seconds, 0.0);
  EXPECT_LT(r.output_seconds, r.wall_seconds);
}

}  // namespace
}  // namespace pc

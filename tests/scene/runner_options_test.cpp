// The runner's options as a user meets them (issue 43), run as a separate process: --plugin for `run`
// and `check` (a scene names a plugin's law without listing the plugin), the same predicted time from
// `check` and from a run's first line, and the note that a --set time.steps does not reach the phi_f sweep.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "support/error_and_temp_dir.hpp"
#include "support/runner_process.hpp"
#include "support/test_helpers.hpp"

// Built with the runner only (PIEZOCONTACT_BUILD_EXAMPLES), whose path CMake passes.
#ifdef PIEZOCONTACT_RUNNER
namespace pc {
namespace {

const std::string kPaper = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";
// The consumer's scene, whose friction law is the velocity_weakening plugin's, the plugin built by the tests.
const std::string kSlider = std::string(PIEZOCONTACT_SCENES) + "/../examples/consumer/slider.json";
const std::string kPlugin = std::string(PIEZOCONTACT_TEST_PLUGINS) + "/libvelocity_weakening.so";

class RunnerOptions : public testing::TemporaryDirectoryTest {
 protected:
  testing::RunnerOutcome run(const std::string& arguments) {
    return testing::run_runner(PIEZOCONTACT_RUNNER, arguments, directory_);
  }
};

TEST_F(RunnerOptions, PluginLoadsALawTheSceneNamesWithoutListingIt) {
  const std::string scene = "'" + kSlider + "' --set 'plugins=[]' --set mesh.nx=6 --set mesh.ny=2";
  const std::string out = " --set time.steps=2 --quiet --out '" + (directory_ / "results").string() + "'";
  const testing::RunnerOutcome refused = run("run " + scene + out);
  EXPECT_EQ(refused.status, 1) << refused.err;
  EXPECT_CONTAINS(refused.err, "'contact.law_tangential': unknown friction law 'velocity_weakening'");

  const testing::RunnerOutcome checked = run("check " + scene + " --plugin '" + kPlugin + "'");
  EXPECT_EQ(checked.status, 0) << checked.err;
  EXPECT_CONTAINS(checked.out, "scene 'slider' is valid");

  const testing::RunnerOutcome ran = run("run " + scene + out + " --plugin '" + kPlugin + "'");
  ASSERT_EQ(ran.status, 0) << ran.err;
  for (const char* foundation : {"conductive", "insulated"})
    EXPECT_CONTAINS(testing::read_text(directory_ / "results" / foundation / "summary.json"), "\"completed\": true");
}

TEST_F(RunnerOptions, PluginNeedsAFileThatIsAPlugin) {
  const testing::RunnerOutcome missing = run("check '" + kPaper + "' --plugin " + (directory_ / "none.so").string());
  EXPECT_EQ(missing.status, 1);
  EXPECT_CONTAINS(missing.err, "plugin '" + (directory_ / "none.so").string() + "': no such file");
}

// "predicted 96.3 ms" as seconds; -1 when the text has no prediction.
double predicted_seconds(const std::string& text) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex("predicted ([0-9.e+-]+) (us|ms|s|min|h)[ (]"))) return -1;
  const std::string unit = m[2];
  const double scale = unit == "us" ? 1e-6 : unit == "ms" ? 1e-3 : unit == "s" ? 1 : unit == "min" ? 60 : 3600;
  return std::stod(m[1]) * scale;
}

TEST_F(RunnerOptions, CheckAndRunPredictTheSameTime) {
  // 20 steps of the paper's mesh: 96 ms, which a run once printed as "0 s".
  const std::string scene = "'" + kPaper + "' --set time.steps=20";
  const testing::RunnerOutcome checked = run("check " + scene);
  ASSERT_EQ(checked.status, 0) << checked.err;
  const testing::RunnerOutcome ran =
      run("run " + scene + " --only conductive --no-sweep --out '" + (directory_ / "results").string() + "'");
  ASSERT_EQ(ran.status, 0) << ran.err;
  const double check_seconds = predicted_seconds(checked.out), run_seconds = predicted_seconds(ran.out);
  EXPECT_DOUBLE_EQ(check_seconds, 0.096) << checked.out;  // the cost model's 4.8 ms a step at 3843 dofs
  EXPECT_EQ(run_seconds, check_seconds) << ran.out;
}

TEST_F(RunnerOptions, ASetStepsTheSweepDoesNotTakeIsNoted) {
  const std::string scene =
      "'" + kPaper + "' --set mesh.nx=6 --set mesh.ny=2 --set time.steps=2 --set 'output.phi_f_sweep=[1]'";
  const std::string out = " --only conductive --out '" + (directory_ / "results").string() + "'";
  const testing::RunnerOutcome noted = run("run " + scene + out);
  ASSERT_EQ(noted.status, 0) << noted.err;
  EXPECT_CONTAINS(noted.out,
                  "note: --set time.steps=2 applies to the main runs; the phi_f sweep keeps its 50 steps "
                  "(output.sweep_steps)\n");
  // Setting the sweep's steps too, or running no sweep: nothing to note.
  for (const std::string more : {" --set output.sweep_steps=3", " --no-sweep"}) {
    const testing::RunnerOutcome quiet = run("run " + scene + out + more);
    ASSERT_EQ(quiet.status, 0) << quiet.err;
    EXPECT_EQ(quiet.out.find("note:"), std::string::npos) << more << "\n" << quiet.out;
  }
}

}  // namespace
}  // namespace pc
#endif

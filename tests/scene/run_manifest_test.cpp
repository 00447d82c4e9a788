// The run manifest and resume in-process (the runner's process tests in run_robustness_test.cpp need the
// runner binary; these run in every build, the sanitizers' included): a run stopped by its budget and
// resumed ends with the files of an uninterrupted run, byte for byte; the manifest records the scene, the
// state and the files; a rerun removes an earlier run's files; a resume of another scene is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "models/scene/run_manifest.hpp"
#include "models/scene/scene_runner.hpp"
#include "support/error_and_temp_dir.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

namespace fs = std::filesystem;
using testing::read_text;

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";

Scene small_scene(std::vector<std::string> extra = {}) {
  std::vector<std::string> overrides = {"mesh.nx=8", "mesh.ny=3", "time.steps=24", "output.vtu_every=5",
                                        "output.checkpoint_every=4"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  return load_scene_file(kScene, overrides);
}

SceneRunOptions quiet_into(const fs::path& out, bool resume = false) {
  SceneRunOptions o;
  o.output_directory = out.string();
  o.progress = false;
  o.only = {"conductive"};
  o.sweep = false;
  o.resume = resume;
  return o;
}

std::vector<std::string> files_of(const fs::path& dir) {
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().filename() != ".piezocontact.lock" &&
        entry.path().filename() != "manifest.json")
      files.push_back(fs::relative(entry.path(), dir).string());
  std::sort(files.begin(), files.end());
  return files;
}

// The summary without its run times (wall_s_total and the timing object's phases).
std::string without_wall_time(const std::string& summary) {
  const std::string no_wall = std::regex_replace(summary, std::regex("\"wall_s_total\": [^,]*,"), "");
  return std::regex_replace(no_wall, std::regex("\"timing\": \\{[^}]*\\},"), "");
}

class RunManifestTest : public testing::TemporaryDirectoryTest {};

TEST_F(RunManifestTest, AStoppedRunResumedEndsWithTheFilesOfAnUninterruptedOne) {
  const fs::path whole = directory_ / "whole", stopped = directory_ / "stopped";
  ASSERT_TRUE(run_scene(small_scene(), quiet_into(whole)));
  EXPECT_FALSE(run_scene(small_scene({"time.max_attempts=10"}), quiet_into(stopped)));
  EXPECT_TRUE(fs::exists(stopped / "conductive" / "checkpoint.bin"));
  const std::string manifest = read_text(stopped / "manifest.json");
  EXPECT_CONTAINS(manifest, "\"state\": \"stopped\"");
  EXPECT_CONTAINS(manifest, "max_attempts = 10");
  EXPECT_CONTAINS(manifest, "\"conductive/checkpoint.bin\"");

  ASSERT_TRUE(run_scene(small_scene(), quiet_into(stopped, /*resume=*/true)));
  ASSERT_EQ(files_of(whole), files_of(stopped));
  for (const std::string& f : files_of(whole)) {
    const std::string a = read_text(whole / f), b = read_text(stopped / f);
    EXPECT_TRUE(f.ends_with("summary.json") ? without_wall_time(a) == without_wall_time(b) : a == b) << f;
  }
  const std::string after = read_text(stopped / "manifest.json");
  EXPECT_CONTAINS(after, "\"state\": \"completed\"");
  EXPECT_CONTAINS(after, "\"resumes\": 1");
  EXPECT_FALSE(fs::exists(stopped / "conductive" / "checkpoint.bin")) << "a completed run keeps no checkpoint";
}

TEST_F(RunManifestTest, ARerunRemovesTheEarlierRunsFilesAndTheManifestListsItsOwn) {
  const fs::path out = directory_ / "out";
  ASSERT_TRUE(run_scene(small_scene({"output.vtu_every=1"}), quiet_into(out)));
  ASSERT_TRUE(fs::exists(out / "conductive" / "paper2d_000024.vtu"));
  ASSERT_TRUE(run_scene(small_scene({"time.steps=4"}), quiet_into(out)));
  EXPECT_FALSE(fs::exists(out / "conductive" / "paper2d_000024.vtu"));
  const std::string manifest = read_text(out / "manifest.json");
  for (const std::string& f : files_of(out)) EXPECT_CONTAINS(manifest, "\"" + f + "\"");
  EXPECT_CONTAINS(manifest, "\"fingerprint\": \"" + scene_fingerprint(small_scene({"time.steps=4"})) + "\"");
}

TEST_F(RunManifestTest, TheFingerprintIgnoresBudgetsButNotTheScene) {
  EXPECT_EQ(scene_fingerprint(small_scene()), scene_fingerprint(small_scene({"time.max_wall_seconds=5"})));
  EXPECT_EQ(scene_fingerprint(small_scene()), scene_fingerprint(small_scene({"output.checkpoint_every=1"})));
  EXPECT_NE(scene_fingerprint(small_scene()), scene_fingerprint(small_scene({"contact.c_nu=1e13"})));
  const fs::path out = directory_ / "out";
  EXPECT_FALSE(run_scene(small_scene({"time.max_attempts=2"}), quiet_into(out)));
  EXPECT_CONTAINS(testing::error_of([&] { run_scene(small_scene({"contact.c_nu=1e13"}), quiet_into(out, true)); }),
                  "is of another scene");
}

}  // namespace
}  // namespace pc

// The runner against hostile input and conditions (issue 11): non-finite results stop the run and are
// never written, an unwritable or empty --out is refused before the first step with a clear message, a
// second run into a folder in use is refused, a stopped run says why on stderr even with --quiet, a rerun
// never mixes its files with an earlier run's, and a killed or stopped run resumes to the very results of
// an uninterrupted one.
// The runner is run as a user runs it, as a separate process (PIEZOCONTACT_RUNNER).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <signal.h>
#include <sys/wait.h>

#include "support/error_and_temp_dir.hpp"
#include "support/runner_process.hpp"

// Built with the runner only (PIEZOCONTACT_BUILD_EXAMPLES), whose path CMake passes.
#ifdef PIEZOCONTACT_RUNNER
namespace pc {
namespace {

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";
// A small, fast version of the paper's scene.
const std::string kSmall = " --set mesh.nx=6 --set mesh.ny=2 --set time.steps=2 --no-sweep";

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

using Outcome = testing::RunnerOutcome;

class RunRobustness : public testing::TemporaryDirectoryTest {
 protected:
  Outcome run(const std::string& arguments) { return testing::run_runner(PIEZOCONTACT_RUNNER, arguments, directory_); }

  // Starts a long run of the paper's scene in the background (bounded by its own wall-time limit), its
  // output into `out` and its stdout and stderr into `log`; `extra` are more runner arguments.
  pid_t start_long_run(const std::filesystem::path& out, const std::filesystem::path& log,
                       const std::vector<std::string>& extra) {
    std::vector<std::string> args = {
        PIEZOCONTACT_RUNNER,        "run",   kScene,      "--set", "time.steps=100000", "--set",
        "time.max_wall_seconds=60", "--out", out.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const pid_t pid = fork();
    if (pid == 0) {
      std::freopen(log.c_str(), "w", stdout);
      std::freopen(log.c_str(), "a", stderr);
      std::vector<char*> argv;
      for (std::string& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(PIEZOCONTACT_RUNNER, argv.data());
      _exit(127);
    }
    return pid;
  }

  // Waits (at most 30 s) until the file holds at least `bytes` bytes.
  static void wait_for(const std::filesystem::path& file, std::size_t bytes) {
    for (int i = 0; i < 600 && (!std::filesystem::exists(file) || read_text(file).size() < bytes); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }

  // Every file under the directory: none may hold a non-finite number.
  void expect_no_non_finite_numbers(const std::filesystem::path& dir) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
      if (!entry.is_regular_file() || entry.path().extension() == ".vtu") continue;
      const std::string text = read_text(entry.path());
      for (const char* bad : {"nan", "inf", "NaN", "Infinity"})
        EXPECT_EQ(text.find(bad), std::string::npos) << entry.path() << " holds '" << bad << "'";
    }
  }
};

// Case 1: a material constant of 1e300 overflows every residual norm; the run must not be "completed".
TEST_F(RunRobustness, AnOverflowingMaterialStopsTheRunAndWritesNoNonFiniteNumber) {
  const auto out = directory_ / "out";
  const Outcome o = run("run " + kScene + kSmall + " --only conductive --set 'material.piezo_E[0][0]=1e300' --out " +
                        quoted(out.string()) + " --quiet");
  EXPECT_EQ(o.status, 1) << o.err;
  const std::string summary = read_text(out / "conductive" / "summary.json");
  EXPECT_NE(summary.find("\"completed\": false"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"message\""), std::string::npos) << summary;
  expect_no_non_finite_numbers(out);
  // Case 11: with --quiet, the stop reason is still on stderr.
  EXPECT_NE(o.err.find("STOPPED"), std::string::npos) << "stderr: " << o.err;
  EXPECT_NE(o.err.find("not finite"), std::string::npos) << "stderr: " << o.err;
}

// Case 2: an initial velocity of 1e300: the message names where the first non-finite value appeared.
TEST_F(RunRobustness, AnOverflowingInitialStateStopsTheRunNamingTheCause) {
  const auto out = directory_ / "out";
  const Outcome o =
      run("run " + kScene + kSmall + " --only insulated --set 'time.v0=[1e300,1e300]' --out " + quoted(out.string()));
  EXPECT_EQ(o.status, 1) << o.err;
  EXPECT_EQ(o.err.find("JSON"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("not finite"), std::string::npos) << o.err;
  const std::string summary = read_text(out / "insulated" / "summary.json");
  EXPECT_NE(summary.find("\"completed\": false"), std::string::npos) << summary;
  expect_no_non_finite_numbers(out);
}

// Case 3: every unwritable --out is a clear error naming --out and the path, exit 1, never an abort.
TEST_F(RunRobustness, AnUnwritableOutIsRefusedBeforeTheFirstStep) {
  const auto file = directory_ / "a_file";
  std::ofstream(file) << "not a directory\n";
  for (const std::string& bad : {file.string(), (file / "below").string(), std::string("/dev/null")}) {
    const Outcome o = run("run " + kScene + kSmall + " --out " + quoted(bad));
    EXPECT_EQ(o.status, 1) << bad << ": " << o.err;
    EXPECT_NE(o.err.find("--out"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find(bad), std::string::npos) << o.err;
    EXPECT_EQ(o.out.find("step 1/"), std::string::npos) << "computed before refusing " << bad;
  }
  const Outcome empty = run("run " + kScene + kSmall + " --out ''");
  EXPECT_EQ(empty.status, 1);
  EXPECT_NE(empty.err.find("--out is empty"), std::string::npos) << empty.err;
}

// SIGTERM (or SIGINT) stops a run at the end of its current step: the summary says so, every history row is
// whole, the rest of the scene is not started, and the exit status is 1.
TEST_F(RunRobustness, ASignalStopsTheRunAfterItsStepWithEverythingWritten) {
  const auto out = directory_ / "out";
  const pid_t run_pid = start_long_run(out, directory_ / "run.txt", {"--quiet"});
  ASSERT_GE(run_pid, 0);
  const auto history = out / "conductive" / "history.csv";
  wait_for(history, 200);  // a few steps in
  kill(run_pid, SIGTERM);
  int status = 0;
  waitpid(run_pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "the runner died of the signal instead of stopping";
  EXPECT_EQ(WEXITSTATUS(status), 1);
  const std::string summary = read_text(out / "conductive" / "summary.json");
  EXPECT_NE(summary.find("\"completed\": false"), std::string::npos) << summary;
  EXPECT_NE(summary.find("interrupted by SIGTERM"), std::string::npos) << summary;
  const std::string rows = read_text(history);
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.back(), '\n') << "a half-written row";
  // Every row is whole: as many fields as the header.
  std::istringstream lines(rows);
  std::string header;
  std::getline(lines, header);
  for (std::string line; std::getline(lines, line);)
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), std::count(header.begin(), header.end(), ',')) << line;
  EXPECT_FALSE(std::filesystem::exists(out / "insulated")) << "the next foundation was started";
  EXPECT_NE(read_text(directory_ / "run.txt").find("interrupted by SIGTERM"), std::string::npos);
}

// Case 4: a second run into a folder in use is refused, naming the first run's pid.
TEST_F(RunRobustness, ASecondRunIntoAFolderInUseIsRefused) {
  const auto out = directory_ / "out";
  // The first run, still running while the second starts.
  const pid_t first = start_long_run(out, directory_ / "first.txt", {"--only", "insulated", "--no-sweep"});
  ASSERT_GE(first, 0);
  // Wait until the first run writes its history (it holds the folder by then).
  const auto history = out / "insulated" / "history.csv";
  wait_for(history, 1);
  EXPECT_TRUE(std::filesystem::exists(history)) << read_text(directory_ / "first.txt");
  const Outcome second = run("run " + kScene + kSmall + " --out " + quoted(out.string()));
  kill(first, SIGKILL);
  int status = 0;
  waitpid(first, &status, 0);
  EXPECT_EQ(second.status, 1) << second.out << second.err;
  EXPECT_NE(second.err.find("in use by another run (pid " + std::to_string(first) + ")"), std::string::npos)
      << second.err;
  // Once the first run is gone (however it ended), the folder is free again.
  const Outcome third = run("run " + kScene + kSmall + " --only insulated --out " + quoted(out.string()) + " --quiet");
  EXPECT_EQ(third.status, 0) << third.err;
}

// Memory that runs out (here under ulimit -v, past a user's too generous solver.max_memory_gib) is a
// clear error naming the phase, never an abort; the summary and the manifest say the run stopped.
// At three limits, so that the shortage falls in different places (the model, MUMPS, the BLAS's buffer,
// which OpenBLAS retries for ever unless it was reserved first: assembly/blas_workspace.hpp), on as many
// threads as the machine has (a thread's stack and malloc arena move the point of failure too). The run
// completes from about 550000 KiB on (since gmsh is loaded only for a gmsh mesh, and less is kept at the
// factorisation); 280000 stops it while building, the others in the step.
TEST_F(RunRobustness, RunningOutOfMemoryStopsTheRunNamingThePhase) {
  for (const char* limit_kib : {"280000", "400000", "470000"}) {
    const auto out = directory_ / (std::string("out") + limit_kib);
    const std::string command = "run " + kScene + " --set mesh.nx=300 --set mesh.ny=100 --set time.steps=1 " +
                                "--set solver.max_memory_gib=100 --only conductive --no-sweep --quiet --out " +
                                quoted(out.string());
    const auto log = directory_ / "oom.txt";
    // timeout: a hang under the memory limit (as OpenBLAS's buffer allocation does) fails here, exit 124.
    const int raw =
        std::system(("ulimit -v " + std::string(limit_kib) + "; timeout -k 10 120 " + std::string(PIEZOCONTACT_RUNNER) +
                     " " + command + " >" + quoted(log.string()) + " 2>&1")
                        .c_str());
    ASSERT_TRUE(WIFEXITED(raw)) << limit_kib;
    EXPECT_EQ(WEXITSTATUS(raw), 1) << limit_kib << " KiB: " << read_text(log);
    const std::string said = read_text(log);
    EXPECT_TRUE(
        std::regex_search(said, std::regex("out of memory (in step 1|while building|while reserving the BLAS)")))
        << said;
    if (std::filesystem::exists(out / "conductive" / "summary.json")) {
      EXPECT_NE(read_text(out / "conductive" / "summary.json").find("\"completed\": false"), std::string::npos);
    }
    EXPECT_NE(read_text(out / "manifest.json").find("\"state\": \"stopped\""), std::string::npos)
        << read_text(out / "manifest.json");
  }
}

// Two processes running one scene write the same bytes, also at a size where MUMPS orders its
// factorisation with SCOTCH (whose orderings on several threads differed from process to process, and so
// did the results' last digits: assembly/mumps_handle.cpp keeps it on one thread).
TEST_F(RunRobustness, TwoProcessesRunningOneSceneWriteTheSameResults) {
  std::vector<std::string> histories;
  for (const char* name : {"first", "second"}) {
    const auto out = directory_ / name;
    const std::string command = "run " + kScene + " --set mesh.nx=240 --set mesh.ny=80 --set time.steps=3 " +
                                "--only conductive --no-sweep --quiet --out " + quoted(out.string());
    ASSERT_EQ(std::system((std::string(PIEZOCONTACT_RUNNER) + " " + command + " >/dev/null 2>&1").c_str()), 0);
    histories.push_back(read_text(out / "conductive" / "history.csv"));
  }
  ASSERT_GT(histories[0].size(), 100u);
  EXPECT_EQ(histories[0], histories[1]);
}

// ---- manifest, stale files, resume (case 5) ---------------------------------------------------------

// The files of a result folder, by relative path (the lock and the manifest left out).
std::vector<std::string> files_of(const std::filesystem::path& dir) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name != ".piezocontact.lock" && name != "manifest.json")
      files.push_back(std::filesystem::relative(entry.path(), dir).string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Two result folders hold the same files with the same contents, the run times in summary.json aside
// (wall_s_total and the timing object).
void expect_same_results(const std::filesystem::path& a, const std::filesystem::path& b) {
  ASSERT_EQ(files_of(a), files_of(b));
  for (const std::string& f : files_of(a)) {
    std::string x = read_text(a / f), y = read_text(b / f);
    if (f.ends_with("summary.json")) {
      const std::regex wall("\"wall_s_total\": [^,]*,"), timing("\"timing\": \\{[^}]*\\},");
      x = std::regex_replace(std::regex_replace(x, wall, ""), timing, "");
      y = std::regex_replace(std::regex_replace(y, wall, ""), timing, "");
    }
    EXPECT_TRUE(x == y) << f << " differs";
  }
}

const std::string kResumable = " --only conductive --no-sweep --set output.vtu_every=50 --quiet";

TEST_F(RunRobustness, AKilledRunResumesToTheSameResults) {
  const auto whole = directory_ / "whole", killed = directory_ / "killed";
  const std::string steps = " --set time.steps=3000 --set output.checkpoint_every=25";
  const Outcome reference = run("run " + kScene + steps + kResumable + " --out " + quoted(whole.string()));
  ASSERT_EQ(reference.status, 0) << reference.err;

  const pid_t pid = start_long_run(
      killed, directory_ / "killed.txt",
      {"--set", "time.steps=3000", "--set", "time.max_wall_seconds=0", "--set", "output.checkpoint_every=25", "--only",
       "conductive", "--no-sweep", "--set", "output.vtu_every=50", "--quiet"});
  ASSERT_GE(pid, 0);
  wait_for(killed / "conductive" / "history.csv", 300 * 60);  // some 300 steps in
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it was killed: nothing to resume";
  const std::string manifest = read_text(killed / "manifest.json");
  EXPECT_NE(manifest.find("\"state\": \"running\""), std::string::npos) << manifest;
  EXPECT_TRUE(std::filesystem::exists(killed / "conductive" / "checkpoint.bin"));
  EXPECT_FALSE(std::filesystem::exists(killed / "conductive" / "summary.json"));

  const Outcome resumed = run("run " + kScene + steps + kResumable + " --resume --out " + quoted(killed.string()));
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  expect_same_results(whole, killed);
  const std::string after = read_text(killed / "manifest.json");
  EXPECT_NE(after.find("\"state\": \"completed\""), std::string::npos) << after;
  EXPECT_NE(after.find("\"resumes\": 1"), std::string::npos) << after;
}

// A run stopped by its budget writes a checkpoint at the stop; resumed with a larger budget (budgets do not
// change results, so the scene is the same), it ends as the uninterrupted run.
TEST_F(RunRobustness, ARunStoppedByItsBudgetResumesToTheSameResults) {
  const auto whole = directory_ / "whole", stopped = directory_ / "stopped";
  const std::string scene = kScene + " --set mesh.nx=12 --set mesh.ny=4 --set time.steps=40" + kResumable;
  ASSERT_EQ(run("run " + scene + " --out " + quoted(whole.string())).status, 0);
  const Outcome part = run("run " + scene + " --set time.max_attempts=17 --out " + quoted(stopped.string()));
  EXPECT_EQ(part.status, 1);
  EXPECT_NE(part.err.find("max_attempts"), std::string::npos) << part.err;
  const Outcome rest = run("run " + scene + " --resume --out " + quoted(stopped.string()));
  ASSERT_EQ(rest.status, 0) << rest.err;
  expect_same_results(whole, stopped);
}

// A rerun into the folder of an earlier, longer run: none of the earlier run's files survive (its VTUs
// past the new run's steps, its summary), and a file that is no run's is kept and reported.
TEST_F(RunRobustness, ARerunNeverMixesItsFilesWithAnEarlierRunsAndFlagsForeignOnes) {
  const auto out = directory_ / "out", fresh = directory_ / "fresh";
  const std::string small = kScene + " --set mesh.nx=6 --set mesh.ny=2 --only conductive --no-sweep --quiet";
  ASSERT_EQ(run("run " + small + " --set time.steps=20 --set output.vtu_every=1 --out " + quoted(out.string())).status,
            0);
  ASSERT_TRUE(std::filesystem::exists(out / "conductive" / "paper2d_000020.vtu"));
  // What a run of a version without a manifest would have left, and a file of the user's.
  std::filesystem::remove(out / "manifest.json");
  std::ofstream(out / "conductive" / "paper2d_000077.vtu") << "stale";
  std::ofstream(out / "conductive" / "notes.txt") << "mine";

  const Outcome rerun = run("run " + small + " --set time.steps=2 --out " + quoted(out.string()));
  ASSERT_EQ(rerun.status, 0) << rerun.err;
  EXPECT_NE(rerun.err.find("not of this run"), std::string::npos) << rerun.err;
  EXPECT_NE(rerun.err.find("conductive/notes.txt"), std::string::npos) << rerun.err;
  EXPECT_EQ(read_text(out / "conductive" / "notes.txt"), "mine");
  const std::string manifest = read_text(out / "manifest.json");
  EXPECT_NE(manifest.find("\"not_of_this_run\": [\n    \"conductive/notes.txt\"\n  ]"), std::string::npos) << manifest;
  std::filesystem::remove(out / "conductive" / "notes.txt");
  ASSERT_EQ(run("run " + small + " --set time.steps=2 --out " + quoted(fresh.string())).status, 0);
  expect_same_results(fresh, out);  // exactly a fresh run's files
  EXPECT_EQ(manifest.find("paper2d_000020.vtu"), std::string::npos) << manifest;
}

TEST_F(RunRobustness, ResumeIsRefusedWithoutARunOrForAnotherScene) {
  const auto out = directory_ / "out";
  const std::string small = kScene + kSmall + " --only insulated --quiet";
  const Outcome nothing = run("run " + small + " --resume --out " + quoted(out.string()));
  EXPECT_EQ(nothing.status, 1);
  EXPECT_NE(nothing.err.find("has no manifest.json"), std::string::npos) << nothing.err;
  ASSERT_EQ(run("run " + small + " --set time.max_attempts=1 --out " + quoted(out.string())).status, 1);
  const Outcome other = run("run " + small + " --set mesh.nx=8 --resume --out " + quoted(out.string()));
  EXPECT_EQ(other.status, 1);
  EXPECT_NE(other.err.find("is of another scene"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find("--set mesh.nx=6"), std::string::npos) << other.err;
}

}  // namespace
}  // namespace pc
#endif  // PIEZOCONTACT_RUNNER

#pragma once
// Test support: the runner (PIEZOCONTACT_RUNNER) run as a user runs it, as a separate process, its exit
// status and its stdout and stderr captured through files of a directory.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <sys/wait.h>

#include "support/test_helpers.hpp"

namespace pc::testing {

struct RunnerOutcome {
  int status = -1;  // exit status, or -1 if the runner did not exit normally
  std::string out, err;
};

// `arguments` as a shell reads them; the captures go into `directory`.
inline RunnerOutcome run_runner(const std::string& runner, const std::string& arguments,
                                const std::filesystem::path& directory) {
  const auto out = directory / "stdout.txt", err = directory / "stderr.txt";
  const std::string command = runner + " " + arguments + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(command.c_str());
  RunnerOutcome o;
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  o.out = read_text(out);
  o.err = read_text(err);
  return o;
}

}  // namespace pc::testing

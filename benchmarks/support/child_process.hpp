#pragma once
// Whole-run studies measure peak memory per run, and VmHWM is a process-wide high-water mark: each run
// goes into a fresh child process (the study re-executing itself with its own arguments), which prints
// one line of numbers for the parent.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace pc::study {

// Peak resident set size of this process so far, in KiB (VmHWM of /proc/self/status); -1 if unknown.
inline long peak_rss_kib() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

// This program's own path, to re-execute it as a child.
inline std::string self_executable() { return std::filesystem::read_symlink("/proc/self/exe").string(); }

struct ChildOutput {
  bool ran = false;  // the child printed a line
  int status = -1;   // its exit status as pclose returns it (0: success)
  std::string line;  // its last line on stdout, without the newline
};

// Runs `self_executable() args...` (each argument single-quoted) and returns its last stdout line.
inline ChildOutput run_child(const std::vector<std::string>& args) {
  std::string command = "'" + self_executable() + "'";
  for (const std::string& a : args) command += " '" + a + "'";
  ChildOutput out;
  FILE* child = popen(command.c_str(), "r");
  if (!child) return out;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, child)) {
    out.line = buffer;
    out.ran = true;
  }
  out.status = pclose(child);
  if (!out.line.empty() && out.line.back() == '\n') out.line.pop_back();
  return out;
}

}  // namespace pc::study

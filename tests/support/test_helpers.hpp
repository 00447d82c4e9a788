#pragma once
// Small helpers shared by the tests: the message of the pc::Error an action throws, a substring
// expectation that prints the whole text, and a file's contents.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "assembly/error.hpp"

namespace pc::testing {

// The message of the pc::Error thrown by `action`, or "(no error)".
template <class F> std::string error_of(F&& action) {
  try {
    action();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace pc::testing

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

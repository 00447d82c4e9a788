#pragma once
// Test support: checking that an action throws pc::Error whose message contains given parts, and a
// fixture with a fresh temporary directory per test.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "assembly/error.hpp"

namespace pc::testing {

template <class Action> void expect_error_containing(Action action, const std::vector<std::string>& parts) {
  try {
    action();
    ADD_FAILURE() << "no pc::Error thrown";
  } catch (const Error& error) {
    const std::string what = error.what();
    for (const std::string& part : parts) EXPECT_NE(what.find(part), std::string::npos) << what;
  }
}

class TemporaryDirectoryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ =
        std::filesystem::temp_directory_path() /
        message("piezocontact_", ::getpid(), "_", ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::filesystem::path directory_;
};

}  // namespace pc::testing

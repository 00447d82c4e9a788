// A duration as the run's lines show it: three significant digits, the unit chosen after rounding, at
// each unit's boundary from both sides.
#include <gtest/gtest.h>

#include <limits>

#include "models/output/duration_text.hpp"

namespace pc {
namespace {

TEST(DurationText, ThreeSignificantDigitsInTheUnitThatSuits) {
  EXPECT_EQ(describe_duration(0), "0 s");
  EXPECT_EQ(describe_duration(2.81e-4), "281 us");
  EXPECT_EQ(describe_duration(0.0963), "96.3 ms");
  EXPECT_EQ(describe_duration(0.096), "96 ms");
  EXPECT_EQ(describe_duration(4.2149), "4.21 s");
  EXPECT_EQ(describe_duration(750), "12.5 min");
  EXPECT_EQ(describe_duration(3004), "50.1 min");  // rounded in minutes, not to 3 digits of seconds first
  EXPECT_EQ(describe_duration(9000), "2.5 h");
  EXPECT_EQ(describe_duration(1e6), "278 h");
}

TEST(DurationText, RoundingCarriesIntoTheNextUnit) {
  EXPECT_EQ(describe_duration(9.994e-4), "999 us");
  EXPECT_EQ(describe_duration(9.996e-4), "1 ms");
  EXPECT_EQ(describe_duration(1e-3), "1 ms");
  EXPECT_EQ(describe_duration(0.9994), "999 ms");
  EXPECT_EQ(describe_duration(0.9996), "1 s");
  EXPECT_EQ(describe_duration(59.94), "59.9 s");
  EXPECT_EQ(describe_duration(59.96), "1 min");
  EXPECT_EQ(describe_duration(60), "1 min");
  EXPECT_EQ(describe_duration(3596), "59.9 min");
  EXPECT_EQ(describe_duration(3599.9), "1 h");
  EXPECT_EQ(describe_duration(3600), "1 h");
}

TEST(DurationText, NegativeAndNonFiniteDurations) {
  EXPECT_EQ(describe_duration(-0.0963), "-96.3 ms");
  EXPECT_EQ(describe_duration(std::numeric_limits<double>::infinity()), "?");
  EXPECT_EQ(describe_duration(std::numeric_limits<double>::quiet_NaN()), "?");
}

}  // namespace
}  // namespace pc

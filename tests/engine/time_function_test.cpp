// Time functions: values at known points, integrals against a fine composite Simpson rule (and their
// closed forms), the kinds that count as constant, and the refused arguments.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "assembly/error.hpp"
#include "assembly/time_function.hpp"

namespace pc {
namespace {

double simpson(const TimeFunction& f, double a, double b, int intervals = 200000) {
  const double h = (b - a) / intervals;
  double sum = f.value(a) + f.value(b);
  for (int i = 1; i < intervals; ++i) sum += (i % 2 ? 4 : 2) * f.value(a + i * h);
  return sum * h / 3;
}

std::vector<TimeFunction> every_kind() {
  return {TimeFunction::constant(2.5), TimeFunction::ramp(3, 0.4), TimeFunction::sine(2, 3.7, 0.6, 0.25),
          TimeFunction::table({{-0.2, 1}, {0.3, -2}, {0.5, 4}, {1.1, 4.5}})};
}

TEST(TimeFunction, ValuesAtKnownPoints) {
  EXPECT_EQ(TimeFunction().value(7), 0.0);
  EXPECT_EQ(TimeFunction::constant(2.5).value(-1), 2.5);
  const TimeFunction ramp = TimeFunction::ramp(3, 0.4);
  EXPECT_EQ(ramp.value(-1), 0.0);
  EXPECT_DOUBLE_EQ(ramp.value(0.1), 0.75);
  EXPECT_EQ(ramp.value(0.4), 3.0);
  EXPECT_EQ(ramp.value(9), 3.0);
  const TimeFunction sine = TimeFunction::sine(2, 0.5, std::numbers::pi / 2, 1);  // 1 + 2 cos(pi t)
  EXPECT_NEAR(sine.value(0), 3, 1e-15);
  EXPECT_NEAR(sine.value(1), -1, 1e-15);
  EXPECT_NEAR(sine.value(0.5), 1, 1e-15);
  const TimeFunction table = TimeFunction::table({{-0.2, 1}, {0.3, -2}, {0.5, 4}});
  EXPECT_EQ(table.value(-5), 1.0);
  EXPECT_DOUBLE_EQ(table.value(0.05), -0.5);
  EXPECT_DOUBLE_EQ(table.value(0.4), 1.0);
  EXPECT_EQ(table.value(0.5), 4.0);
  EXPECT_EQ(table.value(3), 4.0);
}

TEST(TimeFunction, IntegralsFromZeroMatchQuadratureOnBothSidesOfZero) {
  for (const TimeFunction& f : every_kind())
    for (double t : {-0.35, 0.0, 0.07, 0.3, 0.41, 1.3, 2.0}) {
      // Simpson is exact on each linear piece; the kinks of ramps and tables cost it O(h^2) only.
      const double reference = t >= 0 ? simpson(f, 0, t) : -simpson(f, t, 0);
      EXPECT_NEAR(f.integral(t), reference, 1e-7) << f.describe() << " at t = " << t;
    }
  // Closed forms: a sine over whole periods integrates to its offset, a ramp's triangle is half its box.
  EXPECT_NEAR(TimeFunction::sine(5, 2, 0.3, 0.5).integral(3), 1.5, 1e-14);
  EXPECT_DOUBLE_EQ(TimeFunction::ramp(3, 0.4).integral(0.4), 0.6);
  EXPECT_DOUBLE_EQ(TimeFunction::ramp(3, 0.4).integral(1.4), 3.6);
}

TEST(TimeFunction, OnlyChangingKindsVary) {
  EXPECT_FALSE(TimeFunction::constant(4).varies());
  EXPECT_FALSE(TimeFunction::sine(0, 10).varies());
  EXPECT_FALSE(TimeFunction::ramp(0, 1).varies());
  EXPECT_FALSE(TimeFunction::table({{0, 2}, {1, 2}}).varies());
  EXPECT_TRUE(TimeFunction::table({{0, 2}, {1, 3}}).varies());
  EXPECT_TRUE(TimeFunction::sine(1, 10).varies());
  EXPECT_TRUE(TimeFunction::ramp(1, 1).varies());
}

void expect_refused(const std::function<void()>& make, const std::string& part) {
  try {
    make();
    ADD_FAILURE() << "accepted; expected an error with '" << part << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(TimeFunction, BadArgumentsAreRefusedNamingThem) {
  expect_refused([] { TimeFunction::ramp(1, 0); }, "the ramp's duration must be > 0, got 0");
  expect_refused([] { TimeFunction::sine(1, -2); }, "the sine's frequency must be > 0, got -2");
  expect_refused([] { TimeFunction::constant(std::nan("")); }, "the constant's value must be finite");
  expect_refused([] { TimeFunction::table({}); }, "a table needs at least one point");
  expect_refused([] { TimeFunction::table({{0, 1}, {0, 2}}); }, "table times must increase, point 1 has t = 0");
}

}  // namespace
}  // namespace pc

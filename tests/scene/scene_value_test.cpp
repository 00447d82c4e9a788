// A scene value has one reader per shape (number, vector, matrix, function of time, declared parameter)
// and one range check: these tests pin the value every accepted form reads to, and that every range
// error, a scene key's or a declared parameter's, reads the same way with the path, bound and value.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "assembly/parameters.hpp"
#include "models/scene/json.hpp"
#include "models/scene/registered_keys.hpp"
#include "models/scene/scene_time_function.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

using testing::error_of;

Json value_of(const std::string& text) { return parse_json(R"({"x": )" + text + "}", "s")["x"]; }

TEST(SceneValue, NumbersReadTheSameInEveryNotation) {
  for (const char* text : {"1000000000000", "1e12", "1E+12", "1000000000000.0", "0.1e13"})
    EXPECT_EQ(value_of(text).as_number(), 1e12) << text;
  EXPECT_EQ(value_of("-0.25").as_number(Range::any()), -0.25);
  EXPECT_EQ(value_of("3").as_int(), 3);
  EXPECT_EQ(value_of("3.0").as_int_at_least(1), 3);
  EXPECT_EQ(value_of("1e2").as_int(), 100);
  // A bound itself is inside a closed range and outside an open one.
  EXPECT_EQ(value_of("0").as_number_at_least(0), 0.0);
  EXPECT_EQ(value_of("1").as_number_in(0, 1), 1.0);
  EXPECT_THROW(value_of("0").as_positive(), Error);
}

TEST(SceneValue, VectorsAndMatricesKeepTheirEntriesInOrder) {
  EXPECT_EQ(value_of("[0.5, -1, 2e3]").as_vector(3), (std::vector<double>{0.5, -1.0, 2000.0}));
  const Eigen::MatrixXd m = value_of("[[1, 2, 3], [4, 5, 6]]").as_matrix(2, 3);
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(m(r, c), 3 * r + c + 1);
  // One entry is a 1x1 matrix only when written as one: a bare number is no matrix.
  EXPECT_EQ(value_of("[[7]]").as_matrix(1, 1)(0, 0), 7.0);
  EXPECT_THROW(value_of("7").as_matrix(), Error);
}

TEST(SceneValue, EveryFormOfAFunctionOfTimeReadsToItsClosedForm) {
  const double pi = std::acos(-1.0);
  EXPECT_EQ(time_function_from_json(value_of("2.5")).value(0.7), 2.5);
  EXPECT_EQ(time_function_from_json(value_of(R"({"type": "constant", "value": -4})")).value(3.0), -4.0);
  const TimeFunction ramp = time_function_from_json(value_of(R"({"type": "ramp", "value": 10, "duration": 2})"));
  EXPECT_DOUBLE_EQ(ramp.value(0.5), 2.5);
  EXPECT_DOUBLE_EQ(ramp.value(5.0), 10.0);
  const TimeFunction sine =
      time_function_from_json(value_of(R"({"type": "sine", "amplitude": 3, "frequency": 2, "offset": 1})"));
  EXPECT_NEAR(sine.value(0.1), 1 + 3 * std::sin(2 * pi * 2 * 0.1), 1e-14);
  const TimeFunction table = time_function_from_json(value_of(R"({"type": "table", "points": [[0, 0], [2, 4]]})"));
  EXPECT_DOUBLE_EQ(table.value(0.5), 1.0);
}

TEST(SceneValue, DeclaredParametersReadTheirValueOrTheirDefault) {
  const std::vector<ParameterDeclaration> declared = {
      {"c_nu", "Pa s/m", "normal damping", std::nullopt, Range::at_least(0)},
      {"p", "1", "exponent", 2.0, Range::positive()}};
  const ChosenEntry entry{"law_normal 'test'", &declared};
  const Json object = parse_json(R"({"contact": {"c_nu": 1e12}})", "s")["contact"];
  const ParameterValues values = read_parameters(object, entry);
  EXPECT_EQ(values.at("c_nu"), 1e12);
  EXPECT_EQ(values.at("p"), 2.0);
  EXPECT_EQ(error_of([&] { read_parameters(parse_json(R"({"contact": {}})", "s")["contact"], entry); }),
            "scene: 'contact.c_nu' is required by law_normal 'test' (normal damping, Pa s/m)");
}

TEST(SceneValue, EveryRangeErrorNamesThePathTheBoundAndTheValue) {
  EXPECT_EQ(error_of([] { value_of("-1").as_positive(); }), "scene: 'x' must be > 0, got -1");
  EXPECT_EQ(error_of([] { value_of("-1").as_number_at_least(0); }), "scene: 'x' must be >= 0, got -1");
  EXPECT_EQ(error_of([] { value_of("1.5").as_number_in(0, 1); }), "scene: 'x' must be in [0, 1], got 1.5");
  EXPECT_EQ(error_of([] { value_of("-7").as_int_at_least(1); }), "scene: 'x' must be >= 1, got -7");
  EXPECT_EQ(error_of([] { value_of("0").as_number(Range::left_open(0, 1), "1"); }),
            "scene: 'x' must be in (0, 1], got 0");
  // A declared parameter from a scene: the same check, with its unit.
  const std::vector<ParameterDeclaration> declared = {{"c_nu", "Pa s/m", "damping", 0.0, Range::at_least(0)}};
  const Json object = parse_json(R"({"contact": {"c_nu": -1}})", "s")["contact"];
  EXPECT_EQ(error_of([&] {
              read_parameters(object, {"law_normal 'test'", &declared});
            }),
            "scene: 'contact.c_nu' (Pa s/m) must be >= 0, got -1");
  // The same check from C++, where a value can also be NaN or infinite.
  EXPECT_EQ(error_of([&] { check_parameter(declared[0], -1, "brick 'contact'"); }),
            "brick 'contact': c_nu must be >= 0, got -1");
  EXPECT_EQ(error_of([&] { check_parameter(declared[0], std::numeric_limits<double>::quiet_NaN(), "brick"); }),
            "brick: c_nu must be finite and >= 0, got nan");
}

}  // namespace
}  // namespace pc

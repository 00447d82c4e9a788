#include "models/scene/json.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>

#include "assembly/error.hpp"
#include "support/test_helpers.hpp"

namespace pc {

// Found by GoogleTest through argument-dependent lookup, so it must live in pc, not in the anonymous namespace.
void PrintTo(const Json& value, std::ostream* out) { *out << value.dump(0); }

namespace {

using ::testing::HasSubstr;

// A reduced copy of scenes/paper2d.json: tests do not read files outside the repository.
const char* const paper2d = R"json({
  "name": "paper2d",
  "geometry": {"x": [0.0, 0.03], "y": [0.0, 0.01]},
  "material": {
    "rho": 7800.0,
    "elasticity_B": [
      [127205000000.0, 84670200000.0, 0.0],
      [84670200000.0, 117436000000.0, 0.0],
      [0.0, 0.0, 22988500000.0]
    ],
    "piezo_E": [[0.0, 0.0, 17.0345], [-6.62281, 23.2403, 0.0]],
    "permittivity_beta": [[1.5091e-08, 0.0], [0.0, 1.2693e-08]],
    "piezo_E_rows_are_field_directions_x_y": true
  },
  "contact": {
    "law_normal": "c_nu * max(v_nu, 0)",
    "c_nu": 1000000000000.0,
    "law_tangential": "c_tau * v_tau",
    "c_tau": 0.3
  },
  "foundation": {"conductive": {"k_e": 1.0, "phi_f": -48.0}, "insulated": {}},
  "time": {"T": 0.2, "u0": [0.0, 0.0]},
  "reference_discretization": {"elements": "P1 triangles", "nx": 60, "ny": 20, "steps": 200}
})json";

Json scene() { return parse_json(paper2d, "paper2d.json"); }

using testing::error_of;

std::string parse_error(const std::string& text) {
  return error_of([&] { parse_json(text, "in.json"); });
}

TEST(Json, ReadsTheScene) {
  const Json root = scene();
  EXPECT_EQ(root.at("name").as_string(), "paper2d");
  EXPECT_EQ(root["material"]["rho"].as_number(), 7800.0);
  EXPECT_TRUE(root["material"]["piezo_E_rows_are_field_directions_x_y"].as_bool());
  EXPECT_EQ(root["contact"]["c_nu"].as_number(), 1e12);
  EXPECT_EQ(root["reference_discretization"]["nx"].as_int(), 60);
  EXPECT_EQ(root["geometry"]["x"].as_vector(), (std::vector<double>{0.0, 0.03}));
  EXPECT_EQ(root["time"]["u0"].as_vector(2), (std::vector<double>{0.0, 0.0}));

  const Eigen::MatrixXd B = root["material"]["elasticity_B"].as_matrix(3, 3);
  EXPECT_EQ(B(0, 0), 1.27205e11);
  EXPECT_EQ(B(1, 1), 1.17436e11);
  EXPECT_EQ(B(2, 2), 2.29885e10);
  const Eigen::MatrixXd E = root["material"]["piezo_E"].as_matrix();
  EXPECT_EQ(E.rows(), 2);
  EXPECT_EQ(E.cols(), 3);
  EXPECT_EQ(E(1, 0), -6.62281);
  EXPECT_EQ(root["material"]["permittivity_beta"].as_matrix()(0, 0), 1.5091e-08);

  EXPECT_TRUE(root.is_object());
  EXPECT_TRUE(root["foundation"]["insulated"].is_object());
  EXPECT_EQ(root["foundation"]["insulated"].size(), 0u);
  EXPECT_EQ(root["material"]["elasticity_B"].size(), 3u);
  EXPECT_TRUE(root.contains("time"));
  EXPECT_FALSE(root.find("loads").has_value());
  ASSERT_TRUE(root.find("time").has_value());
  EXPECT_EQ(root.find("time")->at("T").as_positive(), 0.2);
}

TEST(Json, KeepsTheOrderOfKeys) {
  const Json root = scene();
  EXPECT_EQ(root["contact"].keys(), (std::vector<std::string>{"law_normal", "c_nu", "law_tangential", "c_tau"}));
  EXPECT_EQ(root.keys().front(), "name");
  EXPECT_EQ(root.keys().back(), "reference_discretization");
}

TEST(Json, ValuesKnowTheirPath) {
  const Json root = scene();
  EXPECT_EQ(root.path(), "");
  EXPECT_EQ(root["contact"]["c_nu"].path(), "contact.c_nu");
  EXPECT_EQ(root["material"]["elasticity_B"][1][2].path(), "material.elasticity_B[1][2]");
  // A copy taken out of the tree still names where it came from.
  const Json contact = root["contact"];
  EXPECT_EQ(contact["c_tau"].path(), "contact.c_tau");
}

TEST(Json, TypeErrorsNameThePath) {
  const Json root = parse_json(R"({"contact": {"c_nu": "1e12", "flag": 1}, "list": [1, "x"]})", "s.json");
  EXPECT_EQ(error_of([&] { root["contact"]["c_nu"].as_number(); }),
            "scene: 'contact.c_nu' must be a number, got the string \"1e12\"");
  EXPECT_EQ(error_of([&] { root["contact"]["flag"].as_bool(); }),
            "scene: 'contact.flag' must be a boolean, got the number 1");
  EXPECT_EQ(error_of([&] { root["contact"].as_string(); }), "scene: 'contact' must be a string, got an object");
  EXPECT_EQ(error_of([&] { root["contact"]["c_nu"]["x"]; }),
            "scene: 'contact.c_nu' must be an object, got the string \"1e12\"");
  EXPECT_EQ(error_of([&] { root["list"].as_vector(); }), "scene: 'list[1]' must be a number, got the string \"x\"");
  EXPECT_EQ(error_of([&] { root.as_array(); }), "scene: the root must be an array, got an object");
  EXPECT_EQ(error_of([&] { root["contact"]["flag"].size(); }),
            "scene: 'contact.flag' must be an array or an object, got the number 1");
  EXPECT_EQ(error_of([&] { parse_json("[false]", "s")[0].as_number(); }),
            "scene: '[0]' must be a number, got the boolean false");
  EXPECT_EQ(error_of([&] { parse_json("null", "s")["x"]; }), "scene: the root must be an object, got null");
}

TEST(Json, MissingKeysAndIndicesNameThePath) {
  const Json root = scene();
  EXPECT_EQ(error_of([&] { root["contact"]["c_nuu"]; }), "scene: missing key 'contact.c_nuu'");
  EXPECT_EQ(error_of([&] { root["loads"]; }), "scene: missing key 'loads'");
  EXPECT_EQ(error_of([&] { root["time"]["u0"][2]; }), "scene: 'time.u0[2]' is out of range: 'time.u0' has 2 entries");
}

TEST(Json, IntegersMustBeIntegralAndInRange) {
  const Json root = parse_json(R"({"a": 2.5, "b": 3e9, "c": -7, "d": 1e2})", "s");
  EXPECT_EQ(error_of([&] { root["a"].as_int(); }), "scene: 'a' must be an integer, got 2.5");
  EXPECT_THAT(error_of([&] { root["b"].as_int(); }), HasSubstr("scene: 'b' must be an integer in ["));
  EXPECT_THAT(error_of([&] { root["b"].as_int(); }), HasSubstr("got 3000000000"));
  EXPECT_EQ(root["c"].as_int(), -7);
  EXPECT_EQ(root["d"].as_int(), 100);
  EXPECT_EQ(error_of([&] { root["c"].as_int_at_least(1); }), "scene: 'c' must be >= 1, got -7");
}

TEST(Json, RangeChecksNameTheBound) {
  const Json root = parse_json(R"({"time": {"T": -1, "theta": 1.5, "zero": 0}})", "s");
  EXPECT_EQ(error_of([&] { root["time"]["T"].as_positive(); }), "scene: 'time.T' must be > 0, got -1");
  EXPECT_EQ(error_of([&] { root["time"]["zero"].as_positive(); }), "scene: 'time.zero' must be > 0, got 0");
  EXPECT_EQ(root["time"]["zero"].as_number_at_least(0), 0.0);
  EXPECT_EQ(error_of([&] { root["time"]["T"].as_number_at_least(0); }), "scene: 'time.T' must be >= 0, got -1");
  EXPECT_EQ(error_of([&] { root["time"]["theta"].as_number_in(0, 1); }),
            "scene: 'time.theta' must be in [0, 1], got 1.5");
  EXPECT_EQ(root["time"]["theta"].as_number_in(1, 2), 1.5);
}

TEST(Json, MatrixErrorsNameTheRow) {
  const Json root = parse_json(R"({"m": {"ragged": [[1, 2, 3], [4, 5]], "text": [[1, 2], [3, "x"]],
                                        "flat": [1, 2], "empty": [], "empty_row": [[]]}})",
                               "s");
  EXPECT_EQ(error_of([&] { root["m"]["ragged"].as_matrix(); }),
            "scene: 'm.ragged' must be a matrix, but row 1 has 2 entries and row 0 has 3");
  EXPECT_EQ(error_of([&] { root["m"]["text"].as_matrix(); }),
            "scene: 'm.text[1][1]' must be a number, got the string \"x\"");
  EXPECT_EQ(error_of([&] { root["m"]["flat"].as_matrix(); }),
            "scene: 'm.flat[0]' must be an array of numbers, got the number 1");
  EXPECT_EQ(error_of([&] { root["m"]["empty"].as_matrix(); }), "scene: 'm.empty' must be a matrix, got an empty array");
  EXPECT_EQ(error_of([&] { root["m"]["empty_row"].as_matrix(); }),
            "scene: 'm.empty_row' must be a matrix, got an empty row 0");
  EXPECT_EQ(error_of([&] { scene()["material"]["piezo_E"].as_matrix(3, 3); }),
            "scene: 'material.piezo_E' must be a 3x3 matrix, got 2x3");
  EXPECT_EQ(error_of([&] { scene()["geometry"]["x"].as_vector(3); }), "scene: 'geometry.x' must have 3 entries, got 2");
}

TEST(Json, HasNoNanOrInfinity) {
  EXPECT_EQ(parse_error("nan"), "in.json:1:1: JSON has no NaN or infinity, got 'nan'");
  EXPECT_EQ(parse_error("[1, NaN]"), "in.json:1:5: JSON has no NaN or infinity, got 'NaN'");
  EXPECT_EQ(parse_error("{\"T\": -Infinity}"), "in.json:1:7: JSON has no NaN or infinity, got '-Infinity'");
  const std::string range = " is out of the range of a double (nonzero magnitudes from 4.9e-324 to 1.8e308)";
  EXPECT_EQ(parse_error("1e400"), "in.json:1:1: number 1e400" + range);
  EXPECT_EQ(parse_error("{\"c\": {\"c_nu\": -1e400}}"), "in.json:1:16: number -1e400 at 'c.c_nu'" + range);
  // nlohmann would round an underflow to zero; the parser refuses it like an overflow.
  EXPECT_EQ(parse_error("[0, 1e-400]"), "in.json: number 1e-400 at '[1]'" + range);
  EXPECT_EQ(parse_json("[5e-324, 0e-400]", "s").as_vector(), (std::vector<double>{5e-324, 0.0}));
  const double nan = std::numeric_limits<double>::quiet_NaN(), infinity = std::numeric_limits<double>::infinity();
  EXPECT_THAT(error_of([&] { Json{nan}; }), HasSubstr("no NaN or infinity"));
  EXPECT_THAT(error_of([&] { Json{-infinity}; }), HasSubstr("no NaN or infinity"));
}

TEST(Json, ParseErrorsGiveLineAndColumn) {
  // The column is that of the byte where the parser saw the error; the message is nlohmann's.
  EXPECT_EQ(parse_error("{\n  \"a\": 1,\n  \"b\" 2\n}"),
            "in.json:3:7: syntax error while parsing object separator - unexpected number literal; expected ':'");
  EXPECT_EQ(parse_error("{\"a\": [1, 2}"),
            "in.json:1:12: syntax error while parsing array - unexpected '}'; expected ']'");
  EXPECT_EQ(parse_error("{\"a\": 1 \"b\": 2}"),
            "in.json:1:11: syntax error while parsing object - unexpected string literal; expected '}'");
  EXPECT_EQ(parse_error(""),
            "in.json:1:1: syntax error while parsing value - unexpected end of input; expected '[', '{', or a literal");
  EXPECT_EQ(parse_error("[1, 2"),
            "in.json:1:6: syntax error while parsing array - unexpected end of input; expected ']'");
  EXPECT_EQ(parse_error("{\"a\": \"x"),
            "in.json:1:9: syntax error while parsing value - invalid string: missing closing quote; last read: '\"x'");
  EXPECT_EQ(parse_error("1 2"),
            "in.json:1:3: syntax error while parsing value - unexpected number literal; expected end of input");
  // Columns count characters, not bytes: "é" is two bytes of UTF-8.
  EXPECT_EQ(parse_error("[\"\xC3\xA9\", x]"),
            "in.json:1:7: syntax error while parsing value - invalid literal; last read: '\"\xC3\xA9\", x'");
}

TEST(Json, RefusesDuplicateKeys) {
  EXPECT_EQ(parse_error("{\"a\": 1, \"a\": 2}"), "in.json: duplicate key 'a'");
  EXPECT_EQ(parse_error("{\"contact\": {\"c_nu\": 1, \"c_tau\": 0, \"c_nu\": 1e12}}"),
            "in.json: duplicate key 'contact.c_nu'");
  EXPECT_EQ(parse_error("[{}, {\"x\": [{\"a\": [], \"a\": {}}]}]"), "in.json: duplicate key '[1].x[0].a'");
  // The same key in different objects is no duplicate.
  EXPECT_EQ(parse_json("{\"a\": {\"a\": 1}, \"b\": {\"a\": 2}}", "s")["b"]["a"].as_int(), 2);
}

TEST(Json, IsStrict) {
  EXPECT_EQ(parse_error("[1, 2,]"),
            "in.json:1:7: syntax error while parsing value - unexpected ']'; expected '[', '{', or a literal");
  EXPECT_EQ(parse_error("{\"a\": 1,}"),
            "in.json:1:9: syntax error while parsing object key - unexpected '}'; expected string literal");
  EXPECT_EQ(parse_error("// scene\n{}"),
            "in.json:1:1: syntax error while parsing value - invalid literal; last read: '/'");
  EXPECT_EQ(parse_error("{\"a\": 1 /* x */}"),
            "in.json:1:9: syntax error while parsing object - invalid literal; last read: '1 /'; expected '}'");
  EXPECT_EQ(parse_error("[/* x */ 1]"),
            "in.json:1:2: syntax error while parsing value - invalid literal; last read: '[/'");
  EXPECT_EQ(parse_error("012"),
            "in.json:1:3: syntax error while parsing value - unexpected number literal; expected end of input");
  EXPECT_EQ(parse_error("-01"),
            "in.json:1:3: syntax error while parsing value - unexpected number literal; expected end of input");
  EXPECT_EQ(parse_error("{a: 1}"),
            "in.json:1:2: syntax error while parsing object key - invalid literal; last read: '{a'; "
            "expected string literal");
  EXPECT_EQ(parse_error("['a']"), "in.json:1:2: syntax error while parsing value - invalid literal; last read: '[''");
  EXPECT_EQ(parse_error("TRUE"), "in.json:1:1: syntax error while parsing value - invalid literal; last read: 'T'");
  EXPECT_EQ(parse_error("truex"),
            "in.json:1:5: syntax error while parsing value - invalid literal; last read: 'truex'; "
            "expected end of input");
  for (const char* bad : {"+1", ".5", "1.", "1.e3", "1e", "1e+", "-", "0x10", "1_000"})
    EXPECT_THAT(parse_error(bad), HasSubstr("in.json:1:")) << bad;
  EXPECT_EQ(parse_error("\"a\tb\""),
            "in.json:1:3: syntax error while parsing value - invalid string: control "
            "character U+0009 (HT) must be escaped to \\u0009 or \\t; "
            "last read: '\"a<U+0009>'");
  EXPECT_EQ(parse_error("\"\\x\""),
            "in.json:1:3: syntax error while parsing value - invalid string: forbidden "
            "character after backslash; last read: '\"\\x'");
  const std::string bad_utf8 = "syntax error while parsing value - invalid string: ill-formed UTF-8 byte; last read: ";
  EXPECT_EQ(parse_error("\"\xC3\""), "in.json:1:3: " + bad_utf8 + "'\"\xC3\"'");
  EXPECT_EQ(parse_error("\"\xC0\xAF\""), "in.json:1:2: " + bad_utf8 + "'\"\xC0'");          // overlong '/'
  EXPECT_EQ(parse_error("\"\xED\xA0\x80\""), "in.json:1:3: " + bad_utf8 + "'\"\xED\xA0'");  // encoded surrogate
  EXPECT_EQ(parse_error("\f1"),
            "in.json:1:1: syntax error while parsing value - invalid literal; last read: '<U+000C>'");
  EXPECT_EQ(parse_error(std::string(300, '[') + std::string(300, ']')), "in.json: nesting deeper than 256 levels");
  EXPECT_EQ(parse_json(std::string(256, '[') + std::string(256, ']'), "s").size(), 1u);

  // What RFC 8259 does allow.
  EXPECT_EQ(parse_json(" \t\r\n[ -0.5e+2 , 0E-1 , 1E2 ]\n", "s").as_vector(), (std::vector<double>{-50, 0, 100}));
  EXPECT_EQ(parse_json("\xEF\xBB\xBF{}", "s").size(), 0u);  // a byte order mark may be ignored
  EXPECT_EQ(parse_json("\"x\"", "s").as_string(), "x");     // any value may be the root
}

TEST(Json, DecodesEscapes) {
  EXPECT_EQ(parse_json(R"("\" \\ \/ \b \f \n \r \t")", "s").as_string(), "\" \\ / \b \f \n \r \t");
  EXPECT_EQ(parse_json(R"("\u0041\u00e9\u20AC")", "s").as_string(), "A\xC3\xA9\xE2\x82\xAC");
  EXPECT_EQ(parse_json(R"("\ud83d\ude00")", "s").as_string(), "\xF0\x9F\x98\x80");  // U+1F600
  EXPECT_EQ(parse_json(R"("\u0000")", "s").as_string(), std::string(1, '\0'));
  EXPECT_EQ(parse_json("\"\xF0\x9F\x98\x80 \xC3\xA9\"", "s").as_string(), "\xF0\x9F\x98\x80 \xC3\xA9");
  const std::string bad_string = "syntax error while parsing value - invalid string: ";
  const std::string unpaired_high = bad_string + "surrogate U+D800..U+DBFF must be followed by U+DC00..U+DFFF";
  EXPECT_EQ(parse_error(R"("\ud83d")"), "in.json:1:8: " + unpaired_high + "; last read: '\"\\ud83d\"'");
  EXPECT_EQ(parse_error(R"("\ud83d\u0041")"), "in.json:1:13: " + unpaired_high + "; last read: '\"\\ud83d\\u0041'");
  EXPECT_EQ(
      parse_error(R"("\ude00")"),
      "in.json:1:7: " + bad_string + "surrogate U+DC00..U+DFFF must follow U+D800..U+DBFF; last read: '\"\\ude00'");
  EXPECT_EQ(parse_error(R"("\u12G4")"),
            "in.json:1:6: " + bad_string + "'\\u' must be followed by 4 hex digits; last read: '\"\\u12G'");
}

TEST(Json, DumpRoundTripsDoublesExactly) {
  const std::vector<double> values = {
      0.1,      1e-300, 1.7976931348623157e308, -0.0, 5e-324, 2.2250738585072014e-308, 1.0 / 3, 1e22,
      -6.62281, 0.03,   9007199254740993.0};
  const Json array = Json::array(std::vector<Json>(values.begin(), values.end()));
  const Json back = parse_json(array.dump(), "s");
  for (std::size_t i = 0; i < values.size(); ++i) {
    EXPECT_EQ(back[i].as_number(), values[i]) << array.dump(0);
    EXPECT_EQ(std::signbit(back[i].as_number()), std::signbit(values[i]));
  }
  EXPECT_EQ(Json(0.1).dump(), "0.1");
  EXPECT_EQ(Json(-0.0).dump(), "-0.0");
  EXPECT_EQ(Json(1e-300).dump(), "1e-300");
  EXPECT_EQ(Json(1.7976931348623157e308).dump(), "1.7976931348623157e+308");
  // Integers print without exponent or decimals.
  EXPECT_EQ(Json(60).dump(), "60");
  EXPECT_EQ(Json(7800.0).dump(), "7800");
  EXPECT_EQ(Json(1e12).dump(), "1000000000000");
  EXPECT_EQ(Json(127205000000.0).dump(), "127205000000");
  EXPECT_EQ(Json(-48.0).dump(), "-48");
  // Also when read from a file, where nlohmann holds 7800.0 as a double and 60 as an integer.
  EXPECT_EQ(parse_json("[7800.0, 1e12, 60, -0.5e1, 1e22, 9007199254740993]", "s").dump(0),
            "[7800,1000000000000,60,-5,1e+22,9007199254740992]");
}

TEST(Json, DumpLaysOutAndEscapes) {
  const Json root =
      parse_json(R"({"b": [1, {"c": null}], "a": "q\"\\\n\u0001\u00e9", "e": {}, "f": [], "t": true})", "s");
  EXPECT_EQ(root.dump(0), R"({"b":[1,{"c":null}],"a":"q\"\\\n\u0001)"
                          "\xC3\xA9"
                          R"(","e":{},"f":[],"t":true})");
  EXPECT_EQ(root.dump(),
            "{\n"
            "  \"b\": [\n"
            "    1,\n"
            "    {\n"
            "      \"c\": null\n"
            "    }\n"
            "  ],\n"
            "  \"a\": \"q\\\"\\\\\\n\\u0001\xC3\xA9\",\n"
            "  \"e\": {},\n"
            "  \"f\": [],\n"
            "  \"t\": true\n"
            "}");
}

TEST(Json, DumpIsStable) {
  const Json root = scene();
  const std::string once = root.dump();
  const Json again = parse_json(once, "s");
  EXPECT_EQ(again.dump(), once);
  EXPECT_EQ(again, root);
  EXPECT_EQ(again.keys(), root.keys());
  EXPECT_EQ(parse_json(root.dump(0), "s").dump(), once);
}

TEST(Json, Equality) {
  EXPECT_EQ(parse_json(R"({"a": 1, "b": [true, null]})", "s"), parse_json(R"({"b": [true, null], "a": 1.0})", "s"));
  EXPECT_NE(parse_json(R"({"a": 1})", "s"), parse_json(R"({"a": 1, "b": 2})", "s"));
  EXPECT_NE(parse_json("[1, 2]", "s"), parse_json("[2, 1]", "s"));
  EXPECT_NE(Json(1), Json("1"));
  EXPECT_NE(Json(), Json(false));
}

TEST(Json, BuildsValues) {
  Json root = Json::object({{"name", "x"}, {"n", 3}, {"list", Json::array({1, 2.5})}});
  root.set("flag", true);
  root.set("n", 4);  // replaces in place
  EXPECT_EQ(root.keys(), (std::vector<std::string>{"name", "n", "list", "flag"}));
  EXPECT_EQ(root["n"].as_int(), 4);
  EXPECT_EQ(root["list"][1].path(), "list[1]");
  EXPECT_EQ(root.dump(0), R"({"name":"x","n":4,"list":[1,2.5],"flag":true})");

  Json outer = Json::object();
  outer.set("inner", root);
  EXPECT_EQ(outer["inner"]["list"][1].path(), "inner.list[1]");
  Json list = Json::array();
  list.push_back(root);
  EXPECT_EQ(list[0]["name"].path(), "[0].name");

  EXPECT_EQ(error_of([] { Json::object({{"a", 1}, {"a", 2}}); }), "scene: duplicate key 'a'");
  EXPECT_EQ(error_of([] { Json{std::string("\xFF")}; }), "scene: a string is not valid UTF-8");
  EXPECT_EQ(error_of([] { Json(1).push_back(2); }), "scene: the root must be an array, got the number 1");
}

TEST(Json, SetPathReplacesNestedValues) {
  Json root = scene();
  root.set_path("contact.c_nu", Json(1e14));
  EXPECT_EQ(root["contact"]["c_nu"].as_number(), 1e14);
  EXPECT_EQ(root["contact"].keys(), (std::vector<std::string>{"law_normal", "c_nu", "law_tangential", "c_tau"}));

  root.set_path("material.elasticity_B[1][2]", Json(5.0));
  EXPECT_EQ(root["material"]["elasticity_B"].as_matrix()(1, 2), 5.0);
  EXPECT_EQ(root["material"]["elasticity_B"][1][2].path(), "material.elasticity_B[1][2]");

  root.set_path("time.u0", parse_json_value_from_cli("[1, 2]"));
  EXPECT_EQ(root["time"]["u0"].as_vector(), (std::vector<double>{1, 2}));
  EXPECT_EQ(root["time"]["u0"][1].path(), "time.u0[1]");

  root.set_path("foundation.conductive", parse_json_value_from_cli(R"({"k_e": 2})"));
  EXPECT_EQ(root["foundation"]["conductive"]["k_e"].path(), "foundation.conductive.k_e");

  root.set_path("name", Json("other"));
  EXPECT_EQ(root["name"].as_string(), "other");

  root.set_path("contact.new_key", Json(1), Json::NewKeys::allow);
  EXPECT_EQ(root["contact"].keys().back(), "new_key");
  EXPECT_EQ(root["contact"]["new_key"].path(), "contact.new_key");

  Json list = parse_json(R"([{"a": [0, 1]}])", "s");
  list.set_path("[0].a[1]", Json(7));
  EXPECT_EQ(list.dump(0), R"([{"a":[0,7]}])");
}

TEST(Json, SetPathErrors) {
  Json root = scene();
  const auto set = [&](const std::string& path, Json::NewKeys new_keys = Json::NewKeys::forbid) {
    return error_of([&] { root.set_path(path, Json(1), new_keys); });
  };
  EXPECT_EQ(set("contact.c_nuu"),
            "scene: unknown key 'contact.c_nuu' (known: c_nu, c_tau, law_normal, law_tangential)");
  EXPECT_EQ(set("foundation.insulated.x"), "scene: unknown key 'foundation.insulated.x' (known: none)");
  EXPECT_EQ(set("contatc.c_nu"),
            "scene: unknown key 'contatc' (known: contact, foundation, geometry, material, name, "
            "reference_discretization, time)");
  // Only the last step may be new.
  EXPECT_EQ(set("contatc.c_nu", Json::NewKeys::allow),
            "scene: unknown key 'contatc' (known: contact, foundation, geometry, material, name, "
            "reference_discretization, time)");
  EXPECT_EQ(set("contact.c_nu.x"),
            "scene: cannot set 'contact.c_nu.x': 'contact.c_nu' is the number 1000000000000, not an object");
  EXPECT_EQ(set("contact[0]"), "scene: cannot set 'contact[0]': 'contact' is an object, not an array");
  EXPECT_EQ(set("time.u0.x"), "scene: cannot set 'time.u0.x': 'time.u0' is an array, not an object");
  EXPECT_EQ(set("time.u0[2]"), "scene: cannot set 'time.u0[2]': 'time.u0' has 2 entries");
  EXPECT_EQ(set("material.elasticity_B[3][0]"),
            "scene: cannot set 'material.elasticity_B[3][0]': 'material.elasticity_B' has 3 entries");
  EXPECT_EQ(set(""), "scene: malformed path '': empty path");
  EXPECT_EQ(set("a..b"), "scene: malformed path 'a..b': empty key");
  EXPECT_EQ(set(".a"), "scene: malformed path '.a': empty key");
  EXPECT_EQ(set("a."), "scene: malformed path 'a.': empty key");
  EXPECT_EQ(set("a[1"), "scene: malformed path 'a[1': '[' without ']'");
  EXPECT_EQ(set("a]"), "scene: malformed path 'a]': ']' without '['");
  EXPECT_EQ(set("a[-1]"), "scene: malformed path 'a[-1]': an index must be a non-negative integer");
  EXPECT_EQ(set("a[x]"), "scene: malformed path 'a[x]': an index must be a non-negative integer");
  EXPECT_EQ(set("a[]"), "scene: malformed path 'a[]': an index must be a non-negative integer");
  EXPECT_EQ(set("a[1]b"), "scene: malformed path 'a[1]b': expected '.' or '[' after ']'");
  // A failed set leaves the scene as it was.
  EXPECT_EQ(root, scene());
}

TEST(Json, ParsesCommandLineValues) {
  EXPECT_EQ(parse_json_value_from_cli("1e14"), Json(1e14));
  EXPECT_EQ(parse_json_value_from_cli("-3"), Json(-3));
  EXPECT_EQ(parse_json_value_from_cli("true"), Json(true));
  EXPECT_EQ(parse_json_value_from_cli("false"), Json(false));
  EXPECT_EQ(parse_json_value_from_cli("null"), Json());
  EXPECT_EQ(parse_json_value_from_cli("P2"), Json("P2"));
  EXPECT_EQ(parse_json_value_from_cli("P1 triangles"), Json("P1 triangles"));
  EXPECT_EQ(parse_json_value_from_cli("1.2.3"), Json("1.2.3"));
  EXPECT_EQ(parse_json_value_from_cli(""), Json(""));
  EXPECT_EQ(parse_json_value_from_cli("\"true\""), Json("true"));
  EXPECT_EQ(parse_json_value_from_cli("[1,2]"), Json::array({1, 2}));
  EXPECT_EQ(parse_json_value_from_cli(R"({"k_e": 1})"), Json::object({{"k_e", 1}}));
  // Text that starts like JSON must be JSON: a typo is reported rather than kept as a string.
  EXPECT_EQ(error_of([] { parse_json_value_from_cli("[1, 2"); }),
            "command-line value:1:6: syntax error while parsing array - unexpected end of input; expected ']'");
  EXPECT_THAT(error_of([] { parse_json_value_from_cli("\"P2"); }), HasSubstr("missing closing quote"));
  // Text that reads as a number must be a number a double holds: 1e400 is no string "1e400".
  const std::string range = " is out of the range of a double (nonzero magnitudes from 4.9e-324 to 1.8e308)";
  for (const std::string number : {"1e400", "1e-400", "-1e400"}) {
    const std::string at = number == "1e-400" ? "--set contact.c_nu: " : "--set contact.c_nu:1:1: ";
    EXPECT_EQ(error_of([&] { parse_json_value_from_cli(number, "--set contact.c_nu"); }),
              at + "number " + number + range);
  }
  EXPECT_EQ(error_of([] { parse_json_value_from_cli("nan"); }),
            "command-line value:1:1: JSON has no NaN or infinity, got 'nan'");
  EXPECT_EQ(error_of([] { parse_json_value_from_cli("-inf"); }),
            "command-line value:1:1: JSON has no NaN or infinity, got '-inf'");
  EXPECT_THAT(error_of([] { parse_json_value_from_cli(".5"); }), HasSubstr("command-line value:1:1: "));
  EXPECT_EQ(parse_json_value_from_cli("5e-324"), Json(5e-324));
}

TEST(Json, UnknownKeys) {
  const Json root = scene();
  EXPECT_EQ(unknown_keys(root["contact"], {"law_normal", "c_nu", "law_tangential", "c_tau"}),
            std::vector<std::string>{});
  EXPECT_EQ(unknown_keys(root["contact"], {"c_nu", "c_tau"}),
            (std::vector<std::string>{"contact.law_normal", "contact.law_tangential"}));
  EXPECT_NO_THROW(require_known_keys(root["time"], {"T", "u0", "v0"}));
  EXPECT_EQ(error_of([&] { require_known_keys(root["time"], {"T"}); }), "scene: unknown key 'time.u0' (known: T)");
  EXPECT_EQ(error_of([&] {
              require_known_keys(root["contact"], {"c_tau", "c_nu"});
            }),
            "scene: unknown keys 'contact.law_normal', 'contact.law_tangential' (known: c_nu, c_tau)");
  EXPECT_EQ(error_of([&] { unknown_keys(root["name"], {}); }),
            "scene: 'name' must be an object, got the string \"paper2d\"");

  // The allowed keys may be computed at run time.
  const std::vector<std::string> allowed = {"c_nu", "c_tau"};
  EXPECT_EQ(unknown_keys(root["contact"], allowed),
            (std::vector<std::string>{"contact.law_normal", "contact.law_tangential"}));
  EXPECT_EQ(error_of([&] { require_known_keys(root["contact"], allowed); }),
            "scene: unknown keys 'contact.law_normal', 'contact.law_tangential' (known: c_nu, c_tau)");
  EXPECT_NO_THROW(require_known_keys(root["time"], std::vector<std::string>{"u0", "T"}));
}

TEST(Json, ReadsFiles) {
  const std::string path = (std::filesystem::temp_directory_path() / "piezocontact_json_test.json").string();
  {
    std::ofstream out(path, std::ios::binary);
    out << "{\n  \"a\": [1,\n 2,, 3]\n}";
  }
  EXPECT_EQ(error_of([&] { read_json_file(path); }),
            path + ":3:4: syntax error while parsing value - unexpected ','; expected '[', '{', or a literal");
  {
    std::ofstream out(path, std::ios::binary);
    out << paper2d;
  }
  EXPECT_EQ(read_json_file(path), scene());
  std::filesystem::remove(path);
  EXPECT_EQ(error_of([&] { read_json_file(path); }), "cannot open scene '" + path + "'");
  const std::string directory = std::filesystem::temp_directory_path().string();
  EXPECT_EQ(error_of([&] { read_json_file(directory); }), "cannot open scene '" + directory + "'");
}

}  // namespace
}  // namespace pc

#pragma once
// A strict JSON value for scene files (RFC 8259, no extensions), read and held by nlohmann::ordered_json.
// Every value remembers its path from the document root ("contact.c_nu", "material.elasticity_B[1][2]"),
// so that a typed accessor that finds the wrong type, a missing key or an out-of-range number throws a
// pc::Error that names the field:
//   scene: 'contact.c_nu' must be a number, got the string "1e12"
// Objects keep the order of their keys, so that a scene read and written back diffs only where it changed.
// Numbers are finite doubles: JSON has no NaN or infinity, and a Json never holds one.
// Children are returned by value (a copy of the subtree with its path): scene documents are small.
#include <Eigen/Core>
#include <concepts>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "assembly/parameters.hpp"

namespace pc {

class Json {
 public:
  // Whether set_path may add a key that the object does not have yet.
  enum class NewKeys { forbid, allow };
  using Member = std::pair<std::string, Json>;

  Json();
  Json(std::nullptr_t) : Json() {}
  Json(bool value);
  // Throws when the value is NaN or infinite.
  Json(double value);
  template <std::integral Integer>
  requires(!std::same_as<Integer, bool>) Json(Integer value) : Json(static_cast<double>(value)) {}
  // Throws when the text is not valid UTF-8, which a JSON document could not hold.
  Json(std::string value);
  // Without it a string literal would convert to bool.
  Json(const char* value) : Json(std::string(value)) {}

  Json(const Json& other);
  // A moved-from Json may only be assigned to or destroyed.
  Json(Json&& other) noexcept;
  Json& operator=(const Json& other);
  Json& operator=(Json&& other) noexcept;
  ~Json();

  static Json array(std::vector<Json> items = {});
  // Keys in the given order; throws on a duplicate key.
  static Json object(std::vector<Member> members = {});

  bool is_null() const;
  bool is_bool() const;
  bool is_number() const;
  bool is_string() const;
  bool is_array() const;
  bool is_object() const;

  // Dotted path from the document root; empty for the root itself.
  const std::string& path() const { return path_; }

  // Typed accessors: each throws a pc::Error naming the path, the expected and the actual type, and the
  // value when it is a scalar.
  bool as_bool() const;
  double as_number() const;
  // An integral number within the range of int.
  int as_int() const;
  std::string as_string() const;
  std::vector<Json> as_array() const;
  std::vector<Member> members() const;

  // A number in the range, the one range check of a scene value: the error names the path, the unit
  // when one is given ("1" is none), the bound and the value, e.g. "scene: 'contact.c_nu' (Pa s/m) must
  // be >= 0, got -1". The others below are its common ranges.
  double as_number(const Range& range, std::string_view unit = {}) const;
  double as_positive() const;
  double as_number_at_least(double min) const;
  double as_number_in(double min, double max) const;
  int as_int_at_least(int min) const;

  // An array of numbers.
  std::vector<double> as_vector() const;
  std::vector<double> as_vector(std::size_t expected_size) const;
  // A non-empty array of equally long, non-empty arrays of numbers, one per row.
  Eigen::MatrixXd as_matrix() const;
  Eigen::MatrixXd as_matrix(Eigen::Index expected_rows, Eigen::Index expected_cols) const;

  // Object access. at() throws "scene: missing key 'contact.c_nu'"; find() returns nothing for a missing
  // key. Both throw when this is not an object.
  Json at(std::string_view key) const;
  std::optional<Json> find(std::string_view key) const;
  bool contains(std::string_view key) const;
  Json operator[](std::string_view key) const { return at(key); }
  // Keys in document order.
  std::vector<std::string> keys() const;

  // Array access; throws when this is not an array or the index is out of range.
  Json at(std::size_t index) const;
  Json operator[](std::size_t index) const { return at(index); }

  // Number of entries of an array or members of an object.
  std::size_t size() const;

  // Replaces the value of an existing key in place, or appends a new key.
  void set(const std::string& key, Json value);
  void push_back(Json value);
  // Replaces the value at "a.b.c" or "a.b[2]" (command-line --set key=value). Every step but the last
  // must exist; the last must exist too unless new_keys is allow and it names a key of an object.
  void set_path(const std::string& dotted_path, Json value, NewKeys new_keys = NewKeys::forbid);

  // Python-style layout with `indent` spaces per level, or a single line when indent is 0. Numbers print
  // in the shortest form that reads back as the same double; integers below 2^53 print without exponent
  // or decimals.
  std::string dump(int indent = 2) const;

  // Structural equality; paths and the order of object keys do not matter.
  friend bool operator==(const Json& a, const Json& b);

  friend Json parse_json(const std::string& text, const std::string& source_name);

 private:
  // The nlohmann value, defined in json.cpp so that this header does not pull nlohmann into every user.
  struct Value;
  Json(Value value, std::string path);

  [[noreturn]] void fail_type(const char* expected) const;
  void expect_object() const;
  void expect_array() const;

  std::unique_ptr<Value> value_;
  std::string path_;
};

// Strict RFC 8259 parser. Syntax errors read "source_name:line:column: " and nlohmann's description. A
// number whose magnitude is beyond a double, too large or too small (1e400, 1e-400), is an error rather
// than an infinity or a silent zero; so is a duplicate key ("source_name: duplicate key 'contact.c_nu'").
Json parse_json(const std::string& text, const std::string& source_name);
// Throws "cannot open scene 'path'" when the file cannot be read.
Json read_json_file(const std::string& path);

// A command-line value: JSON when it parses (1e14, true, null, [1,2], "P2"), otherwise the text itself as
// a string (P2). Text that starts with '[', '{' or '"', or reads as a number (1e400, nan), must be valid
// JSON: a typo or an unrepresentable number is reported, not silently taken as a string. Errors start
// with `source_name`.
Json parse_json_value_from_cli(const std::string& text, const std::string& source_name = "command-line value");

// Full paths of the keys of `object` that are not in `allowed`, in document order.
std::vector<std::string> unknown_keys(const Json& object, const std::vector<std::string>& allowed);
std::vector<std::string> unknown_keys(const Json& object, std::initializer_list<std::string_view> allowed);
// Throws "scene: unknown key 'contact.c_nuu' (known: c_nu, c_tau)" when unknown_keys is not empty.
void require_known_keys(const Json& object, const std::vector<std::string>& allowed);
void require_known_keys(const Json& object, std::initializer_list<std::string_view> allowed);
void require_known_keys(const Json& object, const std::vector<std::string>& allowed);

}  // namespace pc

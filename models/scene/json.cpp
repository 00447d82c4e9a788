#include "models/scene/json.hpp"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

#include "assembly/error.hpp"
#include "assembly/suggestions.hpp"

namespace pc {

struct Json::Value {
  nlohmann::ordered_json json;
};

namespace {

using nlohmann::ordered_json;

// "'contact.c_nu'", or "the root" for the document itself.
std::string where(const std::string& path) { return path.empty() ? std::string("the root") : "'" + path + "'"; }

std::string child_path(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

std::string item_path(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

// Shortest text that reads back as the same double; integers below 2^53 (all exactly representable)
// without exponent or decimals, as a reader of a scene expects "60" and "1000000000000".
std::string format_number(double value) {
  // nlohmann reads "-0" as the integer 0, which has no sign.
  if (value == 0 && std::signbit(value)) return "-0.0";
  char buffer[64];
  const bool integral = std::trunc(value) == value && std::fabs(value) < 9007199254740992.0;
  const auto result = integral ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed)
                               : std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

// The type and, for a scalar, the value: "the string \"1e12\"", "the number -1", "an object".
std::string describe(const ordered_json& value) {
  if (value.is_null()) return "null";
  if (value.is_boolean()) return std::string("the boolean ") + (value.get<bool>() ? "true" : "false");
  if (value.is_number()) return "the number " + format_number(value.get<double>());
  if (value.is_string()) return "the string " + value.dump();
  return value.is_array() ? "an array" : "an object";
}

std::vector<std::string> keys_of(const ordered_json& object) {
  std::vector<std::string> keys;
  for (const auto& member : object.items()) keys.push_back(member.key());
  return keys;
}

std::string join_sorted(std::vector<std::string> names) {
  if (names.empty()) return "none";
  std::sort(names.begin(), names.end());
  std::string joined;
  for (const std::string& name : names) joined += (joined.empty() ? "" : ", ") + name;
  return joined;
}

std::string out_of_range(const std::string& number, const std::string& path) {
  return "number " + number + (path.empty() ? "" : " at '" + path + "'") +
         " is out of the range of a double (nonzero magnitudes from 4.9e-324 to 1.8e308)";
}

// nlohmann prints the double 7800 as 7800.0 and 1e12 as 1000000000000.0; a scene reads better with the
// numbers of format_number. Everything else, strings and their escapes included, nlohmann writes.
void write(std::string& out, const ordered_json& value, int indent, int depth) {
  const auto newline = [&](int level) {
    if (indent <= 0) return;
    out += '\n';
    out.append(static_cast<std::size_t>(indent) * static_cast<std::size_t>(level), ' ');
  };
  if (value.is_number()) {
    out += format_number(value.get<double>());
    return;
  }
  if (!value.is_structured() || value.empty()) {
    out += value.dump();
    return;
  }
  const bool is_object = value.is_object();
  out += is_object ? '{' : '[';
  bool first = true;
  for (const auto& member : value.items()) {
    if (!first) out += ',';
    first = false;
    newline(depth + 1);
    if (is_object) out += ordered_json(member.key()).dump() + (indent > 0 ? ": " : ":");
    write(out, member.value(), indent, depth + 1);
  }
  newline(depth);
  out += is_object ? '}' : ']';
}

// One step of a --set path: a key of an object or an index into an array.
struct PathStep {
  bool is_index = false;
  std::string key;
  std::size_t index = 0;
};

std::vector<PathStep> split_path(const std::string& dotted_path) {
  const auto malformed = [&](const char* why) { fail("scene: malformed path '", dotted_path, "': ", why); };
  std::vector<PathStep> steps;
  std::size_t pos = 0;
  while (pos < dotted_path.size()) {
    if (dotted_path[pos] == '[') {
      const std::size_t close = dotted_path.find(']', pos);
      if (close == std::string::npos) malformed("'[' without ']'");
      const char* first = dotted_path.data() + pos + 1;
      const char* last = dotted_path.data() + close;
      PathStep step;
      step.is_index = true;
      const auto [end, error] = std::from_chars(first, last, step.index);
      if (first == last || error != std::errc() || end != last || *first == '+' || *first == '-')
        malformed("an index must be a non-negative integer");
      steps.push_back(step);
      pos = close + 1;
      if (pos < dotted_path.size() && dotted_path[pos] != '[' && dotted_path[pos] != '.')
        malformed("expected '.' or '[' after ']'");
    } else {
      if (dotted_path[pos] == '.') {
        if (steps.empty()) malformed("empty key");
        ++pos;
      }
      const std::size_t end = std::min(dotted_path.find_first_of(".[]", pos), dotted_path.size());
      if (end == pos) malformed("empty key");
      if (end < dotted_path.size() && dotted_path[end] == ']') malformed("']' without '['");
      PathStep step;
      step.key = dotted_path.substr(pos, end - pos);
      steps.push_back(step);
      pos = end;
    }
  }
  if (steps.empty()) malformed("empty path");
  return steps;
}

// Builds the document from nlohmann's SAX events, to refuse what its own builder accepts: a duplicate key
// (it keeps the last value), a number that underflows to zero (1e-400) and nesting deep enough to
// overflow the stack of the recursive code that walks a document. Turns nlohmann's errors into
// "source:line:column: ..." messages.
class StrictBuilder final : public nlohmann::json_sax<ordered_json> {
 public:
  StrictBuilder(const std::string& text, const std::string& source_name) : text_(text), source_name_(source_name) {}

  ordered_json& root() { return root_; }

  bool null() override { return add(nullptr); }
  bool boolean(bool value) override { return add(value); }
  bool number_integer(number_integer_t value) override { return add(value); }
  bool number_unsigned(number_unsigned_t value) override { return add(value); }
  bool number_float(number_float_t value, const string_t& text) override {
    // nlohmann refuses an overflow (1e400) itself, but rounds an underflow to zero.
    double exact = 0.0;
    if (std::from_chars(text.data(), text.data() + text.size(), exact).ec != std::errc())
      fail(source_name_, ": ", out_of_range(text, next_path()));
    return add(value);
  }
  bool string(string_t& value) override { return add(std::move(value)); }
  // Never called: JSON text has no binary values.
  bool binary(binary_t&) override { return false; }

  bool start_object(std::size_t) override { return open(ordered_json::object()); }
  bool key(string_t& key) override {
    const Container& object = open_.back();
    if (object.value->contains(key)) fail(source_name_, ": duplicate key '", child_path(object.path, key), "'");
    key_ = key;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(ordered_json::array()); }
  bool end_array() override { return close(); }

  // `bytes_read` counts the bytes read up to and including the one that failed.
  bool parse_error(std::size_t bytes_read, const std::string& last_token,
                   const ordered_json::exception& error) override {
    const std::size_t failed = bytes_read > 0 ? bytes_read - 1 : 0;
    // nlohmann's out_of_range 406 is a number beyond a double, and its last token is that number.
    if (error.id == 406)
      fail_at(bytes_read - std::min(bytes_read, last_token.size()), out_of_range(last_token, next_path()));
    // nlohmann calls them invalid literals; whoever wrote one should hear that JSON has no such numbers.
    const std::size_t start = word_start(failed);
    const std::string word = text_.substr(start, word_end(failed) - start);
    if (is_nan_or_infinity(word)) {
      if (start > 0 && text_[start - 1] == '-') fail_at(start - 1, "JSON has no NaN or infinity, got '-" + word + "'");
      fail_at(start, "JSON has no NaN or infinity, got '" + word + "'");
    }
    // "[json.exception.parse_error.101] parse error at line 1, column 3: syntax error ..." without the
    // position, which nlohmann counts in bytes from 0 rather than in characters from 1.
    const std::string what = error.what();
    const std::size_t colon = what.find(": ");
    fail_at(failed, colon == std::string::npos ? what : what.substr(colon + 2));
  }

 private:
  struct Container {
    ordered_json* value;
    std::string path;
  };

  // Deep enough for any scene, shallow enough that hostile input cannot overflow the stack.
  static constexpr std::size_t max_depth = 256;

  // Path of the value that comes next.
  std::string next_path() const {
    if (open_.empty()) return "";
    const Container& parent = open_.back();
    return parent.value->is_array() ? item_path(parent.path, parent.value->size()) : child_path(parent.path, key_);
  }

  ordered_json* place(ordered_json value) {
    if (open_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    ordered_json& parent = *open_.back().value;
    if (parent.is_object()) return &(parent[key_] = std::move(value));
    parent.push_back(std::move(value));
    return &parent.back();
  }

  bool add(ordered_json value) {
    place(std::move(value));
    return true;
  }

  bool open(ordered_json container) {
    if (open_.size() == max_depth) fail(source_name_, ": nesting deeper than ", max_depth, " levels");
    std::string path = next_path();
    open_.push_back({place(std::move(container)), std::move(path)});
    return true;
  }

  bool close() {
    open_.pop_back();
    return true;
  }

  bool is_letter(std::size_t i) const {
    const char c = i < text_.size() ? text_[i] : '\0';
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
  }
  std::size_t word_start(std::size_t i) const {
    while (i > 0 && is_letter(i - 1)) --i;
    return i;
  }
  std::size_t word_end(std::size_t i) const {
    while (is_letter(i)) ++i;
    return i;
  }
  static bool is_nan_or_infinity(std::string word) {
    std::transform(word.begin(), word.end(), word.begin(), [](char c) { return static_cast<char>(c | 0x20); });
    return word == "nan" || word == "inf" || word == "infinity";
  }

  [[noreturn]] void fail_at(std::size_t pos, const std::string& what) const {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < pos && i < text_.size(); ++i) {
      if (text_[i] == '\n') {
        ++line;
        column = 1;
      } else if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) {
        ++column;  // columns count characters, not the continuation bytes of UTF-8
      }
    }
    fail(source_name_, ":", line, ":", column, ": ", what);
  }

  const std::string& text_;
  const std::string& source_name_;
  ordered_json root_;
  std::vector<Container> open_;  // the arrays and objects being read, innermost last
  std::string key_;              // the key of the next value of the innermost object
};

// 1e400, 1e-400, nan and inf read as numbers: whoever wrote one meant a number, not a string.
bool reads_as_number(const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error != std::errc::invalid_argument && end == text.data() + text.size();
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// Construction

Json::Json() : value_(std::make_unique<Value>()) {}

Json::Json(bool value) : Json() { value_->json = value; }

Json::Json(double value) : Json() {
  require(std::isfinite(value), "scene: JSON has no NaN or infinity, cannot store ", value);
  value_->json = value;
}

Json::Json(std::string value) : Json() {
  value_->json = std::move(value);
  // nlohmann checks UTF-8 when it writes a string, not when it stores one.
  try {
    static_cast<void>(value_->json.dump());
  } catch (const ordered_json::type_error&) {
    fail("scene: a string is not valid UTF-8");
  }
}

Json::Json(Value value, std::string path) : value_(std::make_unique<Value>(std::move(value))), path_(std::move(path)) {}

Json::Json(const Json& other) : value_(std::make_unique<Value>(*other.value_)), path_(other.path_) {}
Json::Json(Json&& other) noexcept = default;
Json& Json::operator=(const Json& other) {
  value_ = std::make_unique<Value>(*other.value_);
  path_ = other.path_;
  return *this;
}
Json& Json::operator=(Json&& other) noexcept = default;
Json::~Json() = default;

Json Json::array(std::vector<Json> items) {
  Json result(Value{ordered_json::array()}, "");
  for (Json& item : items) result.value_->json.push_back(std::move(item.value_->json));
  return result;
}

Json Json::object(std::vector<Member> members) {
  Json result(Value{ordered_json::object()}, "");
  for (auto& [key, value] : members) {
    require(!result.contains(key), "scene: duplicate key '", key, "'");
    result.set(key, std::move(value));
  }
  return result;
}

// ---------------------------------------------------------------------------------------------------------
// Typed access

bool Json::is_null() const { return value_->json.is_null(); }
bool Json::is_bool() const { return value_->json.is_boolean(); }
bool Json::is_number() const { return value_->json.is_number(); }
bool Json::is_string() const { return value_->json.is_string(); }
bool Json::is_array() const { return value_->json.is_array(); }
bool Json::is_object() const { return value_->json.is_object(); }

void Json::fail_type(const char* expected) const {
  fail("scene: ", where(path_), " must be ", expected, ", got ", describe(value_->json));
}

void Json::expect_object() const {
  if (!is_object()) fail_type("an object");
}

void Json::expect_array() const {
  if (!is_array()) fail_type("an array");
}

bool Json::as_bool() const {
  if (!is_bool()) fail_type("a boolean");
  return value_->json.get<bool>();
}

double Json::as_number() const {
  if (!is_number()) fail_type("a number");
  return value_->json.get<double>();
}

int Json::as_int() const {
  const double number = as_number();
  require(std::trunc(number) == number, "scene: ", where(path_), " must be an integer, got ", format_number(number));
  require(number >= INT_MIN && number <= INT_MAX, "scene: ", where(path_), " must be an integer in [", INT_MIN, ", ",
          INT_MAX, "], got ", format_number(number));
  return static_cast<int>(number);
}

std::string Json::as_string() const {
  if (!is_string()) fail_type("a string");
  return value_->json.get<std::string>();
}

std::vector<Json> Json::as_array() const {
  expect_array();
  std::vector<Json> items;
  for (std::size_t i = 0; i < value_->json.size(); ++i)
    items.push_back(Json(Value{value_->json[i]}, item_path(path_, i)));
  return items;
}

std::vector<Json::Member> Json::members() const {
  expect_object();
  std::vector<Member> members;
  for (const auto& member : value_->json.items())
    members.emplace_back(member.key(), Json(Value{member.value()}, child_path(path_, member.key())));
  return members;
}

double Json::as_number(const Range& range, std::string_view unit) const {
  const double value = as_number();
  const std::string unit_note = unit.empty() || unit == "1" ? "" : " (" + std::string(unit) + ")";
  require_in_range(range, value, "scene: " + where(path_) + unit_note);
  return value;
}

double Json::as_positive() const { return as_number(Range::positive()); }

double Json::as_number_at_least(double min) const { return as_number(Range::at_least(min)); }

double Json::as_number_in(double min, double max) const { return as_number(Range::closed(min, max)); }

int Json::as_int_at_least(int min) const {
  const int value = as_int();
  as_number(Range::at_least(min));
  return value;
}

std::vector<double> Json::as_vector() const {
  if (!is_array()) fail_type("an array of numbers");
  std::vector<double> values;
  for (const Json& item : as_array()) values.push_back(item.as_number());
  return values;
}

std::vector<double> Json::as_vector(std::size_t expected_size) const {
  if (!is_array()) fail_type("an array of numbers");
  require(size() == expected_size, "scene: ", where(path_), " must have ", expected_size, " entries, got ", size());
  return as_vector();
}

Eigen::MatrixXd Json::as_matrix() const {
  if (!is_array()) fail_type("a matrix (an array of rows)");
  const std::vector<Json> rows = as_array();
  require(!rows.empty(), "scene: ", where(path_), " must be a matrix, got an empty array");
  const std::size_t cols = rows[0].as_vector().size();
  require(cols > 0, "scene: ", where(path_), " must be a matrix, got an empty row 0");
  Eigen::MatrixXd matrix(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const std::vector<double> row = rows[r].as_vector();
    require(row.size() == cols, "scene: ", where(path_), " must be a matrix, but row ", r, " has ", row.size(),
            " entries and row 0 has ", cols);
    for (std::size_t c = 0; c < cols; ++c) matrix(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = row[c];
  }
  return matrix;
}

Eigen::MatrixXd Json::as_matrix(Eigen::Index expected_rows, Eigen::Index expected_cols) const {
  Eigen::MatrixXd matrix = as_matrix();
  require(matrix.rows() == expected_rows && matrix.cols() == expected_cols, "scene: ", where(path_), " must be a ",
          expected_rows, "x", expected_cols, " matrix, got ", matrix.rows(), "x", matrix.cols());
  return matrix;
}

std::optional<Json> Json::find(std::string_view key) const {
  expect_object();
  const auto member = value_->json.find(std::string(key));
  if (member == value_->json.end()) return std::nullopt;
  return Json(Value{*member}, child_path(path_, key));
}

bool Json::contains(std::string_view key) const {
  expect_object();
  return value_->json.contains(std::string(key));
}

Json Json::at(std::string_view key) const {
  std::optional<Json> value = find(key);
  if (!value) fail("scene: missing key '", child_path(path_, key), "'");
  return std::move(*value);
}

std::vector<std::string> Json::keys() const {
  expect_object();
  return keys_of(value_->json);
}

Json Json::at(std::size_t index) const {
  expect_array();
  require(index < size(), "scene: ", where(item_path(path_, index)), " is out of range: ", where(path_), " has ",
          size(), " entries");
  return Json(Value{value_->json[index]}, item_path(path_, index));
}

std::size_t Json::size() const {
  if (!is_array() && !is_object()) fail_type("an array or an object");
  return value_->json.size();
}

// ---------------------------------------------------------------------------------------------------------
// Changes

void Json::set(const std::string& key, Json value) {
  expect_object();
  value_->json[key] = std::move(value.value_->json);
}

void Json::push_back(Json value) {
  expect_array();
  value_->json.push_back(std::move(value.value_->json));
}

void Json::set_path(const std::string& dotted_path, Json value, NewKeys new_keys) {
  const std::vector<PathStep> steps = split_path(dotted_path);
  ordered_json* node = &value_->json;
  std::string node_path = path_;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const PathStep& step = steps[i];
    if (step.is_index) {
      require(node->is_array(), "scene: cannot set '", dotted_path, "': ", where(node_path), " is ", describe(*node),
              ", not an array");
      require(step.index < node->size(), "scene: cannot set '", dotted_path, "': ", where(node_path), " has ",
              node->size(), " entries");
      node = &(*node)[step.index];
      node_path = item_path(node_path, step.index);
    } else {
      require(node->is_object(), "scene: cannot set '", dotted_path, "': ", where(node_path), " is ", describe(*node),
              ", not an object");
      const bool may_add = i + 1 == steps.size() && new_keys == NewKeys::allow;
      if (!node->contains(step.key) && !may_add)
        fail("scene: unknown key '", child_path(node_path, step.key), "' (known: ", join_sorted(keys_of(*node)), ")");
      node = &(*node)[step.key];
      node_path = child_path(node_path, step.key);
    }
  }
  *node = std::move(value.value_->json);
}

// ---------------------------------------------------------------------------------------------------------
// Output and comparison

std::string Json::dump(int indent) const {
  std::string out;
  write(out, value_->json, indent, 0);
  return out;
}

bool operator==(const Json& a, const Json& b) {
  // nlohmann::json keeps keys sorted, so its == ignores their order.
  return nlohmann::json(a.value_->json) == nlohmann::json(b.value_->json);
}

// ---------------------------------------------------------------------------------------------------------
// Reading

Json parse_json(const std::string& text, const std::string& source_name) {
  StrictBuilder builder(text, source_name);
  // Every error throws from the builder, so sax_parse cannot return false.
  static_cast<void>(ordered_json::sax_parse(text, &builder));
  return Json(Json::Value{std::move(builder.root())}, "");
}

Json read_json_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  // A directory opens as a stream on Linux and then reads as empty.
  require(in.good() && !std::filesystem::is_directory(path), "cannot open scene '", path, "'");
  // Read in chunks up to a bound, so that /dev/zero or a runaway file is refused instead of filling memory.
  constexpr std::size_t kMaxSceneBytes = std::size_t(64) << 20;
  std::string content;
  char chunk[65536];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    content.append(chunk, std::size_t(in.gcount()));
    require(content.size() <= kMaxSceneBytes, "scene '", path, "' is larger than 64 MiB: not a scene file");
  }
  require(!in.bad(), "cannot read scene '", path, "'");
  return parse_json(content, path);
}

Json parse_json_value_from_cli(const std::string& text, const std::string& source_name) {
  const bool looks_like_json = !text.empty() && (text[0] == '[' || text[0] == '{' || text[0] == '"');
  if (looks_like_json || reads_as_number(text)) return parse_json(text, source_name);
  try {
    return parse_json(text, source_name);
  } catch (const Error&) {
    return Json(text);
  }
}

std::vector<std::string> unknown_keys(const Json& object, const std::vector<std::string>& allowed) {
  std::vector<std::string> unknown;
  for (const std::string& key : object.keys())
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      unknown.push_back(child_path(object.path(), key));
  return unknown;
}

std::vector<std::string> unknown_keys(const Json& object, std::initializer_list<std::string_view> allowed) {
  return unknown_keys(object, std::vector<std::string>(allowed.begin(), allowed.end()));
}

void require_known_keys(const Json& object, const std::vector<std::string>& allowed) {
  const std::vector<std::string> unknown = unknown_keys(object, allowed);
  if (unknown.empty()) return;
  std::string listed;
  for (const std::string& path : unknown) listed += (listed.empty() ? "'" : ", '") + path + "'";
  // A known key close to an unknown one, as git and cargo suggest: "; did you mean 'c_nu'?" (with several
  // unknown keys, "'c_nu' for 'c_nuu', ..."); nothing when no known key is close.
  std::string suggested;
  for (const std::string& key : object.keys()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    if (const std::vector<std::string> closest = closest_names(key, allowed); !closest.empty())
      suggested += message(suggested.empty() ? "; did you mean " : ", ", quoted_alternatives(closest),
                           unknown.size() > 1 ? " for '" + key + "'" : "");
  }
  fail("scene: unknown key", unknown.size() > 1 ? "s " : " ", listed, " (known: ", join_sorted(allowed), ")", suggested,
       suggested.empty() ? "" : "?");
}

void require_known_keys(const Json& object, std::initializer_list<std::string_view> allowed) {
  require_known_keys(object, std::vector<std::string>(allowed.begin(), allowed.end()));
}

}  // namespace pc

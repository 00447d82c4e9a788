#include "models/scene/json.hpp"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "assembly/error.hpp"

namespace pc {
namespace {

const char* type_name(Json::Type type) {
  switch (type) {
    case Json::Type::null: return "null";
    case Json::Type::boolean: return "a boolean";
    case Json::Type::number: return "a number";
    case Json::Type::string: return "a string";
    case Json::Type::array: return "an array";
    case Json::Type::object: return "an object";
  }
  return "?";
}

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
  char buffer[64];
  const bool integral = std::trunc(value) == value && std::fabs(value) < 9007199254740992.0;
  const auto result = integral ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed)
                               : std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string join_sorted(std::vector<std::string> names) {
  if (names.empty()) return "none";
  std::sort(names.begin(), names.end());
  std::string joined;
  for (const std::string& name : names) joined += (joined.empty() ? "" : ", ") + name;
  return joined;
}

// Length of the valid UTF-8 sequence starting at text[pos], or 0 when it is not valid: no overlong forms,
// no encoded surrogates, nothing above U+10FFFF.
std::size_t utf8_sequence_length(std::string_view text, std::size_t pos) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(pos);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned char min_second = 0x80, max_second = 0xBF;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) min_second = 0xA0;  // overlong below U+0800
    if (lead == 0xED) max_second = 0x9F;  // surrogates U+D800..U+DFFF
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) min_second = 0x90;  // overlong below U+10000
    if (lead == 0xF4) max_second = 0x8F;  // above U+10FFFF
  } else {
    return 0;
  }
  if (pos + length > text.size()) return 0;
  if (byte(pos + 1) < min_second || byte(pos + 1) > max_second) return 0;
  for (std::size_t i = 2; i < length; ++i)
    if ((byte(pos + i) & 0xC0) != 0x80) return 0;
  return length;
}

bool is_valid_utf8(std::string_view text) {
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t length = utf8_sequence_length(text, pos);
    if (length == 0) return false;
    pos += length;
  }
  return true;
}

void append_utf8(std::string& out, unsigned code_point) {
  if (code_point < 0x80) {
    out += static_cast<char>(code_point);
  } else if (code_point < 0x800) {
    out += static_cast<char>(0xC0 | (code_point >> 6));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else if (code_point < 0x10000) {
    out += static_cast<char>(0xE0 | (code_point >> 12));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code_point >> 18));
    out += static_cast<char>(0x80 | ((code_point >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  }
}

void write_string(std::string& out, const std::string& text) {
  static const char hex[] = "0123456789abcdef";
  out += '"';
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          out += "\\u00";
          out += hex[(c >> 4) & 0xF];
          out += hex[c & 0xF];
        } else {
          out += c;
        }
    }
  }
  out += '"';
}

void write_newline(std::string& out, int indent, int depth) {
  if (indent <= 0) return;
  out += '\n';
  out.append(static_cast<std::size_t>(indent) * static_cast<std::size_t>(depth), ' ');
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

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// Construction

Json::Json(bool value) : type_(Type::boolean), bool_(value) {}

Json::Json(double value) : type_(Type::number), number_(value) {
  require(std::isfinite(value), "scene: JSON has no NaN or infinity, cannot store ", value);
}

Json::Json(std::string value) : type_(Type::string), string_(std::move(value)) {
  require(is_valid_utf8(string_), "scene: a string is not valid UTF-8");
}

Json Json::array(std::vector<Json> items) {
  Json result;
  result.type_ = Type::array;
  result.items_ = std::move(items);
  result.move_to("");
  return result;
}

Json Json::object(std::vector<Member> members) {
  Json result;
  result.type_ = Type::object;
  for (auto& [key, value] : members) {
    require(!result.find(key), "scene: duplicate key '", key, "'");
    result.set(key, std::move(value));
  }
  return result;
}

void Json::move_to(const std::string& path) {
  path_ = path;
  for (std::size_t i = 0; i < items_.size(); ++i) items_[i].move_to(item_path(path_, i));
  for (auto& [key, value] : members_) value.move_to(child_path(path_, key));
}

// ---------------------------------------------------------------------------------------------------------
// Typed access

void Json::fail_type(const char* expected) const {
  fail("scene: ", where(path_), " must be ", expected, ", got ", type_name(type_));
}

void Json::expect(Type expected) const {
  if (type_ != expected) fail_type(type_name(expected));
}

bool Json::as_bool() const {
  expect(Type::boolean);
  return bool_;
}

double Json::as_number() const {
  expect(Type::number);
  return number_;
}

int Json::as_int() const {
  expect(Type::number);
  require(std::trunc(number_) == number_, "scene: ", where(path_), " must be an integer, got ",
          format_number(number_));
  require(number_ >= INT_MIN && number_ <= INT_MAX, "scene: ", where(path_), " must be an integer in [", INT_MIN,
          ", ", INT_MAX, "], got ", format_number(number_));
  return static_cast<int>(number_);
}

const std::string& Json::as_string() const {
  expect(Type::string);
  return string_;
}

const std::vector<Json>& Json::as_array() const {
  expect(Type::array);
  return items_;
}

const std::vector<Json::Member>& Json::members() const {
  expect(Type::object);
  return members_;
}

double Json::as_positive() const {
  const double value = as_number();
  require(value > 0, "scene: ", where(path_), " must be > 0, got ", format_number(value));
  return value;
}

double Json::as_number_at_least(double min) const {
  const double value = as_number();
  require(value >= min, "scene: ", where(path_), " must be >= ", format_number(min), ", got ", format_number(value));
  return value;
}

double Json::as_number_in(double min, double max) const {
  const double value = as_number();
  require(value >= min && value <= max, "scene: ", where(path_), " must be in [", format_number(min), ", ",
          format_number(max), "], got ", format_number(value));
  return value;
}

int Json::as_int_at_least(int min) const {
  const int value = as_int();
  require(value >= min, "scene: ", where(path_), " must be an integer >= ", min, ", got ", value);
  return value;
}

std::vector<double> Json::as_vector() const {
  if (type_ != Type::array) fail_type("an array of numbers");
  std::vector<double> values;
  values.reserve(items_.size());
  for (const Json& item : items_) values.push_back(item.as_number());
  return values;
}

std::vector<double> Json::as_vector(std::size_t expected_size) const {
  if (type_ != Type::array) fail_type("an array of numbers");
  require(items_.size() == expected_size, "scene: ", where(path_), " must have ", expected_size,
          " entries, got ", items_.size());
  return as_vector();
}

Eigen::MatrixXd Json::as_matrix() const {
  if (type_ != Type::array) fail_type("a matrix (an array of rows)");
  require(!items_.empty(), "scene: ", where(path_), " must be a matrix, got an empty array");
  const std::size_t cols = items_[0].as_vector().size();
  require(cols > 0, "scene: ", where(path_), " must be a matrix, got an empty row 0");
  Eigen::MatrixXd matrix(static_cast<Eigen::Index>(items_.size()), static_cast<Eigen::Index>(cols));
  for (std::size_t r = 0; r < items_.size(); ++r) {
    const std::vector<double> row = items_[r].as_vector();
    require(row.size() == cols, "scene: ", where(path_), " must be a matrix, but row ", r, " has ", row.size(),
            " entries and row 0 has ", cols);
    for (std::size_t c = 0; c < cols; ++c)
      matrix(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = row[c];
  }
  return matrix;
}

Eigen::MatrixXd Json::as_matrix(Eigen::Index expected_rows, Eigen::Index expected_cols) const {
  Eigen::MatrixXd matrix = as_matrix();
  require(matrix.rows() == expected_rows && matrix.cols() == expected_cols, "scene: ", where(path_),
          " must be a ", expected_rows, "x", expected_cols, " matrix, got ", matrix.rows(), "x", matrix.cols());
  return matrix;
}

const Json* Json::find(std::string_view key) const {
  expect(Type::object);
  for (const auto& [name, value] : members_)
    if (name == key) return &value;
  return nullptr;
}

Json* Json::find_mutable(std::string_view key) { return const_cast<Json*>(std::as_const(*this).find(key)); }

const Json& Json::at(std::string_view key) const {
  const Json* value = find(key);
  if (!value) fail("scene: missing key '", child_path(path_, key), "'");
  return *value;
}

std::vector<std::string> Json::keys() const {
  std::vector<std::string> names;
  for (const auto& member : members()) names.push_back(member.first);
  return names;
}

const Json& Json::at(std::size_t index) const {
  expect(Type::array);
  require(index < items_.size(), "scene: ", where(item_path(path_, index)), " is out of range: ", where(path_),
          " has ", items_.size(), " entries");
  return items_[index];
}

std::size_t Json::size() const {
  if (type_ == Type::array) return items_.size();
  if (type_ == Type::object) return members_.size();
  fail_type("an array or an object");
}

// ---------------------------------------------------------------------------------------------------------
// Changes

void Json::set(const std::string& key, Json value) {
  expect(Type::object);
  value.move_to(child_path(path_, key));
  if (Json* existing = find_mutable(key)) {
    *existing = std::move(value);
  } else {
    members_.emplace_back(key, std::move(value));
  }
}

void Json::push_back(Json value) {
  expect(Type::array);
  value.move_to(item_path(path_, items_.size()));
  items_.push_back(std::move(value));
}

void Json::set_path(const std::string& dotted_path, Json value, NewKeys new_keys) {
  const std::vector<PathStep> steps = split_path(dotted_path);
  Json* node = this;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const PathStep& step = steps[i];
    const bool last = i + 1 == steps.size();
    if (step.is_index) {
      require(node->is_array(), "scene: cannot set '", dotted_path, "': ", where(node->path_), " is ",
              type_name(node->type_), ", not an array");
      require(step.index < node->items_.size(), "scene: cannot set '", dotted_path, "': ", where(node->path_),
              " has ", node->items_.size(), " entries");
      Json& item = node->items_[step.index];
      if (last) {
        value.move_to(item.path_);
        item = std::move(value);
        return;
      }
      node = &item;
    } else {
      require(node->is_object(), "scene: cannot set '", dotted_path, "': ", where(node->path_), " is ",
              type_name(node->type_), ", not an object");
      Json* member = node->find_mutable(step.key);
      if (last && (member || new_keys == NewKeys::allow)) {
        node->set(step.key, std::move(value));
        return;
      }
      if (!member)
        fail("scene: unknown key '", child_path(node->path_, step.key), "' (known: ", join_sorted(node->keys()), ")");
      node = member;
    }
  }
}

// ---------------------------------------------------------------------------------------------------------
// Output

std::string Json::dump(int indent) const {
  std::string out;
  write(out, indent, 0);
  return out;
}

void Json::write(std::string& out, int indent, int depth) const {
  switch (type_) {
    case Type::null: out += "null"; break;
    case Type::boolean: out += bool_ ? "true" : "false"; break;
    case Type::number: out += format_number(number_); break;
    case Type::string: write_string(out, string_); break;
    case Type::array:
      if (items_.empty()) {
        out += "[]";
        break;
      }
      out += '[';
      for (std::size_t i = 0; i < items_.size(); ++i) {
        if (i) out += ',';
        write_newline(out, indent, depth + 1);
        items_[i].write(out, indent, depth + 1);
      }
      write_newline(out, indent, depth);
      out += ']';
      break;
    case Type::object:
      if (members_.empty()) {
        out += "{}";
        break;
      }
      out += '{';
      for (std::size_t i = 0; i < members_.size(); ++i) {
        if (i) out += ',';
        write_newline(out, indent, depth + 1);
        write_string(out, members_[i].first);
        out += indent > 0 ? ": " : ":";
        members_[i].second.write(out, indent, depth + 1);
      }
      write_newline(out, indent, depth);
      out += '}';
      break;
  }
}

bool operator==(const Json& a, const Json& b) {
  if (a.type_ != b.type_) return false;
  switch (a.type_) {
    case Json::Type::null: return true;
    case Json::Type::boolean: return a.bool_ == b.bool_;
    case Json::Type::number: return a.number_ == b.number_;
    case Json::Type::string: return a.string_ == b.string_;
    case Json::Type::array: return a.items_ == b.items_;
    case Json::Type::object:
      if (a.members_.size() != b.members_.size()) return false;
      for (const auto& [key, value] : a.members_) {
        const Json* other = b.find(key);
        if (!other || !(*other == value)) return false;
      }
      return true;
  }
  return false;
}

// ---------------------------------------------------------------------------------------------------------
// Parsing

// Recursive descent over the whole text; each value is built with its final path.
class JsonParser {
 public:
  JsonParser(std::string_view text, const std::string& source_name) : text_(text), source_name_(source_name) {}

  Json parse_document() {
    // RFC 8259 lets a parser ignore a byte order mark, which some editors write.
    if (text_.starts_with("\xEF\xBB\xBF")) pos_ = 3;
    skip_whitespace();
    Json root = parse_value("", 0);
    skip_whitespace();
    if (pos_ < text_.size()) fail_here("expected the end of the input after the value, got " + describe_here());
    return root;
  }

 private:
  // Deep enough for any scene, shallow enough that hostile input cannot overflow the stack.
  static constexpr int max_depth = 256;

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

  [[noreturn]] void fail_here(const std::string& what) const { fail_at(pos_, what); }

  std::string describe_here() const {
    if (pos_ >= text_.size()) return "the end of the input";
    const unsigned char c = static_cast<unsigned char>(text_[pos_]);
    if (c >= 0x20 && c < 0x7F) return std::string("'") + static_cast<char>(c) + "'";
    char code[8];
    std::snprintf(code, sizeof code, "0x%02X", c);
    return std::string("byte ") + code;
  }

  bool at_end() const { return pos_ >= text_.size(); }
  char peek() const { return at_end() ? '\0' : text_[pos_]; }
  static bool is_digit(char c) { return c >= '0' && c <= '9'; }
  static bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

  void skip_whitespace() {
    while (!at_end() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r')) ++pos_;
  }

  Json parse_value(const std::string& path, int depth) {
    if (depth > max_depth) fail_here("nesting deeper than " + std::to_string(max_depth) + " levels");
    Json value;
    const char c = peek();
    if (c == '{') {
      value = parse_object(path, depth);
    } else if (c == '[') {
      value = parse_array(path, depth);
    } else if (c == '"') {
      value = Json(parse_string());
    } else if (c == '-' || is_digit(c)) {
      value = Json(parse_number());
    } else if (is_letter(c)) {
      value = parse_word();
    } else if (c == '/') {
      fail_here("comments are not allowed in JSON");
    } else if (c == '\'') {
      fail_here("strings must be in double quotes");
    } else {
      fail_here("expected a value, got " + describe_here());
    }
    value.path_ = path;
    return value;
  }

  std::string_view read_word() {
    const std::size_t start = pos_;
    while (!at_end() && (is_letter(peek()) || is_digit(peek()) || peek() == '_')) ++pos_;
    return text_.substr(start, pos_ - start);
  }

  static bool is_nan_or_infinity(std::string_view word) {
    std::string lower(word);
    std::transform(lower.begin(), lower.end(), lower.begin(), [](char c) { return static_cast<char>(c | 0x20); });
    return lower == "nan" || lower == "inf" || lower == "infinity";
  }

  Json parse_word() {
    const std::size_t start = pos_;
    const std::string_view word = read_word();
    if (word == "true") return Json(true);
    if (word == "false") return Json(false);
    if (word == "null") return Json();
    if (is_nan_or_infinity(word)) fail_at(start, "JSON has no NaN or infinity, got '" + std::string(word) + "'");
    fail_at(start, "expected a value, got '" + std::string(word) + "' (strings must be in double quotes)");
  }

  double parse_number() {
    const std::size_t start = pos_;
    if (peek() == '-') ++pos_;
    if (is_letter(peek())) {
      const std::string_view word = read_word();
      if (is_nan_or_infinity(word)) fail_at(start, "JSON has no NaN or infinity, got '-" + std::string(word) + "'");
      pos_ = start + 1;
    }
    if (!is_digit(peek())) fail_here("expected a digit after '-', got " + describe_here());
    if (peek() == '0') {
      ++pos_;
      if (is_digit(peek())) fail_here("numbers may not have leading zeros");
    } else {
      skip_digits();
    }
    if (peek() == '.') {
      ++pos_;
      if (!is_digit(peek())) fail_here("expected a digit after the decimal point, got " + describe_here());
      skip_digits();
    }
    if (peek() == 'e' || peek() == 'E') {
      ++pos_;
      if (peek() == '+' || peek() == '-') ++pos_;
      if (!is_digit(peek())) fail_here("expected a digit in the exponent, got " + describe_here());
      skip_digits();
    }
    double value = 0.0;
    const auto [end, error] = std::from_chars(text_.data() + start, text_.data() + pos_, value);
    if (error != std::errc() || end != text_.data() + pos_)
      fail_at(start, "number " + std::string(text_.substr(start, pos_ - start)) + " is out of the range of a double");
    return value;
  }

  void skip_digits() {
    while (is_digit(peek())) ++pos_;
  }

  unsigned parse_hex4() {
    unsigned code = 0;
    for (int i = 0; i < 4; ++i, ++pos_) {
      const char c = peek();
      unsigned digit;
      if (is_digit(c)) {
        digit = static_cast<unsigned>(c - '0');
      } else if (c >= 'a' && c <= 'f') {
        digit = static_cast<unsigned>(c - 'a' + 10);
      } else if (c >= 'A' && c <= 'F') {
        digit = static_cast<unsigned>(c - 'A' + 10);
      } else {
        fail_here("expected 4 hexadecimal digits after \\u, got " + describe_here());
      }
      code = code * 16 + digit;
    }
    return code;
  }

  // The escape starts at pos_, just after the backslash.
  void parse_escape(std::string& out) {
    const std::size_t backslash = pos_ - 1;
    const char c = peek();
    ++pos_;
    switch (c) {
      case '"': out += '"'; return;
      case '\\': out += '\\'; return;
      case '/': out += '/'; return;
      case 'b': out += '\b'; return;
      case 'f': out += '\f'; return;
      case 'n': out += '\n'; return;
      case 'r': out += '\r'; return;
      case 't': out += '\t'; return;
      case 'u': break;
      default:
        fail_at(backslash, "invalid escape in a string (valid: \\\" \\\\ \\/ \\b \\f \\n \\r \\t \\uXXXX)");
    }
    unsigned code = parse_hex4();
    if (code >= 0xDC00 && code <= 0xDFFF) fail_at(backslash, "unpaired low surrogate in a \\u escape");
    if (code >= 0xD800 && code <= 0xDBFF) {
      // A character above U+FFFF is written as a surrogate pair: \uD83D\uDE00.
      if (!text_.substr(pos_).starts_with("\\u")) fail_at(backslash, "high surrogate not followed by a low surrogate");
      pos_ += 2;
      const unsigned low = parse_hex4();
      if (low < 0xDC00 || low > 0xDFFF) fail_at(backslash, "high surrogate not followed by a low surrogate");
      code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
    }
    append_utf8(out, code);
  }

  std::string parse_string() {
    const std::size_t start = pos_;
    ++pos_;  // opening quote
    std::string out;
    while (true) {
      if (at_end()) fail_at(start, "unterminated string");
      const unsigned char c = static_cast<unsigned char>(peek());
      if (c == '"') break;
      if (c == '\\') {
        ++pos_;
        if (at_end()) fail_at(start, "unterminated string");
        parse_escape(out);
      } else if (c < 0x20) {
        fail_here("control character in a string (write it as an escape such as \\n or \\u001f)");
      } else {
        const std::size_t length = utf8_sequence_length(text_, pos_);
        if (length == 0) fail_here("invalid UTF-8 in a string");
        out.append(text_.substr(pos_, length));
        pos_ += length;
      }
    }
    ++pos_;  // closing quote
    return out;
  }

  Json parse_array(const std::string& path, int depth) {
    Json array = Json::array();
    ++pos_;  // '['
    skip_whitespace();
    if (peek() == ']') {
      ++pos_;
      return array;
    }
    while (true) {
      skip_whitespace();
      if (peek() == ']') fail_here("trailing comma before ']'");
      array.items_.push_back(parse_value(item_path(path, array.items_.size()), depth + 1));
      skip_whitespace();
      if (peek() == ']') break;
      if (peek() != ',') fail_here("expected ',' or ']' after an entry of " + where(path) + ", got " + describe_here());
      ++pos_;
    }
    ++pos_;  // ']'
    return array;
  }

  Json parse_object(const std::string& path, int depth) {
    Json object = Json::object();
    ++pos_;  // '{'
    skip_whitespace();
    if (peek() == '}') {
      ++pos_;
      return object;
    }
    while (true) {
      skip_whitespace();
      if (peek() == '}') fail_here("trailing comma before '}'");
      if (peek() != '"') fail_here("expected a key in double quotes, got " + describe_here());
      const std::size_t key_start = pos_;
      std::string key = parse_string();
      if (object.find(key)) fail_at(key_start, "duplicate key '" + child_path(path, key) + "'");
      skip_whitespace();
      if (peek() != ':') fail_here("expected ':' after the key \"" + key + "\", got " + describe_here());
      ++pos_;
      skip_whitespace();
      Json value = parse_value(child_path(path, key), depth + 1);
      object.members_.emplace_back(std::move(key), std::move(value));
      skip_whitespace();
      if (peek() == '}') break;
      if (peek() != ',') fail_here("expected ',' or '}' after a member of " + where(path) + ", got " + describe_here());
      ++pos_;
    }
    ++pos_;  // '}'
    return object;
  }

  std::string_view text_;
  const std::string& source_name_;
  std::size_t pos_ = 0;
};

Json parse_json(const std::string& text, const std::string& source_name) {
  return JsonParser(text, source_name).parse_document();
}

Json read_json_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  // A directory opens as a stream on Linux and then reads as empty.
  require(in.good() && !std::filesystem::is_directory(path), "cannot open scene '", path, "'");
  std::ostringstream content;
  content << in.rdbuf();
  require(!in.bad(), "cannot read scene '", path, "'");
  return parse_json(content.str(), path);
}

Json parse_json_value_from_cli(const std::string& text) {
  const bool looks_like_json = !text.empty() && (text[0] == '[' || text[0] == '{' || text[0] == '"');
  if (looks_like_json) return parse_json(text, "command-line value");
  try {
    return parse_json(text, "command-line value");
  } catch (const Error&) {
    return Json(text);
  }
}

std::vector<std::string> unknown_keys(const Json& object, std::initializer_list<std::string_view> allowed) {
  std::vector<std::string> unknown;
  for (const auto& [key, value] : object.members())
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) unknown.push_back(value.path());
  return unknown;
}

void require_known_keys(const Json& object, std::initializer_list<std::string_view> allowed) {
  require_known_keys(object, std::vector<std::string>(allowed.begin(), allowed.end()));
}

void require_known_keys(const Json& object, const std::vector<std::string>& allowed) {
  std::vector<std::string> unknown;
  for (const auto& [key, value] : object.members())
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) unknown.push_back(value.path());
  if (unknown.empty()) return;
  std::string listed;
  for (const std::string& path : unknown) listed += (listed.empty() ? "'" : ", '") + path + "'";
  fail("scene: unknown key", unknown.size() > 1 ? "s " : " ", listed, " (known: ", join_sorted(allowed), ")");
}

}  // namespace pc

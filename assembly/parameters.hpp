#pragma once
// Declared parameters: a name, a unit, one line of documentation, a default (or none: required) and the
// range a value must lie in. Whatever a scene can name (a law, a time scheme, a solver) declares its
// parameters once, next to its code, and everything else reads the declaration: the scene reader
// (defaults, range checks with the value and the key named), `piezocontact describe`, the generated
// tables of docs/scenes.md, and the bricks that read law parameters from the model (MOOSE's validParams).
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pc {

// An interval of the real line; each end open or closed, infinite ends allowed.
struct Range {
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool lower_open = false;
  bool upper_open = false;

  static constexpr Range any() { return {}; }
  static constexpr Range at_least(double a) { return {a, std::numeric_limits<double>::infinity(), false, false}; }
  static constexpr Range positive() { return {0, std::numeric_limits<double>::infinity(), true, false}; }
  // (a, b]
  static constexpr Range left_open(double a, double b) { return {a, b, true, false}; }
  // [a, b]
  static constexpr Range closed(double a, double b) { return {a, b, false, false}; }
  // Finite and inside the interval.
  bool contains(double value) const;
  // ">= 0", "> 0", "in (0, 1]", "finite".
  std::string describe() const;
};

struct ParameterDeclaration {
  std::string name;
  std::string unit;                     // SI unit, "1" for a pure number
  std::string doc;                      // one line
  std::optional<double> default_value;  // none: the parameter is required
  Range range;
  bool required() const { return !default_value.has_value(); }
};

using ParameterValues = std::map<std::string, double>;

// A registered thing chosen by name, with the values of its parameters (those left out take their defaults).
struct Choice {
  std::string name;
  ParameterValues parameters;
};

// The one range check of a number, a declared parameter's or a scene's: throws pc::Error
// "<subject> must be >= 0, got -1" (or "must be finite and >= 0, got nan") when the value is outside.
void require_in_range(const Range& range, double value, const std::string& subject);
// require_in_range with the subject "<where>: <name>".
void check_parameter(const ParameterDeclaration& declaration, double value, const std::string& where);
// The declaration of that name, or null.
const ParameterDeclaration* find_parameter(const std::vector<ParameterDeclaration>& declarations,
                                           const std::string& name);
// The given values checked against the declarations (an undeclared name, a value out of its range and a
// missing required parameter are errors naming `where`), with the defaults of those left out.
ParameterValues checked_values(const std::vector<ParameterDeclaration>& declarations, ParameterValues values,
                               const std::string& where);

}  // namespace pc

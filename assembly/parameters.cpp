#include "assembly/parameters.hpp"

#include <cmath>

#include "assembly/error.hpp"

namespace pc {

bool Range::contains(double value) const {
  if (!std::isfinite(value)) return false;
  const bool above = lower_open ? value > lower : value >= lower;
  const bool below = upper_open ? value < upper : value <= upper;
  return above && below;
}

std::string Range::describe() const {
  const bool has_lower = std::isfinite(lower), has_upper = std::isfinite(upper);
  if (!has_lower && !has_upper) return "finite";
  if (!has_upper) return message(lower_open ? "> " : ">= ", lower);
  if (!has_lower) return message(upper_open ? "< " : "<= ", upper);
  return message("in ", lower_open ? "(" : "[", lower, ", ", upper, upper_open ? ")" : "]");
}

void require_in_range(const Range& range, double value, const std::string& subject) {
  if (range.contains(value)) return;
  const std::string bound = range.describe();
  const std::string expected = std::isfinite(value) ? bound : bound == "finite" ? bound : "finite and " + bound;
  fail(subject, " must be ", expected, ", got ", value);
}

void check_parameter(const ParameterDeclaration& declaration, double value, const std::string& where) {
  require_in_range(declaration.range, value, where + ": " + declaration.name);
}

const ParameterDeclaration* find_parameter(const std::vector<ParameterDeclaration>& declarations,
                                           const std::string& name) {
  for (const ParameterDeclaration& d : declarations)
    if (d.name == name) return &d;
  return nullptr;
}

ParameterValues checked_values(const std::vector<ParameterDeclaration>& declarations, ParameterValues values,
                               const std::string& where) {
  for (const auto& [name, value] : values) {
    const ParameterDeclaration* declaration = find_parameter(declarations, name);
    if (declaration == nullptr) {
      std::string known;
      for (const ParameterDeclaration& d : declarations) known += (known.empty() ? "" : ", ") + d.name;
      fail(where, ": no parameter '", name, "' (it has: ", known.empty() ? "none" : known, ")");
    }
    check_parameter(*declaration, value, where);
  }
  for (const ParameterDeclaration& d : declarations) {
    if (values.count(d.name)) continue;
    require(!d.required(), where, ": parameter ", d.name, " (", d.doc, ") is required");
    values[d.name] = *d.default_value;
  }
  return values;
}

}  // namespace pc

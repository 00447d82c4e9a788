#pragma once
// How a law declares its parameters: a static parameters() listing, per parameter, its name, the member
// it sets, its unit, one line of documentation, the range of valid values and whether it has a default
// (the member's initial value) or is required. That one declaration is what the registry documents, the
// scene reader checks and the bricks read from the model's constants:
//
//   struct LinearDampedResponse {
//     double c_nu = 0;
//     static constexpr auto parameters() {
//       return std::array{law_parameter("c_nu", &LinearDampedResponse::c_nu, "Pa s/m",
//                                       "damping coefficient", Range::at_least(0), Required::yes)};
//     }
//     ...
//   };
//
// A law that declares none (a user's quick law) holds fixed values and its brick reads no model data.
#include <string>
#include <vector>

#include "assembly/parameters.hpp"

namespace pc {

enum class Required { no, yes };

template <class Law> struct LawParameter {
  const char* name;
  double Law::*member;
  const char* unit;
  const char* doc;
  Range range;
  Required required;
};

template <class Law>
constexpr LawParameter<Law> law_parameter(const char* name, double Law::*member, const char* unit, const char* doc,
                                          Range range, Required required = Required::no) {
  return {name, member, unit, doc, range, required};
}

template <class Law>
concept DeclaresParameters = requires {
  Law::parameters();
};

// The declarations, with defaults taken from a default-constructed law.
template <DeclaresParameters Law> std::vector<ParameterDeclaration> parameter_declarations() {
  std::vector<ParameterDeclaration> out;
  const Law defaults{};
  for (const LawParameter<Law>& p : Law::parameters()) {
    ParameterDeclaration d{p.name, p.unit, p.doc, {}, p.range};
    if (p.required == Required::no) d.default_value = defaults.*(p.member);
    out.push_back(std::move(d));
  }
  return out;
}

// The law's parameter values by name, e.g. {{"c_nu", 1e12}}: what a driver writes into the model's
// constants (Model::set_constants(law_values(LinearDampedResponse{1e12}))).
template <DeclaresParameters Law> ParameterValues law_values(const Law& law) {
  ParameterValues out;
  for (const LawParameter<Law>& p : Law::parameters()) out[p.name] = law.*(p.member);
  return out;
}

}  // namespace pc

// A foundation law of the user's own: a conductive foundation that can deliver only a limited charge flux,
// the paper's D.n = k_e (phi - phi_f) for small potential differences, saturating at the flux k_e phi_s.
// A value type with operator() on any scalar (Dual gives the brick its tangent), compile-time traits, and
// its parameters declared once: name, member, unit, documentation, valid range, required or defaulted. The
// brick reads them from the model's constants by these names, checked against these ranges.
// examples/custom_foundation_law.cpp runs it; the README's "Writing a new foundation law" shows it.
// [snippet law]
#pragma once
#include <array>
#include <cmath>

#include "bricks/laws/law_parameters.hpp"

struct SaturatingConductance {  // D.n = k_e phi_s tanh((phi - phi_f) / phi_s)
  double k_e = 0, phi_f = 0, phi_s = 1;
  static constexpr bool affine = false;                // tanh: the brick is nonlinear
  static constexpr bool dissipative = true;            // monotone in phi
  static constexpr bool uses_normal_pressure = false;  // conducts whether pressed or not
  static constexpr auto parameters() {
    using pc::law_parameter, pc::Range, pc::Required;
    return std::array{law_parameter("k_e", &SaturatingConductance::k_e, "C/(V m^2)",
                                    "conductance at small potential differences", Range::at_least(0), Required::yes),
                      law_parameter("phi_f", &SaturatingConductance::phi_f, "V", "potential of the foundation",
                                    Range::any(), Required::yes),
                      law_parameter("phi_s", &SaturatingConductance::phi_s, "V",
                                    "potential difference where the flux saturates", Range::positive())};
  }
  template <class S> S operator()(const S& phi, const S& /*pressure*/) const {
    using std::tanh;  // std::tanh for double; pc::tanh (found by argument-dependent lookup) for Dual
    return k_e * phi_s * tanh((phi - phi_f) / phi_s);
  }
};
// [snippet law end]

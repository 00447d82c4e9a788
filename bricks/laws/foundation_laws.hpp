#pragma once
// Foundation laws: the normal electric displacement D.n on the contact surface as a function of the
// potential phi and, for laws that switch with contact, of the contact pressure p = p_nu (paper (10):
// D.n = k_e (phi - phi_f)). Every law has the signature
//   template <class S> S operator()(const S& phi, const S& pressure) const;
// Such a law is dissipative when it is monotone in phi: (D(phi1) - D(phi2)) (phi1 - phi2) >= 0, the
// electric analogue of p(r) . r >= 0.
#include <string>

#include "assembly/dual.hpp"
#include "bricks/laws/law_parameters.hpp"
#include "bricks/laws/normal_laws.hpp"

namespace pc {

// D.n = k_e (phi - phi_f): a foundation at potential phi_f, always conductive (paper (10)).
struct LinearConductance {
  double k_e = 0;
  double phi_f = 0;

  static constexpr bool affine = true;
  static constexpr bool dissipative = true;
  static constexpr bool uses_normal_pressure = false;

  template <class S>
  S operator()(const S& phi, const S& /*pressure*/) const {
    return k_e * (phi - phi_f);
  }
  void validate(const std::string& brick) const {
    require_parameter_at_least(brick, "LinearConductance", "k_e", k_e, 0);
    require_finite_parameter(brick, "LinearConductance", "phi_f", phi_f);
  }
};

// D.n = k_e s(p) (phi - phi_f) with s(p) = p_+^2 / (p_+^2 + p_ref^2): charge flows only where the body
// presses on the foundation, switching on smoothly over pressures of order p_ref. The pressure comes
// from the normal law `normal` this law holds, which couples phi to the velocity (or displacement).
template <class NormalLaw = LinearDampedResponse>
struct PressureActivatedConductance {
  double k_e = 0;
  double phi_f = 0;
  double p_ref = 1;
  NormalLaw normal{};

  static constexpr bool affine = false;
  static constexpr bool dissipative = true;
  static constexpr bool uses_normal_pressure = true;

  template <class S>
  S operator()(const S& phi, const S& pressure) const {
    return k_e * activation(pressure) * (phi - phi_f);
  }
  // s(p), written in x = p_+ / p_ref on both sides of x = 1 so that x^2 neither overflows nor gives inf/inf.
  template <class S>
  S activation(const S& pressure) const {
    const S x = positive_part(pressure) / p_ref;
    if (x <= 1.0) return x * x / (1.0 + x * x);
    const S inverse = 1.0 / x;
    return 1.0 / (1.0 + inverse * inverse);
  }
  void validate(const std::string& brick) const {
    require_parameter_at_least(brick, "PressureActivatedConductance", "k_e", k_e, 0);
    require_finite_parameter(brick, "PressureActivatedConductance", "phi_f", phi_f);
    require_positive_parameter(brick, "PressureActivatedConductance", "p_ref", p_ref);
    validate_law(normal, brick);
  }
};

}  // namespace pc

#pragma once
// Foundation laws: the normal electric displacement D.n on the contact surface as a function of the
// potential phi and, for laws that switch with contact, of the contact pressure p = p_nu (paper (10):
// D.n = k_e (phi - phi_f)). Every law has the signature
//   template <class S> S operator()(const S& phi, const S& pressure) const;
// Such a law is dissipative when it is monotone in phi: (D(phi1) - D(phi2)) (phi1 - phi2) >= 0, the
// electric analogue of p(r) . r >= 0.
#include <array>

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

  static constexpr auto parameters() {
    return std::array{law_parameter("k_e", &LinearConductance::k_e, "C/(V m^2)", "conductance: D.n = k_e (phi - phi_f)",
                                    Range::at_least(0), Required::yes),
                      law_parameter("phi_f", &LinearConductance::phi_f, "V", "potential of the foundation",
                                    Range::any(), Required::yes)};
  }
  template <class S> S operator()(const S& phi, const S& /*pressure*/) const { return k_e * (phi - phi_f); }
};

// D.n = k_e s(p) (phi - phi_f) with s(p) = p_+^2 / (p_+^2 + p_ref^2): charge flows only where the body
// presses on the foundation, switching on smoothly over pressures of order p_ref. The pressure comes
// from the normal brick the foundation brick is paired with, which couples phi to the velocity (or
// displacement).
struct PressureActivatedConductance {
  double k_e = 0;
  double phi_f = 0;
  double p_ref = 1;

  static constexpr bool affine = false;
  static constexpr bool dissipative = true;
  static constexpr bool uses_normal_pressure = true;

  static constexpr auto parameters() {
    return std::array{law_parameter("k_e", &PressureActivatedConductance::k_e, "C/(V m^2)",
                                    "conductance at full contact", Range::at_least(0), Required::yes),
                      law_parameter("phi_f", &PressureActivatedConductance::phi_f, "V", "potential of the foundation",
                                    Range::any(), Required::yes),
                      law_parameter("p_ref", &PressureActivatedConductance::p_ref, "Pa",
                                    "pressure over which conduction switches on", Range::positive(), Required::yes)};
  }
  template <class S> S operator()(const S& phi, const S& pressure) const {
    return k_e * activation(pressure) * (phi - phi_f);
  }
  // s(p), written in x = p_+ / p_ref on both sides of x = 1 so that x^2 neither overflows nor gives inf/inf.
  template <class S> S activation(const S& pressure) const {
    const S x = positive_part(pressure) / p_ref;
    if (x <= 1.0) return x * x / (1.0 + x * x);
    const S inverse = 1.0 / x;
    return 1.0 / (1.0 + inverse * inverse);
  }
};

}  // namespace pc

#pragma once
// Normal laws p_nu(r): the normal contact stress -sigma_nu as a function of the normal velocity r = v.n
// (damped responses, paper (9), (12)) or of the normal displacement r = u.n (normal compliance). n is the
// body's outward normal, so r > 0 moves into the foundation; p_nu = 0 for r <= 0 (or r <= gap): no contact.
//
// The value is templated on the scalar so that Dual gives the derivative. At the kink the derivative is
// the right-sided one: a Newton step from a body at rest on the foundation sees the foundation's stiffness.
#include <array>
#include <cmath>

#include "assembly/dual.hpp"
#include "bricks/laws/law_parameters.hpp"

namespace pc {

// r_+ = max(r, 0), keeping the derivative 1 at r = 0 (right-sided).
template <class S> S positive_part(const S& r) { return r < 0.0 ? S(0.0) : r; }

// p_nu(r) = c_nu r_+, paper (12).
struct LinearDampedResponse {
  double c_nu = 0;

  static constexpr bool affine = false;  // piecewise linear: the kink at r = 0 makes the brick nonlinear
  static constexpr bool dissipative = true;
  static constexpr bool uses_displacement = false;

  static constexpr auto parameters() {
    return std::array{law_parameter("c_nu", &LinearDampedResponse::c_nu, "Pa s/m",
                                    "damping coefficient: p_nu = c_nu max(v_nu, 0)", Range::at_least(0),
                                    Required::yes)};
  }
  template <class S> S operator()(const S& r) const { return c_nu * positive_part(r); }
};

// p_nu(r) = c_nu r_+^m with m >= 1 (m = 1 is LinearDampedResponse).
struct PowerDampedResponse {
  double c_nu = 0;
  double m = 1;

  static constexpr bool affine = false;
  static constexpr bool dissipative = true;
  static constexpr bool uses_displacement = false;

  static constexpr auto parameters() {
    return std::array{
        law_parameter("c_nu", &PowerDampedResponse::c_nu, "Pa (s/m)^m",
                      "damping coefficient: p_nu = c_nu max(v_nu, 0)^m", Range::at_least(0), Required::yes),
        law_parameter("m", &PowerDampedResponse::m, "1", "exponent", Range::at_least(1))};
  }
  template <class S> S operator()(const S& r) const {
    using std::pow;
    return r < 0.0 ? S(0.0) : c_nu * pow(r, m);
  }
};

// p_nu(u_nu) = c_nu (u_nu - gap)_+^m: a deformable foundation that resists penetration beyond the initial
// gap. Elastic, not damped: it stores energy, so it is not declared dissipative.
struct NormalCompliance {
  double c_nu = 0;
  double m = 1;
  double gap = 0;

  static constexpr bool affine = false;
  static constexpr bool dissipative = false;
  static constexpr bool uses_displacement = true;

  static constexpr auto parameters() {
    return std::array{law_parameter("c_nu", &NormalCompliance::c_nu, "Pa/m^m",
                                    "stiffness: p_nu = c_nu max(u_nu - gap, 0)^m", Range::at_least(0), Required::yes),
                      law_parameter("m", &NormalCompliance::m, "1", "exponent", Range::at_least(1)),
                      law_parameter("gap", &NormalCompliance::gap, "m", "initial gap to the foundation", Range::any())};
  }
  template <class S> S operator()(const S& u_nu) const {
    using std::pow;
    const S penetration = u_nu - gap;
    return penetration < 0.0 ? S(0.0) : c_nu * pow(penetration, m);
  }
};

}  // namespace pc

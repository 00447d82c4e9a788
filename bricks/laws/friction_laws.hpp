#pragma once
// Friction laws p_tau(r): the tangential contact stress -sigma_tau as a function of the tangential
// velocity r = v_tau (dim components, tangent to the contact surface) and, for laws of Coulomb type, of
// the normal pressure p_nu = -sigma_nu >= 0 (paper (9), (13)). Every law has the signature
//   template <class S> void operator()(const S* r, int dim, const S& normal_pressure, S* out) const;
// templated on the scalar so that Dual gives the derivatives in r and in the pressure.
#include <array>

#include "assembly/dual.hpp"
#include "bricks/laws/direction.hpp"
#include "bricks/laws/law_parameters.hpp"

namespace pc {

// p_tau(r) = c_tau r, paper (13).
struct ViscousFriction {
  double c_tau = 0;

  static constexpr bool affine = true;
  static constexpr bool dissipative = true;
  static constexpr bool monotone = true;
  static constexpr bool symmetric = true;
  static constexpr bool uses_normal_pressure = false;

  static constexpr auto parameters() {
    return std::array{law_parameter("c_tau", &ViscousFriction::c_tau, "Pa s/m",
                                    "friction coefficient: p_tau = c_tau v_tau", Range::at_least(0), Required::yes)};
  }
  template <class S> void operator()(const S* r, int dim, const S& /*normal_pressure*/, S* out) const {
    for (int i = 0; i < dim; ++i) out[i] = c_tau * r[i];
  }
};

// p_tau(r) = mu |p_nu| r / sqrt(|r|^2 + eps^2): Coulomb's law with the slip threshold mu |p_nu|, smoothed
// over slip velocities of order eps.
struct RegularizedCoulomb {
  double mu = 0;
  double eps = 1e-6;

  static constexpr bool affine = false;
  static constexpr bool dissipative = true;
  static constexpr bool monotone = true;   // in r, at one pressure
  static constexpr bool bounded = true;    // |p_tau| < mu |p_nu|
  static constexpr bool symmetric = true;  // in r; the pressure coupling is not, and the brick knows it
  static constexpr bool uses_normal_pressure = true;

  static constexpr auto parameters() {
    return std::array{
        law_parameter("mu", &RegularizedCoulomb::mu, "1", "friction coefficient: slip threshold mu |p_nu|",
                      Range::at_least(0), Required::yes),
        law_parameter("eps", &RegularizedCoulomb::eps, "m/s", "regularisation: slip velocity of the smoothing",
                      Range::positive(), Required::yes)};
  }
  template <class S> void operator()(const S* r, int dim, const S& normal_pressure, S* out) const {
    // |p_nu| with the right-sided derivative at 0, like the normal laws that produce it.
    const S threshold = mu * (normal_pressure < 0.0 ? -normal_pressure : normal_pressure);
    regularized_direction(r, dim, eps, out);
    for (int i = 0; i < dim; ++i) out[i] *= threshold;
  }
};

// p_tau(r) = g r / sqrt(|r|^2 + eps^2): Tresca's law with a given slip bound g, smoothed like Coulomb's.
struct RegularizedTresca {
  double g = 0;
  double eps = 1e-6;

  static constexpr bool affine = false;
  static constexpr bool dissipative = true;
  static constexpr bool monotone = true;
  static constexpr bool bounded = true;  // |p_tau| < g
  static constexpr bool symmetric = true;
  static constexpr bool uses_normal_pressure = false;

  static constexpr auto parameters() {
    return std::array{
        law_parameter("g", &RegularizedTresca::g, "Pa", "slip bound", Range::at_least(0), Required::yes),
        law_parameter("eps", &RegularizedTresca::eps, "m/s", "regularisation: slip velocity of the smoothing",
                      Range::positive(), Required::yes)};
  }
  template <class S> void operator()(const S* r, int dim, const S& /*normal_pressure*/, S* out) const {
    regularized_direction(r, dim, eps, out);
    for (int i = 0; i < dim; ++i) out[i] *= g;
  }
};

}  // namespace pc

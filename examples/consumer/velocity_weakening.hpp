#pragma once
// A friction law that none of piezocontact's is: Coulomb friction whose coefficient falls with the slip
// speed s = |v_tau| from its static value mu_s to its kinetic value mu_k over a speed v_c (the
// velocity weakening behind stick-slip),
//   p_tau = mu(s) |p_nu| v_tau / sqrt(s^2 + eps^2),   mu(s) = mu_k + (mu_s - mu_k) exp(-s / v_c).
// Written as a user outside the library writes a law: operator() on any scalar (Dual gives the
// tangent), traits, and the parameters declared once.
#include <array>
#include <cmath>

#include "bricks/laws/friction_laws.hpp"
#include "bricks/laws/law_parameters.hpp"

struct VelocityWeakeningCoulomb {
  double mu_s = 0, mu_k = 0, v_c = 1, eps = 1;

  static constexpr bool affine = false;
  static constexpr bool dissipative = true;           // mu(s) >= 0, so p_tau . v_tau >= 0
  static constexpr bool symmetric = true;             // p = g(|r|) r has a symmetric Jacobian
  static constexpr bool uses_normal_pressure = true;  // reads p_nu from the paired normal brick

  static constexpr auto parameters() {
    using pc::law_parameter, pc::Range, pc::Required;
    return std::array{law_parameter("mu_s", &VelocityWeakeningCoulomb::mu_s, "1", "static friction coefficient",
                                    Range::at_least(0), Required::yes),
                      law_parameter("mu_k", &VelocityWeakeningCoulomb::mu_k, "1", "kinetic friction coefficient",
                                    Range::at_least(0), Required::yes),
                      law_parameter("v_c", &VelocityWeakeningCoulomb::v_c, "m/s",
                                    "slip speed over which mu falls to mu_k", Range::positive(), Required::yes),
                      law_parameter("eps", &VelocityWeakeningCoulomb::eps, "m/s",
                                    "regularisation of the slip direction", Range::positive(), Required::yes)};
  }

  template <class S> void operator()(const S* r, int dim, const S& normal_pressure, S* out) const {
    using std::exp, std::sqrt;
    S speed2(0.0);
    for (int i = 0; i < dim; ++i) speed2 += r[i] * r[i];
    const S speed = sqrt(speed2 + 1e-300);  // smooth at r = 0, where the direction below is 0 anyway
    const S mu = mu_k + (mu_s - mu_k) * exp(-speed / v_c);
    const S pressure = normal_pressure < 0.0 ? -normal_pressure : normal_pressure;
    pc::regularized_direction(r, dim, eps, out);
    for (int i = 0; i < dim; ++i) out[i] *= mu * pressure;
  }
};

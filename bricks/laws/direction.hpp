#pragma once
// The direction term of isotropic friction laws, out = g(|r|) r / |r|, for any scalar (double or Dual):
//
//   scaled_direction(r, dim, [eps](const auto& rho) { using std::tanh; return tanh(rho / eps); }, out);
//
// g is the law's magnitude as a function of the speed rho = |r| >= 0, written generically in its scalar
// (it is called with S, and with Dual<1> for its slope at 0), with g(0) = 0 and finite values for every
// finite rho (write it so that it does not overflow, e.g. in eps / rho for rho > eps, as
// regularized_direction does). The helper takes care of the rest:
//  - |r| is computed from r / s with s = max_i |r_i|, so nothing is squared unscaled: no overflow for
//    components up to 1e300, no underflow down to 1e-300 (s is a constant factor: derivatives stay exact);
//  - at r = 0, where r / |r| has no limit, out = g'(0) r, the limit of g(|r|) r / |r|, whose derivative
//    g'(0) I is the derivative of the term at 0 (for g with g(0) = 0 and a right derivative at 0). The same
//    limit is taken where 1 / |r| would overflow (|r| below about 1e-308, subnormal components).
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "assembly/dual.hpp"

namespace pc {

template <class S, class Magnitude> void scaled_direction(const S* r, int dim, const Magnitude& g, S* out) {
  using std::sqrt;
  double s = 0;
  for (int i = 0; i < dim; ++i) s = std::max(s, std::abs(value_of(r[i])));
  if (!(1.0 / s <= std::numeric_limits<double>::max())) {  // r = 0 (or subnormal): the limit g'(0) r
    const double slope = g(Dual<1>::variable(0.0, 0)).d[0];
    for (int i = 0; i < dim; ++i) out[i] = slope * r[i];
    return;
  }
  S sum(0.0);
  for (int i = 0; i < dim; ++i) sum += (r[i] / s) * (r[i] / s);
  const S scaled_norm = sqrt(sum);  // |r| / s, in [1, sqrt(dim)]
  const S magnitude = g(s * scaled_norm);
  for (int i = 0; i < dim; ++i) out[i] = magnitude * ((r[i] / s) / scaled_norm);
}

// out = r / sqrt(|r|^2 + eps^2), the slip direction smoothed over a velocity eps: scaled_direction with
// g(rho) = rho / sqrt(rho^2 + eps^2), written in rho / eps below eps and in eps / rho above, so that
// neither side squares a large number (eps from 1e-300 to 1e300, |r| up to 1e300).
template <class S> void regularized_direction(const S* r, int dim, double eps, S* out) {
  scaled_direction(
      r, dim,
      [eps](const auto& rho) {
        using std::sqrt;
        using T = std::decay_t<decltype(rho)>;
        if (rho <= eps) {
          const T x = rho / eps;
          return T(x / sqrt(1.0 + x * x));
        }
        const T y = eps / rho;
        return T(1.0 / sqrt(1.0 + y * y));
      },
      out);
}

}  // namespace pc

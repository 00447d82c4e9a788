#pragma once
// Isotropic linear elasticity as a point-wise flux kernel (sigma = lambda tr(eps) I + 2 mu eps tested with
// grad w), its tangent left to Dual: the generic weak-form route to the term that ElasticityBrick
// assembles by hand. Tests compare the two routes with it, and the assembly benchmark times them.
#include "assembly/pointwise_term.hpp"

namespace pc {

struct ElasticFlux {
  double lambda = 1.2, mu = 0.8;
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    S trace = 0;
    for (int d = 0; d < in.dim; ++d) trace += in.grad[0][d][d];
    for (int i = 0; i < in.dim; ++i)
      for (int j = 0; j < in.dim; ++j)
        out.f1[0][i][j] = mu * (in.grad[0][i][j] + in.grad[0][j][i]) + (i == j ? lambda * trace : S(0));
  }
};

}  // namespace pc

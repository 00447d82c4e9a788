#pragma once
// Test support: smooth manufactured solutions known in closed form, with their gradients and the loads
// that produce them. u(x) = prod_d sin(a x_d + b_d), shifted so that boundary values are not zero.
#include <array>
#include <cmath>

namespace pc::testing {

struct SineProduct {
  int dim;
  double a = 1.3;
  std::array<double, 3> b{0.3, 0.7, 0.5};

  double s(const double* x, int d) const { return std::sin(a * x[d] + b[d]); }
  double c(const double* x, int d) const { return std::cos(a * x[d] + b[d]); }
  double value(const double* x) const {
    double v = 1;
    for (int d = 0; d < dim; ++d) v *= s(x, d);
    return v;
  }
  // d u / d x_i
  double gradient(const double* x, int i) const {
    double v = a;
    for (int d = 0; d < dim; ++d) v *= d == i ? c(x, d) : s(x, d);
    return v;
  }
  // d^2 u / d x_i d x_j
  double hessian(const double* x, int i, int j) const {
    if (i == j) return -a * a * value(x);
    double v = a * a;
    for (int d = 0; d < dim; ++d) v *= (d == i || d == j) ? c(x, d) : s(x, d);
    return v;
  }
  double laplacian(const double* x) const { return -dim * a * a * value(x); }
};

// Isotropic linear elasticity with every displacement component equal to a SineProduct u:
// f = -div sigma = -(mu lap u_i + (lambda + mu) d_i div u).
struct ElasticSine {
  SineProduct u;
  double lambda = 1.5, mu = 0.8;

  double body_force(const double* x, int i) const {
    double grad_div = 0;
    for (int j = 0; j < u.dim; ++j) grad_div += u.hessian(x, i, j);
    return -(mu * u.laplacian(x) + (lambda + mu) * grad_div);
  }
};

}  // namespace pc::testing

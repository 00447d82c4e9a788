#pragma once
// Error norms of a finite-element field against a function known in closed form, integrated with a rule
// of the given degree (by default 2 * order + 3, above the order so that the exact function is resolved).
#include <functional>

#include <Eigen/Core>

#include "assembly/fe_space.hpp"

namespace pc {

// exact(x, out): num_components values at x.
using PointFunction = std::function<void(const double* x, double* out)>;
// exact_gradient(x, out): out[c * dim + d] = d u_c / d x_d at x.
using PointGradient = std::function<void(const double* x, double* out)>;

// || u_h - u ||_{L2} over the space's domain (its cell region, or the whole mesh).
double l2_error(const FESpace& space, const Eigen::VectorXd& coefficients, const PointFunction& exact, int degree = -1);
// | u_h - u |_{H1} over the same domain (the seminorm: L2 norm of the gradient error).
double h1_seminorm_error(const FESpace& space, const Eigen::VectorXd& coefficients, const PointGradient& exact_gradient,
                         int degree = -1);

}  // namespace pc

#include "assembly/gmres.hpp"

#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "assembly/error.hpp"

namespace pc {

GmresResult gmres(const LinearOperator& apply_a, const LinearOperator& apply_preconditioner_inverse,
                  const Eigen::VectorXd& b, const GmresOptions& options) {
  require(options.restart >= 1 && options.max_iterations >= 1 && options.relative_tolerance >= 0,
          "gmres: restart and max_iterations must be >= 1 and the tolerance >= 0, got ", options.restart, ", ",
          options.max_iterations, ", ", options.relative_tolerance);
  GmresResult result;
  const long n = b.size();
  result.x = Eigen::VectorXd::Zero(n);
  const double b_norm = b.norm();
  if (b_norm == 0) {
    result.converged = true;
    return result;
  }
  const double target = options.relative_tolerance * b_norm;
  Eigen::VectorXd r = b;  // residual of the current x
  while (result.iterations < options.max_iterations) {
    const int m = std::min(options.restart, options.max_iterations - result.iterations);
    std::vector<Eigen::VectorXd> v;  // orthonormal basis of the Krylov space of A M^-1
    std::vector<Eigen::VectorXd> z;  // M^-1 v_j: the update is sum_j y_j z_j
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(m + 1, m);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(m + 1), cs = Eigen::VectorXd::Zero(m), sn = Eigen::VectorXd::Zero(m);
    const double beta = r.norm();
    g[0] = beta;
    v.push_back(r / beta);
    int k = 0;
    for (; k < m; ++k) {
      z.push_back(apply_preconditioner_inverse(v[k]));
      Eigen::VectorXd w = apply_a(z[k]);
      ++result.iterations;
      const double w_norm = w.norm();
      for (int i = 0; i <= k; ++i) {
        h(i, k) = v[i].dot(w);
        w -= h(i, k) * v[i];
      }
      // Cancellation lost most of w: orthogonalise once more (Kahan's "twice is enough").
      if (w.norm() < 0.5 * w_norm)
        for (int i = 0; i <= k; ++i) {
          const double c = v[i].dot(w);
          h(i, k) += c;
          w -= c * v[i];
        }
      h(k + 1, k) = w.norm();
      for (int i = 0; i < k; ++i) {  // earlier rotations on the new column
        const double t = cs[i] * h(i, k) + sn[i] * h(i + 1, k);
        h(i + 1, k) = -sn[i] * h(i, k) + cs[i] * h(i + 1, k);
        h(i, k) = t;
      }
      const double rho = std::hypot(h(k, k), h(k + 1, k));
      if (rho == 0) break;  // A M^-1 singular on this space: keep the columns before it
      cs[k] = h(k, k) / rho;
      sn[k] = h(k + 1, k) / rho;
      h(k, k) = rho;
      h(k + 1, k) = 0;
      g[k + 1] = -sn[k] * g[k];
      g[k] = cs[k] * g[k];
      // w = 0: the space is invariant and holds the solution (a "lucky" breakdown).
      if (std::abs(g[k + 1]) <= target || w.norm() == 0) {
        ++k;
        break;
      }
      v.push_back(w / w.norm());
    }
    // x += Z y with H y = g on the k columns built.
    const Eigen::VectorXd y = h.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
    for (int j = 0; j < k; ++j) result.x += y[j] * z[j];
    r = b - apply_a(result.x);
    result.relative_residual = r.norm() / b_norm;
    if (r.norm() <= target) {
      result.converged = true;
      break;
    }
    if (!std::isfinite(result.relative_residual)) break;
  }
  return result;
}

}  // namespace pc

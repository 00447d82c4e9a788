#include "assembly/norms.hpp"

#include <cmath>
#include <vector>

#include "assembly/error.hpp"
#include "assembly/region_geometry.hpp"

namespace pc {
namespace {

// Integrates sum |u_h - u|^2 (values, or gradients) over the cells of the space.
double squared_error(const FESpace& space, const Eigen::VectorXd& u, const PointFunction& exact, int degree,
                     bool gradients) {
  require(u.size() == space.num_dofs(), "error norm: coefficient vector has ", u.size(), " entries, the space has ",
          space.num_dofs(), " dofs");
  const Mesh& mesh = space.mesh();
  const RegionGeometry geometry(mesh, "all", degree >= 0 ? degree : 2 * space.order() + 3);
  const ReferenceElement& element = space.element();
  const int dim = mesh.dim(), nc = space.num_components(), n = element.num_dofs();
  const int width = gradients ? nc * dim : nc;
  std::vector<double> N(n), dN_ref(n * dim), uh(width), ue(width);
  double sum = 0;
  for (int e = 0; e < geometry.num_elements(); ++e) {
    const int cell = geometry.cell(e);
    if (!space.has_cell(cell)) continue;
    const auto dofs = space.cell_scalar_dofs(cell);
    for (int q = 0; q < geometry.num_points(); ++q) {
      const double* xi = geometry.reference_points(-1)[q].data();
      std::fill(uh.begin(), uh.end(), 0.0);
      if (gradients) {
        element.gradients(xi, dN_ref.data());
        const double* G = geometry.inverse_jacobian_t(e, q);
        for (int i = 0; i < n; ++i)
          for (int d = 0; d < dim; ++d) {
            double g = 0;
            for (int k = 0; k < dim; ++k) g += G[d * dim + k] * dN_ref[i * dim + k];
            for (int c = 0; c < nc; ++c) uh[c * dim + d] += g * u[space.dof(dofs[i], c)];
          }
      } else {
        element.values(xi, N.data());
        for (int i = 0; i < n; ++i)
          for (int c = 0; c < nc; ++c) uh[c] += N[i] * u[space.dof(dofs[i], c)];
      }
      exact(geometry.point(e, q).data(), ue.data());
      double local = 0;
      for (int a = 0; a < width; ++a) local += (uh[a] - ue[a]) * (uh[a] - ue[a]);
      sum += geometry.weight(e, q) * local;
    }
  }
  return sum;
}

}  // namespace

double l2_error(const FESpace& space, const Eigen::VectorXd& coefficients, const PointFunction& exact, int degree) {
  return std::sqrt(squared_error(space, coefficients, exact, degree, false));
}

double h1_seminorm_error(const FESpace& space, const Eigen::VectorXd& coefficients, const PointGradient& exact_gradient,
                         int degree) {
  return std::sqrt(squared_error(space, coefficients, exact_gradient, degree, true));
}

}  // namespace pc

#pragma once
// Test support: nonlinear point-wise terms whose every tangent entry is a sum of element contributions
// that depend on the values, and their assembly over a region (or over the region's elements of some
// cells): the residual and the tangent block of one element loop.
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "assembly/pointwise_term.hpp"
#include "assembly/term_assembly.hpp"

namespace pc::testing {

// A nonlinear diffusion-reaction on a vector field: f1 = (1 + |u|^2) grad u, f0 = u_0^3.
struct NonlinearDiffusion {
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    S size = S(1);
    for (int c = 0; c < in.dim; ++c) size += in.value[0][c] * in.value[0][c];
    for (int c = 0; c < in.dim; ++c) {
      for (int d = 0; d < in.dim; ++d) out.f1[0][c][d] = size * in.grad[0][c][d];
      out.f0[0][c] = in.value[0][0] * in.value[0][0] * in.value[0][0];
    }
  }
};

// A face reaction u_c^2 n_c.
struct FaceReaction {
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    for (int c = 0; c < in.dim; ++c) out.f0[0][c] = in.value[0][c] * in.value[0][c] * in.normal[c];
  }
};

// The residual and the tangent block of the kernel's term over the region (only the elements of the
// flagged cells, if `owned` is not empty), at u = a ramp from -0.7 to 1.3 over the dofs.
template <class Kernel>
std::pair<Eigen::VectorXd, CsrMatrix> assembled_term(const FESpace& space, Integration integration,
                                                     const std::string& region, std::span<const char> owned = {}) {
  auto term = std::make_shared<PointwiseTerm<Kernel>>("t", integration,
                                                      std::vector<FieldUse>{{"u", integration == Integration::Cells}},
                                                      std::vector<int>{0}, std::vector<Coupling>{{0, 0}}, Kernel{});
  auto geometry =
      std::make_shared<const RegionGeometry>(space.mesh(), region, term->quadrature_degree(space.order()), owned);
  TermAssembly assembly(term, geometry, {&space});
  const Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(space.num_dofs(), -0.7, 1.3);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(space.num_dofs());
  const Eigen::VectorXd* values[] = {&u};
  Eigen::VectorXd* residuals[] = {&r};
  assembly.assemble(values, 0.0, residuals, true);
  return {r, assembly.block(0)};
}

}  // namespace pc::testing

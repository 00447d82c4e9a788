// Manufactured solutions with measured convergence rates: Poisson and linear elasticity, 2D and 3D,
// P1, P2 and Q1. Each problem is solved on four meshes; the last two observed rates in L2 and in the H1
// seminorm must lie within 0.15 of the theory (p + 1 and p). The kernels are point-wise flux forms, so
// every tangent here comes from Dual numbers through the generic weak form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "assembly/mesh_generators.hpp"
#include "assembly/norms.hpp"
#include "assembly/pointwise_term.hpp"
#include "support/manufactured.hpp"
#include "support/single_field_problem.hpp"

namespace pc {
namespace {

using testing::ElasticSine;
using testing::SineProduct;

// -lap u = f:  f0 = -f, f1 = grad u.
struct PoissonKernel {
  SineProduct exact;
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    out.f0[0][0] = exact.laplacian(in.x);
    for (int d = 0; d < in.dim; ++d) out.f1[0][0][d] = in.grad[0][0][d];
  }
};

// -div sigma(u) = f:  f0 = -f, f1 = sigma = lambda tr(eps) I + 2 mu eps.
struct ElasticityKernel {
  ElasticSine exact;
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    const int dim = in.dim;
    S trace = 0;
    for (int d = 0; d < dim; ++d) trace += in.grad[0][d][d];
    for (int i = 0; i < dim; ++i) {
      out.f0[0][i] = -exact.body_force(in.x, i);
      for (int j = 0; j < dim; ++j)
        out.f1[0][i][j] = exact.mu * (in.grad[0][i][j] + in.grad[0][j][i]) + (i == j ? exact.lambda * trace : S(0));
    }
  }
};

struct Errors {
  double h, l2, h1;
};

Mesh make_mesh(int dim, Shape shape, int n) {
  if (dim == 2) return rectangle_mesh({0, 0}, {1, 1}, n, n, shape);
  return box_mesh({0, 0, 0}, {1, 1, 1}, n, n, n, shape);
}

template <class Kernel>
Errors solve(int dim, Shape shape, int order, int n, int components, const Kernel& kernel, const SineProduct& u) {
  auto mesh = std::make_shared<const Mesh>(make_mesh(dim, shape, n));
  FESpace space(mesh, order, components);
  auto term =
      std::make_shared<PointwiseTerm<Kernel>>("operator", Integration::Cells, std::vector<FieldUse>{{"u", true}},
                                              std::vector<int>{0}, std::vector<Coupling>{{0, 0}}, kernel, 2);
  auto exact = [&](const double* x, double* out) {
    for (int c = 0; c < components; ++c) out[c] = u.value(x);
  };
  auto exact_gradient = [&](const double* x, double* out) {
    for (int c = 0; c < components; ++c)
      for (int d = 0; d < dim; ++d) out[c * dim + d] = u.gradient(x, d);
  };
  Eigen::VectorXd guess = space.interpolate(exact);
  const std::vector<int> boundary = space.dofs_on("boundary");
  Eigen::VectorXd initial = Eigen::VectorXd::Zero(space.num_dofs());
  for (int d : boundary) initial[d] = guess[d];
  testing::SingleFieldProblem problem{space, {term}, {"all"}, boundary};
  const Eigen::VectorXd uh = problem.solve(initial);
  return {1.0 / n, l2_error(space, uh, exact), h1_seminorm_error(space, uh, exact_gradient)};
}

void expect_rates(const std::vector<Errors>& e, double l2_rate, double h1_rate, const std::string& what) {
  for (size_t k = e.size() - 2; k < e.size(); ++k) {
    const double ratio = std::log(e[k - 1].h / e[k].h);
    const double observed_l2 = std::log(e[k - 1].l2 / e[k].l2) / ratio;
    const double observed_h1 = std::log(e[k - 1].h1 / e[k].h1) / ratio;
    EXPECT_NEAR(observed_l2, l2_rate, 0.15) << what << ": L2 rate between h = " << e[k - 1].h << " and " << e[k].h;
    EXPECT_NEAR(observed_h1, h1_rate, 0.15) << what << ": H1 rate between h = " << e[k - 1].h << " and " << e[k].h;
    std::printf("%s: h %.4g -> %.4g  L2 rate %.3f  H1 rate %.3f\n", what.c_str(), e[k - 1].h, e[k].h, observed_l2,
                observed_h1);
  }
}

struct Case {
  const char* name;
  int dim;
  Shape shape;
  int order;
  std::vector<int> sizes;
};

class Poisson : public ::testing::TestWithParam<Case> {};
class Elasticity : public ::testing::TestWithParam<Case> {};

TEST_P(Poisson, ConvergesAtTheoreticalRates) {
  const Case& c = GetParam();
  const SineProduct u{c.dim};
  std::vector<Errors> errors;
  for (int n : c.sizes) errors.push_back(solve(c.dim, c.shape, c.order, n, 1, PoissonKernel{u}, u));
  expect_rates(errors, c.order + 1, c.order, c.name);
}

TEST_P(Elasticity, ConvergesAtTheoreticalRates) {
  const Case& c = GetParam();
  const ElasticSine load{SineProduct{c.dim}};
  std::vector<Errors> errors;
  for (int n : c.sizes) errors.push_back(solve(c.dim, c.shape, c.order, n, c.dim, ElasticityKernel{load}, load.u));
  expect_rates(errors, c.order + 1, c.order, c.name);
}

const Case kPoissonCases[] = {
    {"P1_triangles", 2, Shape::Triangle, 1, {8, 16, 32, 64}},  {"P2_triangles", 2, Shape::Triangle, 2, {4, 8, 16, 32}},
    {"Q1_quads", 2, Shape::Quadrilateral, 1, {8, 16, 32, 64}}, {"Q2_quads", 2, Shape::Quadrilateral, 2, {4, 8, 16, 32}},
    {"P1_tets", 3, Shape::Tetrahedron, 1, {4, 8, 12, 16}},     {"P2_tets", 3, Shape::Tetrahedron, 2, {2, 4, 6, 8}},
    {"Q1_hexes", 3, Shape::Hexahedron, 1, {4, 8, 12, 16}},
};
const Case kElasticityCases[] = {
    {"P1_triangles", 2, Shape::Triangle, 1, {8, 16, 32, 64}},  {"P2_triangles", 2, Shape::Triangle, 2, {4, 8, 16, 32}},
    {"Q1_quads", 2, Shape::Quadrilateral, 1, {8, 16, 32, 64}}, {"P1_tets", 3, Shape::Tetrahedron, 1, {4, 8, 12, 16}},
    {"P2_tets", 3, Shape::Tetrahedron, 2, {2, 4, 6, 8}},       {"Q1_hexes", 3, Shape::Hexahedron, 1, {4, 6, 8, 12}},
};

std::string case_name(const ::testing::TestParamInfo<Case>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Engine, Poisson, ::testing::ValuesIn(kPoissonCases), case_name);
INSTANTIATE_TEST_SUITE_P(Engine, Elasticity, ::testing::ValuesIn(kElasticityCases), case_name);

}  // namespace
}  // namespace pc

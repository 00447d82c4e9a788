// The forward-mode AD type: derivatives of elementary functions against closed forms, and the tangent the
// generic weak form derives with it against (a) a hand-written tangent of the same linear term and (b)
// finite differences of the residual of a nonlinear term.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "assembly/dual.hpp"
#include "assembly/mesh_generators.hpp"
#include "assembly/pointwise_term.hpp"
#include "assembly/term_assembly.hpp"
#include "bricks/elastic_flux_kernel.hpp"

namespace pc {
namespace {

using D = Dual<2>;

TEST(Dual, ElementaryDerivativesMatchClosedForms) {
  const double x0 = 0.7, y0 = 1.9;
  const D x = D::variable(x0, 0), y = D::variable(y0, 1);
  const D f = x * y + sin(x) / y - exp(x * 0.5) + sqrt(y) * log(y) + pow(x, 3.0) - tanh(y);
  EXPECT_NEAR(
      f.v,
      x0 * y0 + std::sin(x0) / y0 - std::exp(0.5 * x0) + std::sqrt(y0) * std::log(y0) + x0 * x0 * x0 - std::tanh(y0),
      1e-15);
  EXPECT_NEAR(f.d[0], y0 + std::cos(x0) / y0 - 0.5 * std::exp(0.5 * x0) + 3 * x0 * x0, 1e-14);
  const double t = std::tanh(y0);
  EXPECT_NEAR(f.d[1],
              x0 - std::sin(x0) / (y0 * y0) + (0.5 / std::sqrt(y0)) * std::log(y0) + std::sqrt(y0) / y0 - (1 - t * t),
              1e-14);
}

TEST(Dual, KinksTakeTheDocumentedOneSidedDerivative) {
  const D zero = D::variable(0.0, 0);
  EXPECT_EQ(abs(zero).d[0], 0.0);
  EXPECT_EQ(pow(zero, 2.0).d[0], 0.0);
  EXPECT_EQ(max(zero, D(0.0)).d[0], 1.0);  // ties keep the first argument
  EXPECT_EQ(max(D(0.0), zero).d[0], 0.0);
  EXPECT_EQ(sqrt(zero).d[0], 0.0);
  EXPECT_TRUE(std::isfinite(sqrt(zero).d[0]));
}

// Isotropic elasticity written as a flux kernel (bricks/elastic_flux_kernel.hpp: tangent from Dual) and by hand: K_ij =
// sum_q w (lambda div N_i div N_j + mu (grad N_i : grad N_j + grad N_i : grad N_j^T)).
class HandElasticity : public Term {
 public:
  HandElasticity(double lambda, double mu)
      : Term("hand elasticity", Integration::Cells, {{"u", true}}, {0}, {{0, 0}}), lambda_(lambda), mu_(mu) {}
  void assemble(const ElementData& e, LocalSystem& local, bool, bool want_tangent) const override {
    if (!want_tangent) return;
    const auto& f = e.fields[0];
    const int dim = e.dim;
    for (int q = 0; q < e.num_points; ++q)
      for (int i = 0; i < f.num_shapes; ++i)
        for (int j = 0; j < f.num_shapes; ++j) {
          const double* a = f.shape_grad(q, i, dim);
          const double* b = f.shape_grad(q, j, dim);
          double dot = 0;
          for (int d = 0; d < dim; ++d) dot += a[d] * b[d];
          for (int ci = 0; ci < dim; ++ci)
            for (int cj = 0; cj < dim; ++cj)
              local.tangent[0](i * dim + ci, j * dim + cj) +=
                  e.weights[q] * (lambda_ * a[ci] * b[cj] + mu_ * a[cj] * b[ci] + (ci == cj ? mu_ * dot : 0.0));
        }
  }

 private:
  double lambda_, mu_;
};

TEST(Dual, GenericTangentEqualsHandWrittenElasticity) {
  for (Shape shape : {Shape::Triangle, Shape::Quadrilateral, Shape::Tetrahedron, Shape::Hexahedron}) {
    const bool is3d = dimension(shape) == 3;
    auto mesh = std::make_shared<const Mesh>(is3d ? box_mesh({0, 0, 0}, {1, 2, 1}, 2, 2, 2, shape)
                                                  : rectangle_mesh({0, 0}, {1, 2}, 3, 2, shape));
    FESpace space(mesh, 2, mesh->dim());
    auto generic = std::make_shared<PointwiseTerm<ElasticFlux>>("ad", Integration::Cells,
                                                                std::vector<FieldUse>{{"u", true}}, std::vector<int>{0},
                                                                std::vector<Coupling>{{0, 0}}, ElasticFlux{1.7, 0.6});
    auto hand = std::make_shared<HandElasticity>(1.7, 0.6);
    TermAssembly a(generic, "all", {&space}), b(hand, "all", {&space});
    const Eigen::VectorXd u = Eigen::VectorXd::Random(space.num_dofs());
    const Eigen::VectorXd* values[] = {&u};
    Eigen::VectorXd* none[] = {nullptr};
    a.assemble(values, 0, none, true);
    b.assemble(values, 0, none, true);
    const double scale = Eigen::MatrixXd(a.block(0)).norm();
    EXPECT_LT(Eigen::MatrixXd(a.block(0) - b.block(0)).norm(), 1e-13 * scale) << to_string(shape);
  }
}

// A nonlinear diffusion-reaction pair of fields: f0_u = u^3 + u p, f1_u = (1 + u^2) grad u, f0_p = sin(u) p.
struct Nonlinear {
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    using std::sin;
    const S u = in.value[0][0], p = in.value[1][0];
    out.f0[0][0] = u * u * u + u * p;
    for (int d = 0; d < in.dim; ++d) out.f1[0][0][d] = (1.0 + u * u) * in.grad[0][0][d];
    out.f0[1][0] = sin(u) * p;
  }
};

TEST(Dual, GenericTangentMatchesFiniteDifferences) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 3, 3, Shape::Triangle));
  FESpace su(mesh, 2, 1), sp(mesh, 1, 1);
  auto term = std::make_shared<PointwiseTerm<Nonlinear>>(
      "nonlinear", Integration::Cells, std::vector<FieldUse>{{"u", true}, {"p", false}}, std::vector<int>{0, 1},
      std::vector<Coupling>{{0, 0}, {0, 1}, {1, 0}, {1, 1}}, Nonlinear{});
  TermAssembly assembly(term, "all", {&su, &sp});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Eigen::VectorXd u(su.num_dofs()), p(sp.num_dofs());
  for (auto& x : u) x = uniform(rng);
  for (auto& x : p) x = uniform(rng);
  auto residual = [&](const Eigen::VectorXd& uu, const Eigen::VectorXd& pp) {
    Eigen::VectorXd ru = Eigen::VectorXd::Zero(su.num_dofs()), rp = Eigen::VectorXd::Zero(sp.num_dofs());
    const Eigen::VectorXd* values[] = {&uu, &pp};
    Eigen::VectorXd* residuals[] = {&ru, &rp};
    assembly.assemble(values, 0, residuals, false);
    return std::make_pair(ru, rp);
  };
  const Eigen::VectorXd* values[] = {&u, &p};
  Eigen::VectorXd* none[] = {nullptr, nullptr};
  assembly.assemble(values, 0, none, true);
  const Eigen::MatrixXd K[2][2] = {{assembly.block(0), assembly.block(1)}, {assembly.block(2), assembly.block(3)}};
  const double h = 1e-6;
  for (int trial = 0; trial < 2; ++trial) {
    const int n = trial == 0 ? su.num_dofs() : sp.num_dofs();
    for (int j = 0; j < n; j += 3) {
      Eigen::VectorXd up = u, um = u, pp = p, pm = p;
      (trial == 0 ? up : pp)[j] += h;
      (trial == 0 ? um : pm)[j] -= h;
      const auto plus = residual(up, pp), minus = residual(um, pm);
      const Eigen::VectorXd fd_u = (plus.first - minus.first) / (2 * h);
      const Eigen::VectorXd fd_p = (plus.second - minus.second) / (2 * h);
      EXPECT_LT((K[0][trial].col(j) - fd_u).norm(), 1e-7 * (1 + fd_u.norm())) << "trial " << trial << " col " << j;
      EXPECT_LT((K[1][trial].col(j) - fd_p).norm(), 1e-7 * (1 + fd_p.norm())) << "trial " << trial << " col " << j;
    }
  }
}

}  // namespace
}  // namespace pc

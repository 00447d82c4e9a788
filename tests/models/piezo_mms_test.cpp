// Manufactured solutions of the coupled piezoelectric problem assembled from bricks in a Model:
//  - static (no inertia, no viscosity): -div sigma = f0, div D = q0 with sigma = B eps(u) + E^T grad phi,
//    D = E eps(u) - beta grad phi, solved as one backward Euler step of size 1 from u = 0 (so u = v);
//    measured L2 and H1 rates of u and phi for P1 and P2 (theory p + 1 and p, within 0.15);
//  - in time: rho u'' - div(A eps(u') + B eps(u) + E^T grad phi) = f0 with u = g(t) s(x): backward Euler's
//    error at T is first order in k (measured rate within 0.15 of 1).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "assembly/mesh_generators.hpp"
#include "assembly/norms.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/elasticity_brick.hpp"
#include "bricks/inertia_brick.hpp"
#include "bricks/permittivity_brick.hpp"
#include "bricks/piezoelectric_brick.hpp"
#include "bricks/source_bricks.hpp"
#include "bricks/viscosity_brick.hpp"
#include "models/model.hpp"
#include "models/newton.hpp"
#include "models/stepper.hpp"
#include "models/time_scheme.hpp"
#include "support/manufactured.hpp"
#include "support/piezo_material.hpp"

namespace pc {
namespace {

using testing::PiezoTensors;
using testing::SineProduct;
using testing::voigt_index_2d;

// Exact fields: u_i(x, t) = g(t) U_i s(x), phi(x, t) = g(t) P s(x), with s a shifted sine product.
struct Exact {
  SineProduct s{2};
  double U[2] = {1.0, -0.7};
  double P = 0.8;
  PiezoTensors m = testing::scaled_pzt5h();

  // -div(C eps(w) + E^T grad(chi)) for w_i = U_i s, chi = P s (per unit g).
  double minus_div_stress(const double* x, int i, const Eigen::MatrixXd& C, bool with_piezo) const {
    double div = 0;
    for (int j = 0; j < 2; ++j) {
      for (int k = 0; k < 2; ++k)
        for (int l = 0; l < 2; ++l) div += C(voigt_index_2d(i, j), voigt_index_2d(k, l)) * U[k] * s.hessian(x, j, l);
      if (with_piezo)
        for (int k = 0; k < 2; ++k) div += m.E(k, voigt_index_2d(i, j)) * P * s.hessian(x, j, k);
    }
    return -div;
  }
  // div D for D = E eps(w) - beta grad chi (per unit g).
  double div_displacement(const double* x) const {
    double div = 0;
    for (int k = 0; k < 2; ++k)
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) div += m.E(k, voigt_index_2d(i, j)) * U[i] * s.hessian(x, k, j);
    for (int k = 0; k < 2; ++k)
      for (int l = 0; l < 2; ++l) div -= m.beta(k, l) * P * s.hessian(x, k, l);
    return div;
  }
};

struct PiezoProblem {
  std::unique_ptr<Model> model;
  std::unique_ptr<BackwardEuler> scheme;
};

// Stacks the bulk bricks; with_dynamics adds inertia (rho) and viscosity (A).
PiezoProblem build(std::shared_ptr<const Mesh> mesh, int order, const Exact& exact, bool with_dynamics,
            std::function<double(double)> g, std::function<double(double)> g_dot, std::function<double(double)> g_ddot) {
  PiezoProblem s;
  s.model = std::make_unique<Model>(mesh);
  Model& m = *s.model;
  m.add_unknown("v", std::make_shared<const FESpace>(mesh, order, 2));
  m.add_unknown("phi", std::make_shared<const FESpace>(mesh, order, 1));
  s.scheme = std::make_unique<BackwardEuler>();
  s.scheme->attach(m, with_dynamics);
  m.set_constant("B", exact.m.B);
  m.set_constant("E", exact.m.E);
  m.set_constant("beta", exact.m.beta);
  m.add_brick(std::make_shared<ElasticityBrick>());
  m.add_brick(std::make_shared<PiezoelectricCouplingBrick>());
  m.add_brick(std::make_shared<PermittivityBrick>());
  const double rho = 1.3;
  if (with_dynamics) {
    m.set_constant("rho", rho);
    m.set_constant("A", exact.m.A);
    m.add_brick(std::make_shared<InertiaBrick>());
    m.add_brick(std::make_shared<ViscosityBrick>());
  }
  m.add_brick(std::make_shared<BodyForceBrick>(
      [=](const double* x, double t, double* out) {
        for (int i = 0; i < 2; ++i) {
          out[i] = g(t) * exact.minus_div_stress(x, i, exact.m.B, true);
          if (with_dynamics)
            out[i] += rho * g_ddot(t) * exact.U[i] * exact.s.value(x) +
                      g_dot(t) * exact.minus_div_stress(x, i, exact.m.A, false);
        }
      },
      LoadTime::Varying));
  m.add_brick(std::make_shared<VolumeChargeBrick>(
      [=](const double* x, double t, double* out) { out[0] = g(t) * exact.div_displacement(x); }, LoadTime::Varying));
  m.add_brick(std::make_shared<DirichletBrick>(
      "v", "boundary", std::vector<int>{},
      [=](const double* x, double t, double* out) {
        for (int i = 0; i < 2; ++i) out[i] = g_dot(t) * exact.U[i] * exact.s.value(x);
      },
      true));
  m.add_brick(std::make_shared<DirichletBrick>(
      "phi", "boundary", std::vector<int>{},
      [=](const double* x, double t, double* out) { out[0] = g(t) * exact.P * exact.s.value(x); }, true));
  m.finalize();
  return s;
}

struct FieldErrors {
  double u_l2, u_h1, phi_l2, phi_h1;
};

FieldErrors errors_at(const Model& m, const Exact& exact, double gT) {
  auto u = [&](const double* x, double* out) {
    for (int i = 0; i < 2; ++i) out[i] = gT * exact.U[i] * exact.s.value(x);
  };
  auto grad_u = [&](const double* x, double* out) {
    for (int i = 0; i < 2; ++i)
      for (int d = 0; d < 2; ++d) out[i * 2 + d] = gT * exact.U[i] * exact.s.gradient(x, d);
  };
  auto phi = [&](const double* x, double* out) { out[0] = gT * exact.P * exact.s.value(x); };
  auto grad_phi = [&](const double* x, double* out) {
    for (int d = 0; d < 2; ++d) out[d] = gT * exact.P * exact.s.gradient(x, d);
  };
  return {l2_error(m.space("u"), m.values("u"), u), h1_seminorm_error(m.space("u"), m.values("u"), grad_u),
          l2_error(m.space("phi"), m.values("phi"), phi), h1_seminorm_error(m.space("phi"), m.values("phi"), grad_phi)};
}

double rate(double coarse, double fine, double ratio) { return std::log(coarse / fine) / std::log(ratio); }

class StaticPiezo : public ::testing::TestWithParam<int> {};

TEST_P(StaticPiezo, CoupledFieldsConvergeAtTheoreticalRates) {
  const int order = GetParam();
  const Exact exact;
  std::vector<FieldErrors> e;
  const std::vector<int> sizes = order == 1 ? std::vector<int>{8, 16, 32, 64} : std::vector<int>{4, 8, 16, 32};
  auto one = [](double) { return 1.0; };
  auto zero = [](double) { return 0.0; };
  for (int n : sizes) {
    auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, n, n, Shape::Triangle));
    // One backward Euler step of size 1 from u_prev = 0: u = v, and the Dirichlet value of v is u.
    PiezoProblem s = build(mesh, order, exact, false, one, one, zero);
    StepperOptions options;
    options.start = 0;
    options.end = 1;
    options.step = 1;
    options.initial_potential = false;
    NewtonSolver newton;
    const RunSummary run = Stepper(options).run(*s.model, *s.scheme, newton);
    ASSERT_TRUE(run.completed) << run.message;
    EXPECT_EQ(run.newton_iterations_max_per_step, 1) << "a linear model converges in one Newton iteration";
    e.push_back(errors_at(*s.model, exact, 1.0));
  }
  for (size_t k = e.size() - 2; k < e.size(); ++k) {
    const double r[4] = {rate(e[k - 1].u_l2, e[k].u_l2, 2), rate(e[k - 1].u_h1, e[k].u_h1, 2),
                         rate(e[k - 1].phi_l2, e[k].phi_l2, 2), rate(e[k - 1].phi_h1, e[k].phi_h1, 2)};
    std::printf("P%d n=%d: rates u L2 %.3f H1 %.3f, phi L2 %.3f H1 %.3f\n", order, sizes[k], r[0], r[1], r[2], r[3]);
    EXPECT_NEAR(r[0], order + 1, 0.15);
    EXPECT_NEAR(r[1], order, 0.15);
    EXPECT_NEAR(r[2], order + 1, 0.15);
    EXPECT_NEAR(r[3], order, 0.15);
  }
}

INSTANTIATE_TEST_SUITE_P(Bricks, StaticPiezo, ::testing::Values(1, 2));

TEST(DynamicPiezo, BackwardEulerIsFirstOrderInTime) {
  const Exact exact;
  auto g = [](double t) { return std::sin(2 * t); };
  auto g_dot = [](double t) { return 2 * std::cos(2 * t); };
  auto g_ddot = [](double t) { return -4 * std::sin(2 * t); };
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 6, 6, Shape::Triangle));
  const double T = 1.0;
  std::vector<double> errors;
  const std::vector<int> steps = {8, 16, 32, 64};
  for (int n : steps) {
    PiezoProblem s = build(mesh, 2, exact, true, g, g_dot, g_ddot);
    // Exact initial state: u(0) = 0, v(0) = g'(0) U s.
    Eigen::VectorXd v0 = s.model->space("v").interpolate([&](const double* x, double* out) {
      for (int i = 0; i < 2; ++i) out[i] = g_dot(0) * exact.U[i] * exact.s.value(x);
    });
    s.scheme->set_initial_state(*s.model, Eigen::VectorXd::Zero(v0.size()), v0);
    StepperOptions options;
    options.end = T;
    options.step = T / n;
    options.prediction = Prediction::Previous;
    NewtonSolver newton;
    const RunSummary run = Stepper(options).run(*s.model, *s.scheme, newton);
    ASSERT_TRUE(run.completed) << run.message;
    errors.push_back(errors_at(*s.model, exact, g(T)).u_l2);
  }
  for (size_t k = 2; k < errors.size(); ++k) {
    const double r = rate(errors[k - 1], errors[k], 2);
    std::printf("backward Euler: %d -> %d steps, error %.3e -> %.3e, rate %.3f\n", steps[k - 1], steps[k],
                errors[k - 1], errors[k], r);
    EXPECT_NEAR(r, 1.0, 0.15);
  }
}

}  // namespace
}  // namespace pc

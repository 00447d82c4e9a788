// Contact physics against closed forms and exact discrete identities, on models stacked from bricks:
//  1. a column on a compliant foundation (normal compliance, m = 1 and m = 2) under a uniform pressure:
//     the exact solution is linear in y, so P1/Q1 reproduce it to round-off;
//  2. the same column on a damped foundation (p = c_nu v_n+): it sinks at the speed P / c_nu, and
//     backward Euler is exact for a constant velocity;
//  3. the discrete energy identity of backward Euler with inertia, viscosity, elasticity and dissipative
//     contact laws (damped normal response, viscous and regularized Tresca friction), every step;
//  4. the conductive foundation alone: the 1D potential of a strip between a grounded top and a foundation
//     at phi_f, and its limits k_e -> infinity (phi = phi_f) and k_e = 0 (insulated);
//  5. the same linear friction law through the Model's cached path (FrictionBrick, linear) and through the
//     generic nonlinear brick (WeakFormBrick): identical residuals and Jacobians.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "assembly/mesh_generators.hpp"
#include "assembly/term_assembly.hpp"
#include "bricks/conductive_foundation_brick.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/elasticity_brick.hpp"
#include "bricks/friction_brick.hpp"
#include "bricks/inertia_brick.hpp"
#include "bricks/laws/foundation_laws.hpp"
#include "bricks/laws/friction_laws.hpp"
#include "bricks/laws/normal_laws.hpp"
#include "bricks/normal_response_brick.hpp"
#include "bricks/permittivity_brick.hpp"
#include "bricks/source_bricks.hpp"
#include "bricks/viscosity_brick.hpp"
#include "bricks/voigt.hpp"
#include "bricks/weak_form_brick.hpp"
#include "models/model.hpp"
#include "models/solvers/newton.hpp"
#include "models/stepper.hpp"
#include "models/time_scheme.hpp"

namespace pc {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ---- helpers ------------------------------------------------------------------------------------------

// The values of the brick's fields in the model, or zeros.
std::vector<Eigen::VectorXd> brick_field_values(const Model& model, const Term& term, bool zeros) {
  std::vector<Eigen::VectorXd> values;
  for (const FieldUse& use : term.fields())
    values.push_back(zeros ? Eigen::VectorXd::Zero(model.space(use.name).num_dofs()) : model.values(use.name));
  return values;
}

std::vector<const FESpace*> brick_spaces(const Model& model, const Term& term) {
  std::vector<const FESpace*> spaces;
  for (const FieldUse& use : term.fields()) spaces.push_back(&model.space(use.name));
  return spaces;
}

// The tangent block of a linear brick's single term and single coupling, assembled alone (all dofs,
// constrained ones included): the mass matrix of the inertia brick (v, a), the viscous matrix (v, v),
// the stiffness (v, u).
CsrMatrix brick_matrix(const Model& model, const Brick& brick) {
  const auto terms = brick.terms();
  EXPECT_EQ(terms.size(), 1u) << brick.name();
  const BrickTerm& bt = terms.front();
  EXPECT_EQ(bt.term->couplings().size(), 1u) << brick.name();
  TermAssembly assembly(bt.term, bt.region, brick_spaces(model, *bt.term));
  const auto values = brick_field_values(model, *bt.term, true);
  std::vector<const Eigen::VectorXd*> pointers;
  for (const auto& v : values) pointers.push_back(&v);
  std::vector<Eigen::VectorXd*> outputs(bt.term->tests().size(), nullptr);
  assembly.assemble(pointers, model.time(), outputs, true);
  return assembly.block(0);
}

// The residual of a brick alone at the model's current values, in the numbering of its test field
// `unknown` (all dofs).
class BrickResidual {
 public:
  BrickResidual(const Model& model, const Brick& brick, std::string unknown) : unknown_(std::move(unknown)) {
    for (const BrickTerm& bt : brick.terms())
      assemblies_.push_back(std::make_unique<TermAssembly>(bt.term, bt.region, brick_spaces(model, *bt.term)));
  }
  Eigen::VectorXd operator()(const Model& model) {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(model.space(unknown_).num_dofs());
    for (auto& a : assemblies_) {
      const Term& term = a->term();
      const auto values = brick_field_values(model, term, false);
      std::vector<const Eigen::VectorXd*> pointers;
      for (const auto& v : values) pointers.push_back(&v);
      std::vector<Eigen::VectorXd*> outputs;
      for (int t : term.tests()) outputs.push_back(term.fields()[t].name == unknown_ ? &r : nullptr);
      a->assemble(pointers, model.time(), outputs, false);
    }
    return r;
  }

 private:
  std::string unknown_;
  std::vector<std::unique_ptr<TermAssembly>> assemblies_;
};

// ---- 1. compression column on a compliant foundation ----------------------------------------------------
//
// (0, W) x (0, H), plane strain with Young's modulus E and Poisson's ratio nu, sides free (a roller
// v_x = 0 on x = 0 removes the horizontal rigid motion), pressure P on top, the bottom on a foundation
// p_nu = c (u_nu)_+^m with outward normal (0, -1), so u_nu = -u_y. The uniaxial stress state
// sigma_yy = -P, sigma_xx = sigma_xy = 0 is exact:
//   eps_yy = -P (1 - nu^2) / E, eps_xx = P nu (1 + nu) / E (plane strain),
//   c (-u_y(0))^m = P  =>  u_y(0) = -(P / c)^(1/m),
//   u_y(x, y) = u_y(0) - P (1 - nu^2) y / E,  u_x(x, y) = P nu (1 + nu) x / E.
// The solution is linear, so P1 (and Q1) reproduce it to round-off.

struct ColumnSetup {
  double W = 2, H = 1, young = 3, poisson = 0, P = 0.6;
  Shape shape = Shape::Triangle;
  int nx = 4, ny = 3;
};

struct Column {
  std::shared_ptr<const Mesh> mesh;
  std::unique_ptr<Model> model;
  BackwardEuler scheme;
};

// Elasticity, pressure on top, roller on the left, and the given contact brick on the bottom;
// quasi-static (no inertia, no viscosity).
// `constants`: the contact law's parameters, which the contact brick reads from the model.
std::unique_ptr<Column> make_column(const ColumnSetup& s, std::shared_ptr<Brick> contact,
                                    const ParameterValues& constants) {
  auto c = std::make_unique<Column>();
  c->mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {s.W, s.H}, s.nx, s.ny, s.shape));
  c->model = std::make_unique<Model>(c->mesh);
  Model& m = *c->model;
  m.add_unknown("v", std::make_shared<const FESpace>(c->mesh, 1, 2));
  c->scheme.attach(m, false);
  m.set_constant("B", isotropic_stiffness_from_young(2, s.young, s.poisson));
  m.add_brick(std::make_shared<ElasticityBrick>());
  m.add_brick(std::make_shared<TractionBrick>(std::vector<double>{0.0, -s.P}, "top"));
  m.set_constants(constants);
  m.add_brick(std::move(contact));
  m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "left", {0})));
  m.finalize();
  return c;
}

// max over nodes of |u - exact| with exact(x, out); returns the error and the largest exact component.
std::pair<double, double> nodal_error(const FESpace& space, const Eigen::VectorXd& u,
                                      const std::function<void(const double*, double*)>& exact) {
  double error = 0, size = 0;
  for (int s = 0; s < space.num_scalar_dofs(); ++s) {
    const auto x = space.scalar_dof_point(s);
    double e[3] = {0, 0, 0};
    exact(x.data(), e);
    for (int c = 0; c < space.num_components(); ++c) {
      error = std::max(error, std::abs(u[space.dof(s, c)] - e[c]));
      size = std::max(size, std::abs(e[c]));
    }
  }
  return {error, size};
}

std::function<void(const double*, double*)> column_displacement(const ColumnSetup& s, double u_bottom) {
  return [=](const double* x, double* out) {
    out[0] = s.P * s.poisson * (1 + s.poisson) * x[0] / s.young;
    out[1] = u_bottom - s.P * (1 - s.poisson * s.poisson) * x[1] / s.young;
  };
}

StepperOptions one_static_step() {
  StepperOptions o;
  o.start = 0;
  o.end = 1;
  o.step = 1;  // one backward Euler step of size 1 from u_prev = 0: u = v
  return o;
}

TEST(CompressionColumn, LinearComplianceGivesTheClosedFormToRoundOff) {
  const double c = 5;
  for (const Shape shape : {Shape::Triangle, Shape::Quadrilateral})
    for (const double poisson : {0.0, 0.3}) {
      ColumnSetup s;
      s.shape = shape;
      s.poisson = poisson;
      auto column = make_column(s, std::make_shared<NormalResponseBrick<NormalCompliance>>("bottom"),
                                law_values(NormalCompliance{c, 1, 0}));
      NewtonSolver newton;
      const RunSummary run = Stepper(one_static_step()).run(*column->model, column->scheme, newton);
      ASSERT_TRUE(run.completed) << run.message;
      // Piecewise linear with the right-sided slope at u_nu = 0: the first Newton step is exact.
      EXPECT_EQ(run.newton_iterations_max_per_step, 1);
      const Model& m = *column->model;
      const double u_bottom = -s.P / c;  // -0.12: the foundation's penetration
      const auto [error, size] = nodal_error(m.space("u"), m.values("u"), column_displacement(s, u_bottom));
      std::printf("compliance m=1 (%s, nu=%.1f): u_y(0) = %.15f (exact %.15f), max nodal error %.2e\n",
                  shape == Shape::Triangle ? "P1" : "Q1", poisson, m.values("u")[m.space("u").dof(0, 1)], u_bottom,
                  error);
      EXPECT_LT(error, 1e-12 * size);
      // The top sinks by the penetration plus the column's shortening P H (1 - nu^2) / E.
      const double u_top = u_bottom - s.P * (1 - poisson * poisson) * s.H / s.young;
      for (int n : m.space("u").scalar_dofs_on("top"))
        EXPECT_NEAR(m.values("u")[m.space("u").dof(n, 1)], u_top, 1e-12 * std::abs(u_top));
    }
}

TEST(CompressionColumn, QuadraticComplianceConvergesToTheClosedForm) {
  const double c = 5;
  ColumnSetup s;
  s.poisson = 0.3;
  auto column = make_column(s, std::make_shared<NormalResponseBrick<NormalCompliance>>("bottom"),
                            law_values(NormalCompliance{c, 2, 0}));
  Model& m = *column->model;
  // At u_nu = 0 the law's slope 2 c u_nu vanishes and the column floats: start Newton from a guess in
  // contact, deeper than the solution (v = u for one step of size 1 from u_prev = 0).
  column->scheme.begin_step(m, 1.0);
  m.set_time(1.0);
  Eigen::VectorXd guess = Eigen::VectorXd::Zero(m.space("v").num_dofs());
  for (int n = 0; n < m.space("v").num_scalar_dofs(); ++n) guess[m.space("v").dof(n, 1)] = -1.0;
  m.set_values("v", guess);
  m.apply_dirichlet();
  // The default relative tolerance (1e-10 of the first residual, which is large this far from the
  // solution) leaves an error of that order; ask for round-off.
  NewtonOptions options;
  options.relative_tolerance = 1e-14;
  NewtonSolver newton(options);
  const NewtonReport report = newton.solve(m);
  std::printf("compliance m=2: %s after %d Newton iterations\n", to_string(report.outcome).c_str(), report.iterations);
  ASSERT_TRUE(report.converged()) << report.message;
  EXPECT_GT(report.iterations, 1);
  EXPECT_LE(report.iterations, 10);
  column->scheme.end_step(m, 1.0);
  const double u_bottom = -std::sqrt(s.P / c);
  const auto [error, size] = nodal_error(m.space("u"), m.values("u"), column_displacement(s, u_bottom));
  std::printf("compliance m=2: u_y(0) = %.15f (exact %.15f), max nodal error %.2e\n",
              m.values("u")[m.space("u").dof(0, 1)], u_bottom, error);
  EXPECT_LT(error, 1e-12 * size);
}

// ---- 2. the column on a damped foundation ---------------------------------------------------------------
//
// p_nu = c_nu (v_nu)_+ with no inertia and no viscosity: the stress is sigma_yy = -P from the first step
// on, so c_nu v_nu = P on the bottom in every step and the column sinks at the speed P / c_nu. Backward
// Euler integrates a constant velocity exactly: u_y(x, 0, t_n) = -t_n P / c_nu, and the column keeps the
// elastic shortening of the first step, u_y(top) - u_y(bottom) = -P H (1 - nu^2) / E. From the second
// step on the velocity is the rigid sinking (0, -P / c_nu) everywhere.
TEST(DampedColumn, SinksAtTheSpeedPressureOverDampingExactly) {
  const double c_nu = 4;
  ColumnSetup s;
  s.poisson = 0.25;
  auto column = make_column(s, std::make_shared<NormalResponseBrick<LinearDampedResponse>>("bottom"),
                            law_values(LinearDampedResponse{c_nu}));
  StepperOptions o = one_static_step();
  o.end = 0.5;
  o.step = 0.1;
  NewtonSolver newton;
  int checked = 0;
  double worst = 0;
  StepperCallbacks callbacks;
  callbacks.on_step = [&](const Model& m, const StepRecord& record) {
    EXPECT_TRUE(record.newton.converged());
    EXPECT_EQ(record.newton.iterations, 1) << "piecewise linear, entered on the right-sided slope";
    const double u_bottom = -record.time * s.P / c_nu;
    const auto [error, size] = nodal_error(m.space("u"), m.values("u"), column_displacement(s, u_bottom));
    EXPECT_LT(error, 1e-12 * size) << "step " << record.step;
    worst = std::max(worst, error / size);
    if (record.step >= 2) {
      const auto [v_error, v_size] = nodal_error(m.space("v"), m.values("v"), [&](const double*, double* out) {
        out[0] = 0;
        out[1] = -s.P / c_nu;
      });
      EXPECT_LT(v_error, 1e-12 * v_size) << "step " << record.step;
    }
    ++checked;
  };
  const RunSummary run = Stepper(o).run(*column->model, column->scheme, newton, callbacks);
  ASSERT_TRUE(run.completed) << run.message;
  EXPECT_EQ(checked, 5);
  const Model& m = *column->model;
  const double u_bottom = -0.5 * s.P / c_nu;
  std::printf("damped column: u_y(0, T) = %.15f (exact %.15f), worst relative nodal error %.2e\n",
              m.values("u")[m.space("u").dof(0, 1)], u_bottom, worst);
  const double shortening = s.P * s.H * (1 - s.poisson * s.poisson) / s.young;
  for (int n : m.space("u").scalar_dofs_on("top"))
    EXPECT_NEAR(m.values("u")[m.space("u").dof(n, 1)], u_bottom - shortening, 1e-12);
  for (int n : m.space("u").scalar_dofs_on("bottom"))
    EXPECT_NEAR(m.values("u")[m.space("u").dof(n, 1)], u_bottom, 1e-12 * std::abs(u_bottom));
}

// ---- 3. discrete energy identity of backward Euler ------------------------------------------------------
//
// With M (v_n - v_{n-1}) / k + C v_n + K u_n + F(v_n) = 0 and u_n - u_{n-1} = k v_n, multiplying by k v_n:
//   E_n - E_{n-1} + 1/2 |v_n - v_{n-1}|_M^2 + 1/2 |u_n - u_{n-1}|_K^2 + k v_n^T C v_n + k F(v_n) . v_n = 0,
// E_n = 1/2 v_n^T M v_n + 1/2 u_n^T K u_n. Every term after E_n - E_{n-1} is >= 0 for dissipative contact
// laws, so the energy never grows; the identity itself checks that the scheme's factors, the history
// shift and the bricks' matrices fit together.
TEST(EnergyIdentity, BackwardEulerWithDissipativeContactLaws) {
  const double L = 2, H = 0.5;
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {L, H}, 8, 2, Shape::Triangle));
  Model m(mesh);
  m.add_unknown("v", std::make_shared<const FESpace>(mesh, 1, 2));
  BackwardEuler scheme;
  scheme.attach(m, true);
  const Eigen::MatrixXd B = isotropic_stiffness_from_young(2, 1.0, 0.3);
  m.set_constant("rho", 1.0);
  m.set_constant("A", Eigen::MatrixXd(0.02 * B));
  m.set_constant("B", B);
  auto inertia = std::make_shared<InertiaBrick>();
  auto viscosity = std::make_shared<ViscosityBrick>();
  auto elasticity = std::make_shared<ElasticityBrick>();
  m.set_constants({{"c_nu", 1.0}, {"c_tau", 0.3}, {"g", 0.05}, {"eps", 1e-2}});
  auto normal = std::make_shared<NormalResponseBrick<LinearDampedResponse>>("bottom");
  auto viscous = std::make_shared<FrictionBrick<ViscousFriction>>("bottom");
  auto tresca = std::make_shared<FrictionBrick<RegularizedTresca>>("bottom");
  for (std::shared_ptr<Brick> b :
       std::vector<std::shared_ptr<Brick>>{inertia, viscosity, elasticity, normal, viscous, tresca})
    m.add_brick(b);
  m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "left")));
  m.finalize();

  const CsrMatrix M = brick_matrix(m, *inertia), C = brick_matrix(m, *viscosity), K = brick_matrix(m, *elasticity);
  BrickResidual normal_residual(m, *normal, "v"), viscous_residual(m, *viscous, "v"), tresca_residual(m, *tresca, "v");

  // v0 vanishes on the clamped side, slides along the bottom and pushes into the foundation on x < L / 2.
  const Eigen::VectorXd v0 = m.space("v").interpolate([&](const double* x, double* out) {
    const double s = x[0] / L;
    out[0] = 0.6 * s * (1 + x[1]);
    out[1] = -0.8 * s * std::sin(2 * kPi * s) * (1 - 0.5 * x[1]);
  });
  const Eigen::VectorXd u0 = Eigen::VectorXd::Zero(v0.size());
  scheme.set_initial_state(m, u0, v0);
  auto energy = [&](const Eigen::VectorXd& v, const Eigen::VectorXd& u) {
    return 0.5 * v.dot(M * v) + 0.5 * u.dot(K * u);
  };
  const double E0 = energy(v0, u0);
  ASSERT_GT(E0, 0.0);

  Eigen::VectorXd v_prev = v0, u_prev = u0;
  double E_prev = E0, worst_identity = 0, normal_work = 0, friction_work = 0, viscous_work = 0, numerical = 0;
  int steps = 0, pressing_steps = 0;
  StepperCallbacks callbacks;
  callbacks.on_step = [&](const Model& model, const StepRecord& record) {
    const double k = record.dt;
    const Eigen::VectorXd& v = model.values("v");
    const Eigen::VectorXd& u = model.values("u");  // u_n after end_step
    const Eigen::VectorXd dv = v - v_prev, du = u - u_prev;
    const double E = energy(v, u);
    const double kinetic_jump = 0.5 * dv.dot(M * dv), elastic_jump = 0.5 * du.dot(K * du);
    const double viscous_power = v.dot(C * v);
    const double normal_power = normal_residual(model).dot(v);
    const double friction_power = viscous_residual(model).dot(v) + tresca_residual(model).dot(v);
    const double identity =
        E - E_prev + kinetic_jump + elastic_jump + k * (viscous_power + normal_power + friction_power);
    worst_identity = std::max(worst_identity, std::abs(identity) / E0);
    EXPECT_LT(std::abs(identity), 1e-9 * E0) << "step " << record.step << ": E_n - E_{n-1} = " << E - E_prev;
    EXPECT_GE(kinetic_jump, 0.0);
    EXPECT_GE(elastic_jump, 0.0);
    EXPECT_GE(viscous_power, 0.0);
    EXPECT_GE(normal_power, 0.0);
    EXPECT_GE(friction_power, 0.0);
    EXPECT_LT(E, E_prev) << "step " << record.step;
    // u_n - u_{n-1} = k v_n: the displacement is the affine field of the velocity.
    EXPECT_LT((du - k * v).norm(), 1e-14 * (u.norm() + 1));
    if (normal_power > 0) ++pressing_steps;
    normal_work += k * normal_power;
    friction_work += k * friction_power;
    viscous_work += k * viscous_power;
    numerical += kinetic_jump + elastic_jump;
    E_prev = E;
    v_prev = v;
    u_prev = u;
    ++steps;
  };
  StepperOptions o;
  o.start = 0;
  o.end = 1;
  o.step = 0.05;
  o.prediction = Prediction::Previous;
  NewtonOptions newton_options;
  newton_options.relative_tolerance = 1e-12;
  NewtonSolver newton(newton_options);
  const RunSummary run = Stepper(o).run(m, scheme, newton, callbacks);
  ASSERT_TRUE(run.completed) << run.message;
  EXPECT_EQ(steps, 20);
  std::printf(
      "energy: E0 = %.6e, E_N = %.6e; dissipated: normal %.3e, friction %.3e, viscous %.3e, numerical %.3e;"
      " worst |identity| / E0 = %.2e; %d of %d steps pressing; Newton iterations max %d\n",
      E0, E_prev, normal_work, friction_work, viscous_work, numerical, worst_identity, pressing_steps, steps,
      run.newton_iterations_max_per_step);
  // The checks bite: the body pressed into the foundation and slid on it, and each mechanism took a share.
  EXPECT_GT(pressing_steps, 0);
  EXPECT_GT(normal_work, 1e-3 * E0);
  EXPECT_GT(friction_work, 1e-3 * E0);
  EXPECT_GT(viscous_work, 1e-3 * E0);
  EXPECT_NEAR(E0 - E_prev, normal_work + friction_work + viscous_work + numerical, 1e-8 * E0);
}

// ---- 4. the conductive foundation alone -----------------------------------------------------------------
//
// (0, L) x (0, H) with permittivity beta only, phi = 0 on top and D . nu = k_e (phi - phi_f) on the
// bottom. The residual int beta grad phi . grad psi + int_bottom k_e (phi - phi_f) psi is the weak form of
// -div(beta grad phi) = 0 with beta grad phi . nu + k_e (phi - phi_f) = 0 on the bottom (nu = (0, -1)) and
// no flux on the sides, so phi = a (1 - y / H) with -beta phi'(0) = beta a / H = -k_e (a - phi_f):
//   a = phi_f k_e H / (k_e H + beta).
struct Strip {
  double L = 1.5, H = 0.8, beta = 2.5, phi_f = 1.7;
  std::shared_ptr<const Mesh> mesh =
      std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {L, H}, 3, 4, Shape::Triangle));

  std::unique_ptr<Model> model(double k_e) const {
    auto m = std::make_unique<Model>(mesh);
    m->add_unknown("phi", std::make_shared<const FESpace>(mesh, 1, 1));
    m->set_constant("beta", isotropic_permittivity(2, beta));
    m->add_brick(std::make_shared<PermittivityBrick>());
    m->set_constants(law_values(LinearConductance{k_e, phi_f}));
    m->add_brick(std::make_shared<ConductiveFoundationBrick<LinearConductance>>("bottom"));
    m->add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("phi", "top")));
    m->finalize();
    m->set_time(0);
    return m;
  }
  double bottom(double k_e) const { return phi_f * k_e * H / (k_e * H + beta); }
};

TEST(ConductiveFoundation, StripPotentialMatchesTheClosedForm) {
  const Strip strip;
  for (const double k_e : {4.0, 1e15}) {
    auto m = strip.model(k_e);
    NewtonSolver newton;
    const NewtonReport report = newton.solve(*m);
    ASSERT_TRUE(report.converged()) << report.message;
    EXPECT_EQ(report.iterations, 1);
    const double a = strip.bottom(k_e);
    const auto [error, size] = nodal_error(m->space("phi"), m->values("phi"),
                                           [&](const double* x, double* out) { out[0] = a * (1 - x[1] / strip.H); });
    std::printf("foundation k_e = %g: phi(bottom) = %.15f (exact %.15f), max nodal error %.2e\n", k_e,
                m->values("phi")[m->space("phi").scalar_dofs_on("bottom").front()], a, error);
    EXPECT_LT(error, 1e-10 * size);
    if (k_e > 1e10) {
      for (int n : m->space("phi").scalar_dofs_on("bottom"))
        EXPECT_NEAR(m->values("phi")[n], strip.phi_f, 1e-9 * strip.phi_f) << "a perfectly conducting foundation";
    }
  }
  EXPECT_NEAR(strip.bottom(4.0), 4 * 1.7 * 0.8 / (4 * 0.8 + 2.5), 1e-15);  // 0.954385964912...
}

TEST(ConductiveFoundation, ZeroConductanceInsulates) {
  const Strip strip;
  auto m = strip.model(0.0);
  // Start away from the solution, so that the solve has something to do.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Eigen::VectorXd phi(m->space("phi").num_dofs());
  for (double& x : phi) x = uniform(rng);
  m->set_values("phi", phi);
  m->apply_dirichlet();
  NewtonSolver newton;
  const NewtonReport report = newton.solve(*m);
  ASSERT_TRUE(report.converged()) << report.message;
  EXPECT_EQ(report.iterations, 1);
  EXPECT_LT(m->values("phi").cwiseAbs().maxCoeff(), 1e-13) << "no charge and an insulated bottom: phi = 0";
}

// ---- 5. cached linear brick versus the generic nonlinear brick ------------------------------------------

using ViscousKernel = FrictionKernel<ViscousFriction>;

std::shared_ptr<Brick> generic_viscous_friction(double c_tau) {
  return std::make_shared<WeakFormBrick<ViscousKernel>>(
      WeakForm{.name = "viscous friction (generic)",
               .fields = {{"v"}},
               .tests = {"v"},
               .couplings = {{"v", "v"}},
               .region = "bottom",
               .integration = Integration::Faces,
               .linear = false},
      ViscousKernel{std::make_shared<const ViscousFriction>(ViscousFriction{c_tau}), nullptr, 0});
}

struct FrictionPair {
  std::unique_ptr<Model> model;
  std::unique_ptr<BackwardEuler> scheme;
  int friction = -1;
};

// `constants`: the friction law's parameters, for a brick that reads them from the model.
FrictionPair friction_model(std::shared_ptr<const Mesh> mesh, bool with_bulk, std::shared_ptr<Brick> friction,
                            const ParameterValues& constants = {}) {
  FrictionPair p;
  p.model = std::make_unique<Model>(mesh);
  Model& m = *p.model;
  m.set_constants(constants);
  m.add_unknown("v", std::make_shared<const FESpace>(mesh, 1, 2));
  if (with_bulk) {
    p.scheme = std::make_unique<BackwardEuler>();
    p.scheme->attach(m, true);
    const Eigen::MatrixXd B = isotropic_stiffness_from_young(2, 1.0, 0.3);
    m.set_constant("rho", 1.0);
    m.set_constant("A", Eigen::MatrixXd(0.1 * B));
    m.set_constant("B", B);
    m.add_brick(std::make_shared<InertiaBrick>());
    m.add_brick(std::make_shared<ViscosityBrick>());
    m.add_brick(std::make_shared<ElasticityBrick>());
  }
  p.friction = m.add_brick(std::move(friction));
  m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "left")));
  m.finalize();
  if (with_bulk) p.scheme->begin_step(m, 0.07);
  return p;
}

void set_random_state(Model& m, std::mt19937& rng) {
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (const std::string& name : {std::string("v"), std::string("u_prev"), std::string("v_prev")}) {
    if (!m.has_field(name)) continue;
    Eigen::VectorXd x(m.space(name).num_dofs());
    for (double& value : x) value = uniform(rng);
    m.set_values(name, x);
  }
  m.apply_dirichlet();
}

double relative_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / a.norm(); }

TEST(CachedVersusGeneric, LinearFrictionThroughBothPathsIsIdentical) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {2, 1}, 6, 3, Shape::Triangle));
  const double c_tau = 0.8;
  for (const bool with_bulk : {false, true}) {
    auto cached =
        friction_model(mesh, with_bulk, std::make_shared<FrictionBrick<ViscousFriction>>("bottom"), {{"c_tau", c_tau}});
    auto generic = friction_model(mesh, with_bulk, generic_viscous_friction(c_tau));
    ASSERT_TRUE(cached.model->bricks()[cached.friction]->linear());
    ASSERT_FALSE(generic.model->bricks()[generic.friction]->linear());
    std::mt19937 rng_a(11), rng_b(11);
    for (int sample = 0; sample < 3; ++sample) {
      set_random_state(*cached.model, rng_a);
      set_random_state(*generic.model, rng_b);
      const auto cached_loops = cached.model->elements_assembled(cached.friction);
      const auto generic_loops = generic.model->elements_assembled(generic.friction);
      cached.model->assemble(true);
      generic.model->assemble(true);
      if (sample > 0) {  // the cached brick's residual is a mat-vec; the generic brick re-runs its loop
        EXPECT_EQ(cached.model->elements_assembled(cached.friction), cached_loops);
        EXPECT_GT(generic.model->elements_assembled(generic.friction), generic_loops);
      }
      const Eigen::VectorXd& r = cached.model->residual();
      ASSERT_GT(r.norm(), 0.0);
      const double dr = (r - generic.model->residual()).norm() / r.norm();
      const double dJ =
          relative_difference(Eigen::MatrixXd(cached.model->jacobian()), Eigen::MatrixXd(generic.model->jacobian()));
      std::printf("cached vs generic (%s, sample %d): residual %.2e, Jacobian %.2e (relative)\n",
                  with_bulk ? "with bulk" : "friction only", sample, dr, dJ);
      EXPECT_LT(dr, 1e-13);
      EXPECT_LT(dJ, 1e-13);
    }
  }
}

}  // namespace
}  // namespace pc

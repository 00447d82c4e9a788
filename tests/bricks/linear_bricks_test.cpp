// The linear bricks of the paper's model (inertia, viscosity, elasticity, piezoelectric coupling,
// permittivity, sources, Dirichlet) on the brick checker's meshes (P1, P2 triangles, Q1 quadrilaterals,
// P1 tetrahedra): their tangents against finite differences, linearity and symmetry, closed-form values
// (mass, rigid motions, uniform fields balanced by the boundary loads they imply) and their errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "assembly/error.hpp"
#include "assembly/term_assembly.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/elasticity_brick.hpp"
#include "bricks/inertia_brick.hpp"
#include "bricks/permittivity_brick.hpp"
#include "bricks/piezoelectric_brick.hpp"
#include "bricks/source_bricks.hpp"
#include "bricks/testing/brick_checker.hpp"
#include "bricks/viscosity_brick.hpp"
#include "bricks/voigt.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

using State = std::map<std::string, Eigen::VectorXd>;
using Block = std::pair<std::string, std::string>;  // (test field, trial field)

struct Case {
  std::string label;
  BrickCheckSetup setup;
};

std::vector<Case> cases() {
  return {{"P1 triangles", BrickCheckSetup::square(Shape::Triangle, 1)},
          {"P2 triangles", BrickCheckSetup::square(Shape::Triangle, 2)},
          {"Q1 quadrilaterals", BrickCheckSetup::square(Shape::Quadrilateral, 1)},
          {"P1 tetrahedra", BrickCheckSetup::cube(Shape::Tetrahedron, 1)}};
}

// Anisotropic material data of the right sizes for the dimension.
Eigen::MatrixXd stiffness_matrix(int dim, double scale) {
  Eigen::MatrixXd C = isotropic_stiffness(dim, 1.3 * scale, 0.8 * scale);
  const int n = voigt_size(dim);
  C(0, 0) += 0.5 * scale;
  C(0, 1) = C(1, 0) = C(0, 1) + 0.2 * scale;
  C(0, n - 1) = C(n - 1, 0) = 0.1 * scale;
  return C;
}

Eigen::MatrixXd piezoelectric_matrix(int dim) {
  Eigen::MatrixXd E(dim, voigt_size(dim));
  for (int r = 0; r < E.rows(); ++r)
    for (int c = 0; c < E.cols(); ++c) E(r, c) = std::sin(1.0 + 7 * r + c);
  return E;
}

Eigen::MatrixXd permittivity_matrix(int dim) {
  Eigen::Matrix3d beta;
  beta << 2.0, 0.3, 0.1, 0.3, 1.5, 0.2, 0.1, 0.2, 1.8;
  return beta.topLeftCorner(dim, dim);
}

constexpr double kRho = 2.5;

ConstantTable material(int dim) {
  ConstantTable table;
  table.set("rho", kRho)
      .set("A", stiffness_matrix(dim, 0.1))
      .set("B", stiffness_matrix(dim, 1.0))
      .set("E", piezoelectric_matrix(dim))
      .set("beta", permittivity_matrix(dim));
  return table;
}

// Residuals and tangent blocks of all the brick's terms, assembled with TermAssembly; fields missing
// from the state are zero.
struct Evaluation {
  std::map<std::string, Eigen::VectorXd> residual;
  std::map<Block, Eigen::MatrixXd> tangent;
};

Evaluation evaluate(const Brick& brick, const BrickCheckSetup& setup, const State& state, double time = 0) {
  Evaluation out;
  for (const BrickTerm& bt : brick.terms()) {
    const Term& term = *bt.term;
    std::vector<const FESpace*> spaces;
    std::vector<Eigen::VectorXd> values;
    for (const FieldUse& use : term.fields()) {
      const FESpace& space = *setup.spaces.at(use.name);
      spaces.push_back(&space);
      values.push_back(state.count(use.name) ? state.at(use.name) : Eigen::VectorXd::Zero(space.num_dofs()));
    }
    TermAssembly assembly(bt.term, bt.region, spaces);
    std::vector<const Eigen::VectorXd*> value_ptrs;
    for (const auto& v : values) value_ptrs.push_back(&v);
    std::vector<Eigen::VectorXd*> residuals;
    for (int t : term.tests()) {
      auto [it, inserted] =
          out.residual.try_emplace(term.fields()[t].name, Eigen::VectorXd::Zero(spaces[t]->num_dofs()));
      residuals.push_back(&it->second);
    }
    assembly.assemble(value_ptrs, time, residuals, true);
    for (int k = 0; k < int(term.couplings().size()); ++k) {
      const Coupling& c = term.couplings()[k];
      const Block key{term.fields()[c.test].name, term.fields()[c.trial].name};
      const Eigen::MatrixXd K(assembly.block(k));
      auto [it, inserted] = out.tangent.try_emplace(key, Eigen::MatrixXd::Zero(K.rows(), K.cols()));
      it->second += K;
    }
  }
  return out;
}

double max_abs(const Eigen::MatrixXd& M) { return M.size() ? M.cwiseAbs().maxCoeff() : 0.0; }

// The harness checks the tangent against finite differences, the linear claim (constant tangent,
// R(x) = K x + R(0)) and the symmetric claim (with affine fields read as their unknown).
void expect_linear_and_symmetric(Brick& brick, const DataView& data, const Case& c) {
  SCOPED_TRACE(brick.name() + " on " + c.label);
  const BrickCheckReport report = check_brick(brick, data, c.setup);
  EXPECT_GT(report.tangent_checks, 0) << report;
  EXPECT_TRUE(report.ok()) << report;
}

TEST(LinearBricks, TangentsAreConstantExactAndSymmetricWhereClaimed) {
  for (const Case& c : cases()) {
    const ConstantTable data = material(c.setup.mesh->dim());
    InertiaBrick inertia;
    ViscosityBrick viscosity;
    ElasticityBrick elasticity;
    PiezoelectricCouplingBrick piezo;
    PermittivityBrick permittivity;
    for (Brick* brick : std::vector<Brick*>{&inertia, &viscosity, &elasticity, &piezo, &permittivity})
      expect_linear_and_symmetric(*brick, data, c);
  }
}

TEST(LinearBricks, TraitsNamesAndData) {
  InertiaBrick inertia("body", "density", "w", "acc");
  EXPECT_EQ(inertia.name(), "inertia (density) on body");
  EXPECT_EQ(inertia.data(), std::vector<std::string>{"density"});
  EXPECT_TRUE(inertia.linear() && inertia.symmetric() && !inertia.time_dependent());
  PiezoelectricCouplingBrick piezo;
  EXPECT_EQ(piezo.name(), "piezoelectric coupling (E) on all");
  EXPECT_TRUE(piezo.linear());
  EXPECT_FALSE(piezo.symmetric());
  EXPECT_EQ(ViscosityBrick().data(), std::vector<std::string>{"A"});
  EXPECT_EQ(ElasticityBrick().data(), std::vector<std::string>{"B"});
  EXPECT_EQ(PermittivityBrick().data(), std::vector<std::string>{"beta"});
  EXPECT_TRUE(BodyForceBrick({1.0, 2.0}).data().empty());

  // Field names reach the terms: fields {v, a} tested by v, coupling (v, a).
  ConstantTable data;
  data.set("density", 1.0);
  inertia.update(data);
  const Term& term = *inertia.terms().at(0).term;
  ASSERT_EQ(term.fields().size(), 2u);
  EXPECT_EQ(term.fields()[0].name, "w");
  EXPECT_EQ(term.fields()[1].name, "acc");
  EXPECT_EQ(inertia.terms().at(0).region, "body");
}

// (c) Closed forms.

TEST(LinearBricks, MassMatrixSumsToDensityTimesMeasurePerComponent) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.label);
    const int dim = c.setup.mesh->dim();
    InertiaBrick inertia;
    inertia.update(material(dim));
    const Eigen::MatrixXd M = evaluate(inertia, c.setup, {}).tangent.at({"v", "a"});
    const FESpace& space = *c.setup.spaces.at("v");
    for (int comp = 0; comp < dim; ++comp) {
      Eigen::VectorXd ones = Eigen::VectorXd::Zero(space.num_dofs());
      for (int s = 0; s < space.num_scalar_dofs(); ++s) ones[space.dof(s, comp)] = 1;
      EXPECT_NEAR(ones.dot(M * ones), kRho * 1.0, 1e-12);  // unit square / cube
    }
    EXPECT_NEAR(M.sum(), kRho * 1.0 * dim, 1e-12);
  }
}

TEST(LinearBricks, RigidMotionsCostNoElasticOrViscousForce) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.label);
    const int dim = c.setup.mesh->dim();
    const ConstantTable data = material(dim);
    ElasticityBrick elasticity;
    ViscosityBrick viscosity;
    elasticity.update(data);
    viscosity.update(data);
    // u = t + W x with W skew: a translation plus an infinitesimal rotation.
    const Eigen::Matrix3d W = (Eigen::Matrix3d() << 0, -0.3, 0.2, 0.3, 0, -0.7, -0.2, 0.7, 0).finished();
    const Eigen::Vector3d t(0.5, -1.0, 2.0);
    const Eigen::VectorXd rigid = c.setup.spaces.at("u")->interpolate([&](const double* x, double* out) {
      for (int i = 0; i < dim; ++i) {
        out[i] = t[i];
        for (int j = 0; j < dim; ++j) out[i] += W(i, j) * x[j];
      }
    });
    const double scale =
        max_abs(evaluate(elasticity, c.setup, {}).tangent.at({"v", "u"})) * rigid.cwiseAbs().maxCoeff();
    EXPECT_LT(max_abs(evaluate(elasticity, c.setup, {{"u", rigid}}).residual.at("v")), 1e-13 * scale);
    EXPECT_LT(max_abs(evaluate(viscosity, c.setup, {{"v", rigid}}).residual.at("v")), 1e-13 * scale);
  }
}

struct Side {
  std::string region;
  Eigen::Vector3d normal;
};

std::vector<Side> sides(int dim) {
  std::vector<Side> all = {{"xmin", -Eigen::Vector3d::UnitX()},
                           {"xmax", Eigen::Vector3d::UnitX()},
                           {"ymin", -Eigen::Vector3d::UnitY()},
                           {"ymax", Eigen::Vector3d::UnitY()}};
  if (dim == 3) {
    all.push_back({"zmin", -Eigen::Vector3d::UnitZ()});
    all.push_back({"zmax", Eigen::Vector3d::UnitZ()});
  }
  return all;
}

Eigen::Matrix3d stress_tensor(int dim, const Eigen::VectorXd& s) {
  static const int pair3[3][3] = {{0, 5, 4}, {5, 1, 3}, {4, 3, 2}};
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) m(i, j) = s[dim == 2 ? (i == j ? i : 2) : pair3[i][j]];
  return m;
}

// Residual of tractions sigma n on every side of the unit square or cube, for a uniform stress sigma.
Eigen::VectorXd boundary_traction_residual(const BrickCheckSetup& setup, const Eigen::Matrix3d& sigma) {
  const int dim = setup.mesh->dim();
  Eigen::VectorXd total = Eigen::VectorXd::Zero(setup.spaces.at("v")->num_dofs());
  for (const Side& side : sides(dim)) {
    const Eigen::Vector3d t = sigma * side.normal;
    TractionBrick traction(std::vector<double>(t.data(), t.data() + dim), side.region);
    total += evaluate(traction, setup, {}).residual.at("v");
  }
  return total;
}

// Residual of the surface charge D . n on every side, for a uniform electric displacement D.
Eigen::VectorXd boundary_charge_residual(const BrickCheckSetup& setup, const Eigen::Vector3d& D) {
  Eigen::VectorXd total = Eigen::VectorXd::Zero(setup.spaces.at("phi")->num_dofs());
  for (const Side& side : sides(setup.mesh->dim())) {
    SurfaceChargeBrick charge(D.dot(side.normal), side.region);
    total += evaluate(charge, setup, {}).residual.at("phi");
  }
  return total;
}

// Uniform fields solve the balance equations with q0 = 0 and f0 = 0, so a brick's residual must be
// cancelled exactly by the boundary loads the field implies (sigma n = f_N, D . n = q_b): this checks the
// constitutive signs of each brick and the sign convention of the boundary loads at once.
TEST(LinearBricks, UniformFieldsAreBalancedByTheirBoundaryLoads) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.label);
    const int dim = c.setup.mesh->dim();
    const ConstantTable data = material(dim);
    Eigen::Matrix3d H;  // displacement gradient, not symmetric
    H << 0.3, -0.2, 0.15, 0.4, -0.1, 0.05, -0.25, 0.35, 0.2;
    const Eigen::Vector3d g(0.7, -0.4, 0.9);  // grad phi
    const Eigen::VectorXd u = c.setup.spaces.at("u")->interpolate([&](const double* x, double* out) {
      for (int i = 0; i < dim; ++i) {
        out[i] = 0;
        for (int j = 0; j < dim; ++j) out[i] += H(i, j) * x[j];
      }
    });
    const Eigen::VectorXd phi = c.setup.spaces.at("phi")->interpolate([&](const double* x, double* out) {
      out[0] = 0.2;
      for (int d = 0; d < dim; ++d) out[0] += g[d] * x[d];
    });
    Eigen::VectorXd eps(voigt_size(dim));  // engineering shear
    if (dim == 2)
      eps << H(0, 0), H(1, 1), H(0, 1) + H(1, 0);
    else
      eps << H(0, 0), H(1, 1), H(2, 2), H(1, 2) + H(2, 1), H(0, 2) + H(2, 0), H(0, 1) + H(1, 0);
    const Eigen::VectorXd gd = g.head(dim);

    ElasticityBrick elasticity;
    elasticity.update(data);
    const Eigen::MatrixXd B = data.constant("B");
    const Eigen::VectorXd r_elastic = evaluate(elasticity, c.setup, {{"u", u}}).residual.at("v");
    const Eigen::VectorXd load_elastic = boundary_traction_residual(c.setup, stress_tensor(dim, B * eps));
    EXPECT_LT(max_abs(r_elastic + load_elastic), 1e-12 * max_abs(r_elastic)) << "elasticity";

    ViscosityBrick viscosity;
    viscosity.update(data);
    const Eigen::MatrixXd A = data.constant("A");
    const Eigen::VectorXd r_viscous = evaluate(viscosity, c.setup, {{"v", u}}).residual.at("v");
    const Eigen::VectorXd load_viscous = boundary_traction_residual(c.setup, stress_tensor(dim, A * eps));
    EXPECT_LT(max_abs(r_viscous + load_viscous), 1e-12 * max_abs(r_viscous)) << "viscosity";

    // Piezoelectric coupling: linear phi gives the stress E^T grad phi; uniform strain gives D = E eps.
    PiezoelectricCouplingBrick piezo;
    piezo.update(data);
    const Eigen::MatrixXd E = data.constant("E");
    const Evaluation r_piezo = evaluate(piezo, c.setup, {{"phi", phi}, {"u", u}});
    const Eigen::VectorXd load_piezo_v = boundary_traction_residual(c.setup, stress_tensor(dim, E.transpose() * gd));
    EXPECT_LT(max_abs(r_piezo.residual.at("v") + load_piezo_v), 1e-12 * max_abs(load_piezo_v)) << "piezo, v rows";
    Eigen::Vector3d D = Eigen::Vector3d::Zero();
    D.head(dim) = E * eps;
    const Eigen::VectorXd load_piezo_phi = boundary_charge_residual(c.setup, D);
    EXPECT_LT(max_abs(r_piezo.residual.at("phi") + load_piezo_phi), 1e-12 * max_abs(load_piezo_phi))
        << "piezo, phi rows";

    // Permittivity: D = -beta grad phi.
    PermittivityBrick permittivity;
    permittivity.update(data);
    const Eigen::MatrixXd beta = data.constant("beta");
    const Eigen::VectorXd r_perm = evaluate(permittivity, c.setup, {{"phi", phi}}).residual.at("phi");
    D.head(dim) = -beta * gd;
    EXPECT_LT(max_abs(r_perm + boundary_charge_residual(c.setup, D)), 1e-12 * max_abs(r_perm)) << "permittivity";
  }
}

// Uniaxial strain of an isotropic body: interior rows carry no force, and the reaction on the side
// x = 1 adds up to sigma_xx times its measure (the top and bottom carry only sigma_yy, normal to them).
TEST(LinearBricks, UniaxialStrainGivesTheReactionSigmaTimesArea) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.label);
    const int dim = c.setup.mesh->dim();
    const double lambda = 1.2, mu = 0.7, strain = 0.01;
    ConstantTable data;
    data.set("B", isotropic_stiffness(dim, lambda, mu));
    ElasticityBrick elasticity;
    elasticity.update(data);
    const FESpace& space = *c.setup.spaces.at("u");
    const Eigen::VectorXd u = space.interpolate([&](const double* x, double* out) {
      for (int d = 0; d < dim; ++d) out[d] = d == 0 ? strain * x[0] : 0.0;
    });
    const Eigen::VectorXd r = evaluate(elasticity, c.setup, {{"u", u}}).residual.at("v");
    const double sigma_xx = (lambda + 2 * mu) * strain;

    std::vector<bool> on_boundary(space.num_dofs(), false);
    for (int dof : space.dofs_on("boundary")) on_boundary[dof] = true;
    double interior = 0;
    for (int dof = 0; dof < space.num_dofs(); ++dof)
      if (!on_boundary[dof]) interior = std::max(interior, std::abs(r[dof]));
    EXPECT_LT(interior, 1e-14);

    double reaction = 0;
    for (int dof : space.dofs_on("xmax", 0)) reaction += r[dof];
    EXPECT_NEAR(reaction, sigma_xx * 1.0, 1e-14);  // the side has measure 1
    double opposite = 0;
    for (int dof : space.dofs_on("xmin", 0)) opposite += r[dof];
    EXPECT_NEAR(opposite, -sigma_xx * 1.0, 1e-14);
  }
}

// Permittivity with phi = x and a diagonal beta: the flux through x = 1 is beta_xx times its measure.
TEST(LinearBricks, LinearPotentialGivesTheFluxBetaTimesArea) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.label);
    const int dim = c.setup.mesh->dim();
    ConstantTable data;
    data.set("beta", Eigen::MatrixXd(Eigen::Vector3d(3.0, 2.0, 1.5).head(dim).asDiagonal()));
    PermittivityBrick permittivity;
    permittivity.update(data);
    const FESpace& space = *c.setup.spaces.at("phi");
    const Eigen::VectorXd phi = space.interpolate([](const double* x, double* out) { out[0] = x[0]; });
    const Eigen::VectorXd r = evaluate(permittivity, c.setup, {{"phi", phi}}).residual.at("phi");
    double flux = 0;
    for (int dof : space.dofs_on("xmax")) flux += r[dof];
    EXPECT_NEAR(flux, 3.0, 1e-13);
  }
}

double sum_of_component(const FESpace& space, const Eigen::VectorXd& r, int component) {
  double total = 0;
  for (int s = 0; s < space.num_scalar_dofs(); ++s) total += r[space.dof(s, component)];
  return total;
}

// Lagrange shape functions sum to one, so a residual's entries add up to the load's integral.
TEST(LinearBricks, SourcesIntegrateToTheLoadTimesTheMeasure) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.label);
    const int dim = c.setup.mesh->dim();
    const FESpace& v = *c.setup.spaces.at("v");
    const std::string top = dim == 2 ? "top" : "zmax";  // measure 1 in both cases

    BodyForceBrick body(dim == 2 ? std::vector<double>{0.5, -2.0} : std::vector<double>{0.5, -2.0, 1.5});
    const Eigen::VectorXd r_body = evaluate(body, c.setup, {}).residual.at("v");
    EXPECT_NEAR(sum_of_component(v, r_body, 0), -0.5, 1e-13);
    EXPECT_NEAR(sum_of_component(v, r_body, 1), 2.0, 1e-13);

    TractionBrick traction(dim == 2 ? std::vector<double>{0.0, -3.0} : std::vector<double>{0.0, 0.0, -3.0}, top);
    const Eigen::VectorXd r_traction = evaluate(traction, c.setup, {}).residual.at("v");
    EXPECT_NEAR(sum_of_component(v, r_traction, dim - 1), 3.0, 1e-13);  // external: R = -int f_N . w
    EXPECT_NEAR(sum_of_component(v, r_traction, 0), 0.0, 1e-14);
    Eigen::VectorXd off_top = r_traction;  // only the loaded side's dofs see the traction
    for (int dof : v.dofs_on(top)) off_top[dof] = 0;
    EXPECT_EQ(max_abs(off_top), 0.0);

    // Time-dependent loads see the assembly's time: q0 = t x_0 integrates to t / 2.
    VolumeChargeBrick volume([](const double* x, double t, double* out) { out[0] = t * x[0]; }, LoadTime::Varying);
    EXPECT_TRUE(volume.time_dependent());
    EXPECT_NEAR(evaluate(volume, c.setup, {}, 0.8).residual.at("phi").sum(), -0.8 / 2, 1e-13);
    VolumeChargeBrick constant_volume(1.5);
    EXPECT_FALSE(constant_volume.time_dependent());
    EXPECT_NEAR(evaluate(constant_volume, c.setup, {}).residual.at("phi").sum(), -1.5, 1e-13);

    SurfaceChargeBrick surface(0.25, top);  // D . nu = q_b enters with a plus (see source_bricks.hpp)
    EXPECT_NEAR(evaluate(surface, c.setup, {}).residual.at("phi").sum(), 0.25, 1e-13);
  }
}

TEST(LinearBricks, DirichletBrickHandsOverItsCondition) {
  const DirichletBrick clamp = DirichletBrick::clamp("v", "left");
  EXPECT_TRUE(clamp.terms().empty());
  EXPECT_TRUE(clamp.linear());
  EXPECT_FALSE(clamp.time_dependent());
  const auto conditions = clamp.dirichlet_conditions();
  ASSERT_EQ(conditions.size(), 1u);
  EXPECT_EQ(conditions[0].unknown, "v");
  EXPECT_EQ(conditions[0].region, "left");
  EXPECT_TRUE(conditions[0].components.empty());
  double out[3] = {1, 1, 1};
  const double x[3] = {0, 0.5, 0};
  conditions[0].value(x, 0.3, out);
  EXPECT_EQ(out[0], 0.0);
  EXPECT_EQ(out[1], 0.0);

  const DirichletBrick roller("v", "bottom", {1}, -0.25);
  EXPECT_EQ(roller.dirichlet_conditions()[0].components, std::vector<int>{1});
  roller.dirichlet_conditions()[0].value(x, 0.0, out);
  EXPECT_EQ(out[1], -0.25);

  const DirichletBrick ramp(
      "phi", "top", {}, [](const double* p, double t, double* o) { o[0] = t * p[1]; }, true);
  EXPECT_TRUE(ramp.time_dependent());
  ramp.dirichlet_conditions()[0].value(x, 2.0, out);
  EXPECT_EQ(out[0], 1.0);
  EXPECT_EQ(ramp.name(), "Dirichlet condition on phi over top");
}

// (d) Errors name what is wrong.

using testing::error_of;

TEST(LinearBricks, BadDataIsRefusedWithTheDatumNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto update_with = [](Brick& brick, const std::string& name, Eigen::MatrixXd value) {
    ConstantTable data;
    data.set(name, std::move(value));
    return error_of([&] { brick.update(data); });
  };
  ElasticityBrick elasticity("all", "B2");
  EXPECT_EQ(update_with(elasticity, "B2", Eigen::MatrixXd::Identity(2, 2)),
            "datum 'B2' must be 3 x 3 (2D) or 6 x 6 (3D), got 2 x 2");
  Eigen::MatrixXd skew = stiffness_matrix(2, 1.0);
  skew(0, 2) += 0.5;
  EXPECT_CONTAINS(update_with(elasticity, "B2", skew), "datum 'B2' is not symmetric");
  EXPECT_CONTAINS(update_with(elasticity, "B2", isotropic_stiffness(3, 1.0, -0.2)),
                  "datum 'B2' is not positive definite");
  Eigen::MatrixXd with_nan = stiffness_matrix(2, 1.0);
  with_nan(2, 2) = nan;
  EXPECT_CONTAINS(update_with(elasticity, "B2", with_nan), "datum 'B2' has a non-finite entry");
  EXPECT_CONTAINS(update_with(elasticity, "B2", Eigen::MatrixXd::Zero(3, 3)), "datum 'B2' is not positive definite");

  ViscosityBrick viscosity;
  EXPECT_EQ(update_with(viscosity, "A", Eigen::MatrixXd::Zero(3, 3)), "(no error)");  // no viscosity
  EXPECT_CONTAINS(update_with(viscosity, "A", -stiffness_matrix(2, 1.0)), "datum 'A' is not positive definite");

  PiezoelectricCouplingBrick piezo;
  EXPECT_CONTAINS(update_with(piezo, "E", Eigen::MatrixXd::Zero(3, 3)), "datum 'E' must be");
  Eigen::MatrixXd E = piezoelectric_matrix(3);
  E(1, 1) = nan;
  EXPECT_CONTAINS(update_with(piezo, "E", E), "datum 'E' has a non-finite entry");

  PermittivityBrick permittivity;
  EXPECT_CONTAINS(update_with(permittivity, "beta", -permittivity_matrix(2)), "datum 'beta' is not positive definite");
  EXPECT_CONTAINS(update_with(permittivity, "beta", Eigen::MatrixXd::Identity(4, 4)), "datum 'beta' must be");

  InertiaBrick inertia;
  for (double rho : {-1.0, 0.0, nan}) {
    const std::string error = update_with(inertia, "rho", Eigen::MatrixXd::Constant(1, 1, rho));
    EXPECT_CONTAINS(error, "datum 'rho'");
    EXPECT_CONTAINS(error, "must be > 0");
    EXPECT_CONTAINS(error, "leave out the inertia brick");
  }
  EXPECT_CONTAINS(update_with(inertia, "rho", Eigen::MatrixXd::Ones(2, 2)), "datum 'rho'");
  EXPECT_CONTAINS(update_with(inertia, "density", Eigen::MatrixXd::Ones(1, 1)), "'rho'");  // missing datum
  EXPECT_CONTAINS(error_of([&] { inertia.terms(); }), "before update()");
}

TEST(LinearBricks, TensorOfTheWrongDimensionIsRefusedAtAssembly) {
  const Case cube = cases().back();
  ASSERT_EQ(cube.setup.mesh->dim(), 3);
  const ConstantTable data2d = material(2);
  ElasticityBrick elasticity;
  PiezoelectricCouplingBrick piezo;
  PermittivityBrick permittivity;
  for (Brick* brick : std::vector<Brick*>{&elasticity, &piezo, &permittivity}) {
    brick->update(data2d);
    const std::string error = error_of([&] { evaluate(*brick, cube.setup, {}); });
    EXPECT_CONTAINS(error, "'" + brick->data()[0] + "' is written for 2D but the mesh is 3D");
    EXPECT_CONTAINS(error, brick->name());
  }
  // A scalar field where a vector field is expected.
  ElasticityBrick wrong_field("all", "B", "v", "phi");
  wrong_field.update(material(3));
  EXPECT_CONTAINS(error_of([&] { evaluate(wrong_field, cube.setup, {}); }), "field 'phi' has 1 components, expected 3");
}

TEST(LinearBricks, NonFiniteLoadsNameTheBrickThePointAndTheTime) {
  const Case square = cases().front();
  BodyForceBrick body(
      [](const double* x, double t, double* out) {
        out[0] = 1.0;
        out[1] = x[0] > 0.5 ? std::log(-t) : 0.0;
      },
      LoadTime::Varying);
  const std::string error = error_of([&] { evaluate(body, square.setup, {}, 0.25); });
  EXPECT_CONTAINS(error, "brick 'body force on all'");
  EXPECT_CONTAINS(error, "nan in component 1 at x = (");
  EXPECT_CONTAINS(error, "t = 0.25");

  // A load that writes fewer components than the field has.
  TractionBrick short_load(std::vector<double>{1.0}, "top");
  EXPECT_CONTAINS(error_of([&] { evaluate(short_load, square.setup, {}); }),
                  "one finite value per component of field 'v' (2)");
  EXPECT_CONTAINS(error_of([] { SurfaceChargeBrick(Load(), LoadTime::Constant, "top"); }), "load function is empty");
  EXPECT_CONTAINS(error_of([] { DirichletBrick("v", "left", {3}, 0.0); }), "component 3 is out of range");
}

}  // namespace
}  // namespace pc

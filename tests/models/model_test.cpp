// The Model's contract: caching of linear bricks (a new step size or a changed datum re-runs only what it
// must), cached and forced assembly agree, a linear model converges in one Newton iteration, and bad
// input is refused with a message naming the field, region or datum, and a parameter is one brick's.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <tuple>

#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"
#include "bricks/boundary_dashpot_brick.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/elasticity_brick.hpp"
#include "bricks/friction_brick.hpp"
#include "bricks/inertia_brick.hpp"
#include "bricks/laws/friction_laws.hpp"
#include "bricks/laws/normal_laws.hpp"
#include "bricks/normal_response_brick.hpp"
#include "bricks/permittivity_brick.hpp"
#include "bricks/piezoelectric_brick.hpp"
#include "bricks/source_bricks.hpp"
#include "bricks/viscosity_brick.hpp"
#include "models/model.hpp"
#include "models/solvers/newton.hpp"
#include "models/time_scheme.hpp"
#include "support/piezo_material.hpp"

namespace pc {
namespace {

using ::testing::HasSubstr;

struct Bulk {
  std::shared_ptr<const Mesh> mesh =
      std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {2, 1}, 6, 3, Shape::Triangle));
  std::unique_ptr<Model> model = std::make_unique<Model>(mesh);
  BackwardEuler scheme;
  int inertia = -1, viscosity = -1, elasticity = -1, piezo = -1, permittivity = -1, traction = -1;

  // `extra` adds bricks (and their constants) before finalize().
  explicit Bulk(const std::function<void(Model&)>& extra = {}) {
    Model& m = *model;
    const auto tensors = testing::scaled_pzt5h();
    m.add_unknown("v", std::make_shared<const FESpace>(mesh, 1, 2));
    m.add_unknown("phi", std::make_shared<const FESpace>(mesh, 1, 1));
    scheme.attach(m, true);
    m.set_constant("rho", 2.0);
    m.set_constant("A", tensors.A);
    m.set_constant("B", tensors.B);
    m.set_constant("E", tensors.E);
    m.set_constant("beta", tensors.beta);
    inertia = m.add_brick(std::make_shared<InertiaBrick>());
    viscosity = m.add_brick(std::make_shared<ViscosityBrick>());
    elasticity = m.add_brick(std::make_shared<ElasticityBrick>());
    piezo = m.add_brick(std::make_shared<PiezoelectricCouplingBrick>());
    permittivity = m.add_brick(std::make_shared<PermittivityBrick>());
    traction = m.add_brick(std::make_shared<TractionBrick>(std::vector<double>{0.0, -1.0}, "top"));
    m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "left")));
    m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("phi", "top")));
    if (extra) extra(m);
    m.finalize();
  }

  std::vector<std::int64_t> loops() const {
    std::vector<std::int64_t> n;
    for (int b = 0; b < int(model->bricks().size()); ++b) n.push_back(model->elements_assembled(b));
    return n;
  }
};

Eigen::MatrixXd dense(const CsrMatrix& m) { return Eigen::MatrixXd(m); }

TEST(Model, ALinearModelConvergesInOneNewtonIteration) {
  Bulk bulk;
  bulk.scheme.begin_step(*bulk.model, 0.01);
  NewtonSolver newton;
  const NewtonReport report = newton.solve(*bulk.model);
  EXPECT_TRUE(report.converged()) << report.message;
  EXPECT_EQ(report.iterations, 1);
  EXPECT_GT(bulk.model->values("v").norm(), 0.0);
}

TEST(Model, ChangingTheTimeStepRunsNoElementLoopOfACachedBrick) {
  Bulk bulk;
  bulk.scheme.begin_step(*bulk.model, 0.01);
  bulk.model->assemble(true);
  const auto before = bulk.loops();
  const Eigen::MatrixXd J1 = dense(bulk.model->jacobian());
  bulk.scheme.begin_step(*bulk.model, 0.002);
  bulk.model->assemble(true);
  EXPECT_EQ(bulk.loops(), before);
  // ... and yet the Jacobian follows the new factors: J = M / k + C_A + k C_B + couplings.
  const Eigen::MatrixXd J2 = dense(bulk.model->jacobian());
  EXPECT_GT((J1 - J2).norm(), 1e-3 * J1.norm());
  bulk.model->invalidate_caches();
  bulk.model->assemble(true);
  EXPECT_LT((dense(bulk.model->jacobian()) - J2).norm(), 1e-14 * J2.norm());
}

TEST(Model, ChangingADatumInvalidatesOnlyTheBricksThatReadIt) {
  Bulk bulk;
  bulk.scheme.begin_step(*bulk.model, 0.01);
  bulk.model->assemble(true);
  const auto before = bulk.loops();
  bulk.model->set_constant("B", 2 * bulk.model->constant("B"));
  bulk.model->assemble(true);
  const auto after = bulk.loops();
  for (int b = 0; b < int(before.size()); ++b) {
    if (b == bulk.elasticity)
      EXPECT_GT(after[b], before[b]) << "the elasticity brick reads B";
    else
      EXPECT_EQ(after[b], before[b]) << "brick " << bulk.model->bricks()[b]->name() << " does not read B";
  }
}

TEST(Model, CachedAndForcedAssemblyAreIdentical) {
  Bulk bulk;
  bulk.scheme.begin_step(*bulk.model, 0.01);
  Eigen::VectorXd v = Eigen::VectorXd::Random(bulk.model->space("v").num_dofs());
  bulk.model->set_values("v", v);
  bulk.model->apply_dirichlet();
  bulk.model->assemble(true);
  bulk.model->set_values("phi", Eigen::VectorXd::Random(bulk.model->space("phi").num_dofs()));
  bulk.model->apply_dirichlet();
  bulk.model->assemble(true);  // cached: mat-vec residual, summed linear blocks
  const Eigen::VectorXd cached_residual = bulk.model->residual();
  const Eigen::MatrixXd cached_jacobian = dense(bulk.model->jacobian());
  bulk.model->invalidate_caches();
  bulk.model->assemble(true);
  EXPECT_LT((bulk.model->residual() - cached_residual).norm(), 1e-13 * cached_residual.norm());
  EXPECT_LT((dense(bulk.model->jacobian()) - cached_jacobian).norm(), 1e-14 * cached_jacobian.norm());
}

// A residual snapshot put back after an assembly at perturbed values (the time estimate's finite
// difference) gives what assembling again at the restored values gives: the residual, each field's piece,
// a kept brick's and the scales Newton measures by, bitwise.
TEST(Model, ARestoredResidualSnapshotIsTheAssemblyAtTheRestoredValues) {
  Bulk bulk;
  Model& m = *bulk.model;
  m.keep_brick_residuals({bulk.traction, bulk.elasticity});
  bulk.scheme.begin_step(m, 0.01);
  m.set_values("v", Eigen::VectorXd::Random(m.space("v").num_dofs()));
  m.apply_dirichlet();
  m.assemble(false);
  Model::ResidualSnapshot kept = m.take_residual_snapshot();
  const Eigen::VectorXd u_prev = m.values("u_prev");
  m.set_values("u_prev", u_prev + 1e-3 * Eigen::VectorXd::Random(u_prev.size()));
  m.assemble(false);
  ASSERT_GT((m.residual() - kept.residual).norm(), 0.0);  // the perturbation reached the residual
  // The snapshot holds the kept residuals (moved, not copied): none is read until it is put back.
  EXPECT_THAT([&] { (void)m.brick_residual(bulk.elasticity, "v"); },
              ::testing::ThrowsMessage<Error>(HasSubstr("while a residual snapshot holds the kept residuals")));
  EXPECT_THAT([&] { (void)m.take_residual_snapshot(); },
              ::testing::ThrowsMessage<Error>(HasSubstr("while another snapshot holds the kept residuals")));
  m.restore_residual(std::move(kept));
  const Eigen::VectorXd restored = m.residual(), restored_v = m.field_residual("v"),
                        restored_elastic = m.brick_residual(bulk.elasticity, "v");
  const std::vector<double> restored_scales = m.residual_scales(), restored_round_off = m.round_off_scales();
  m.set_values("u_prev", u_prev);
  m.assemble(false);
  EXPECT_EQ(restored, m.residual());
  EXPECT_EQ(restored_v, m.field_residual("v"));
  EXPECT_EQ(restored_elastic, m.brick_residual(bulk.elasticity, "v"));
  EXPECT_EQ(restored_scales, m.residual_scales());
  EXPECT_EQ(restored_round_off, m.round_off_scales());

  Model::ResidualSnapshot wrong;
  wrong.residual = Eigen::VectorXd::Zero(3);
  EXPECT_THAT([&] { m.restore_residual(std::move(wrong)); },
              ::testing::ThrowsMessage<Error>(HasSubstr("the snapshot has 3 residual entries")));
}

// The Jacobian's share of assembly: the linear bricks' tangents (whichever assembly needs them first, since
// their residual is a mat-vec with them) and the Jacobian's sum; a later residual alone adds nothing. Newton
// reports it within its assembly time.
// The kept brick residuals are each brick's share of its fields' residuals: summed in brick order they give
// each field's residual bitwise, at every assembly (the kept vectors are swapped, not copied, from one to
// the next), and an unknown a brick does not test has a zero share.
// A brick's share that is one product is added straight into the field's residual unless the brick's own
// residual is kept: both ways give the same bits, residual, field residuals and the scales Newton measures
// by (the traction's share is its R0, which is not zero; the others' are one product each).
TEST(Model, KeepingBrickResidualsChangesNoBitOfTheResidual) {
  const auto assembled = [](bool keep_all) {
    Bulk bulk;
    Model& m = *bulk.model;
    if (keep_all) {
      std::vector<int> all(m.bricks().size());
      for (int b = 0; b < int(all.size()); ++b) all[b] = b;
      m.keep_brick_residuals(all);
    }
    bulk.scheme.begin_step(m, 0.01);
    m.set_values("v", Eigen::VectorXd::LinSpaced(m.space("v").num_dofs(), -1.0, 3.0).array().sin().matrix());
    m.set_values("phi", Eigen::VectorXd::LinSpaced(m.space("phi").num_dofs(), 0.0, 2.0).array().cos().matrix());
    m.set_values("u_prev", Eigen::VectorXd::LinSpaced(m.space("v").num_dofs(), 1e-3, -2e-3));
    m.apply_dirichlet();
    m.assemble(true);
    return std::tuple{m.residual(), m.field_residual("v"), m.field_residual("phi"), m.residual_scales(),
                      m.round_off_scales()};
  };
  const auto direct = assembled(false), kept = assembled(true);
  ASSERT_GT(std::get<0>(direct).norm(), 0.0);
  EXPECT_EQ(std::get<0>(direct), std::get<0>(kept));
  EXPECT_EQ(std::get<1>(direct), std::get<1>(kept));
  EXPECT_EQ(std::get<2>(direct), std::get<2>(kept));
  EXPECT_EQ(std::get<3>(direct), std::get<3>(kept));
  EXPECT_EQ(std::get<4>(direct), std::get<4>(kept));
}

TEST(Model, KeptBrickResidualsAreEachBricksShareOfTheFieldResiduals) {
  Bulk bulk;
  Model& m = *bulk.model;
  std::vector<int> all(m.bricks().size());
  for (int b = 0; b < int(all.size()); ++b) all[b] = b;
  m.keep_brick_residuals(all);
  bulk.scheme.begin_step(m, 0.01);
  for (int state = 0; state < 3; ++state) {
    m.set_values("v", Eigen::VectorXd::Random(m.space("v").num_dofs()));
    m.set_values("phi", Eigen::VectorXd::Random(m.space("phi").num_dofs()));
    m.apply_dirichlet();
    m.assemble(state == 1);
    for (const char* u : {"v", "phi"}) {
      Eigen::VectorXd sum = Eigen::VectorXd::Zero(m.space(u).num_dofs());
      for (int b : all) sum += m.brick_residual(b, u);
      EXPECT_EQ(sum, m.field_residual(u)) << u << " at state " << state;
      ASSERT_GT(m.field_residual(u).norm(), 0.0);
    }
    EXPECT_EQ(m.brick_residual(bulk.viscosity, "phi").norm(), 0.0);
    EXPECT_EQ(m.brick_residual(bulk.permittivity, "v").norm(), 0.0);
    EXPECT_GT(m.brick_residual(bulk.piezo, "v").norm(), 0.0);
    EXPECT_GT(m.brick_residual(bulk.piezo, "phi").norm(), 0.0);
  }
}

TEST(Model, CountsTheJacobiansShareOfAssemblyOnlyWhenItIsAssembled) {
  Bulk bulk;
  bulk.scheme.begin_step(*bulk.model, 0.01);
  EXPECT_EQ(bulk.model->jacobian_assembly_seconds(), 0.0);
  bulk.model->assemble(false);
  const double tangents = bulk.model->jacobian_assembly_seconds();
  EXPECT_GT(tangents, 0.0) << "the linear bricks' tangents were assembled";
  bulk.model->assemble(false);
  EXPECT_EQ(bulk.model->jacobian_assembly_seconds(), tangents) << "a residual alone is no Jacobian work";
  bulk.model->assemble(true);
  const double first = bulk.model->jacobian_assembly_seconds();
  EXPECT_GT(first, tangents) << "the sum of the Jacobian";
  bulk.model->assemble(false);
  EXPECT_EQ(bulk.model->jacobian_assembly_seconds(), first);
  NewtonSolver newton;
  const NewtonReport report = newton.solve(*bulk.model);
  EXPECT_GT(report.jacobian_seconds, 0.0);
  EXPECT_LE(report.jacobian_seconds, report.assembly_seconds);
  EXPECT_DOUBLE_EQ(report.jacobian_seconds, bulk.model->jacobian_assembly_seconds() - first);
  // On the full path J is formed in the linear step, when the factorisation first asks for it: that is the
  // Jacobian's time, and the assembly's, all of it in the report.
  NewtonOptions full;
  full.condensed_max_fraction = 0;
  bulk.scheme.begin_step(*bulk.model, 0.005);
  const double before = bulk.model->jacobian_assembly_seconds();
  const NewtonReport by_full = NewtonSolver(full).solve(*bulk.model);
  EXPECT_GT(by_full.factorizations, 0);
  EXPECT_DOUBLE_EQ(by_full.jacobian_seconds, bulk.model->jacobian_assembly_seconds() - before);
  EXPECT_LE(by_full.jacobian_seconds, by_full.assembly_seconds);
}

// An affine field is computed when read after what it reads changed -- its map, its base, a history field --
// and reads the same bits as the formula factor * base + sum c_i history_i whatever changed them.
TEST(Model, AnAffineFieldFollowsEveryChangeOfWhatItReads) {
  Bulk bulk;
  Model& m = *bulk.model;
  const int n = m.space("v").num_dofs();
  auto expected = [&] {
    Eigen::VectorXd u = m.affine_factor("u") * m.values("v");
    const double c = m.affine_coefficients("u")[0];
    if (c != 0) u += c * m.values("u_prev");
    return u;
  };
  auto expect_current = [&](const char* after) { EXPECT_TRUE(m.values("u") == expected()) << "after " << after; };
  bulk.scheme.begin_step(m, 0.01);
  m.set_values("v", Eigen::VectorXd::LinSpaced(n, -1.0, 1.0));
  expect_current("set_values of the base");
  m.set_values("u_prev", Eigen::VectorXd::LinSpaced(n, 2.0, 3.0));
  expect_current("set_values of the history");
  m.set_affine("u", 0.5, {2.0});
  expect_current("set_affine");
  m.apply_dirichlet();
  expect_current("apply_dirichlet");
  m.assemble(false);
  m.add_to_free_values(Eigen::VectorXd::Constant(m.layout().size(), 0.25));
  expect_current("add_to_free_values");
  m.set_free_values(Eigen::VectorXd::Constant(m.layout().size(), -0.5));
  expect_current("set_free_values");
  const Eigen::VectorXd* first = &m.values("u");
  EXPECT_EQ(&m.values("u"), first) << "an unchanged field is read where it is";
}

// The residual's derivative along the history (what the time estimate propagates its errors by) from the
// linear bricks' blocks: the residual is affine in u_prev and v_prev (through u and the acceleration), so a
// central difference of residuals with a step as large as the fields themselves is exact but for round-off.
// Where the blocks cannot give it (a nonlinear brick reads u, or the constants changed since the blocks
// were assembled), it says so and leaves its output alone.
TEST(Model, TheResidualsDerivativeAlongTheHistoryIsTheDifferenceOfItsResiduals) {
  Bulk bulk;
  Model& m = *bulk.model;
  bulk.scheme.begin_step(m, 0.01);
  const int n = m.space("v").num_dofs();
  m.set_values("v", Eigen::VectorXd::LinSpaced(n, -1.0, 2.0));
  m.set_values("v_prev", Eigen::VectorXd::LinSpaced(n, 0.5, -0.5));
  m.set_values("u_prev", Eigen::VectorXd::LinSpaced(n, 1e-3, 3e-3));
  m.apply_dirichlet();
  m.assemble(true);
  const std::map<std::string, Eigen::VectorXd> direction{
      {"u_prev", Eigen::VectorXd::LinSpaced(n, 0.0, 1.0).array().square().matrix()},
      {"v_prev", Eigen::VectorXd::LinSpaced(n, 2.0, -1.0).array().sin().matrix()}};
  Eigen::VectorXd derivative;
  ASSERT_TRUE(m.residual_derivative(direction, derivative));

  const auto residual_moved_by = [&](double t) {
    for (const auto& [h, d] : direction) m.set_values(h, m.values(h) + t * d);
    m.assemble(false);
    const Eigen::VectorXd r = m.residual();
    for (const auto& [h, d] : direction) m.set_values(h, m.values(h) - t * d);
    return r;
  };
  const Eigen::VectorXd difference = (residual_moved_by(1.0) - residual_moved_by(-1.0)) / 2;
  ASSERT_GT(difference.lpNorm<Eigen::Infinity>(), 1e-3 * m.residual().lpNorm<Eigen::Infinity>());
  EXPECT_LT((derivative - difference).lpNorm<Eigen::Infinity>(), 1e-10 * difference.lpNorm<Eigen::Infinity>());
  // Each history field on its own: the derivative is linear in the direction.
  Eigen::VectorXd along_u, along_v;
  ASSERT_TRUE(m.residual_derivative({{"u_prev", direction.at("u_prev")}}, along_u));
  ASSERT_TRUE(m.residual_derivative({{"v_prev", direction.at("v_prev")}}, along_v));
  EXPECT_GT(along_u.norm(), 0.0);
  EXPECT_GT(along_v.norm(), 0.0);
  EXPECT_LT((along_u + along_v - derivative).lpNorm<Eigen::Infinity>(), 1e-12 * derivative.lpNorm<Eigen::Infinity>());

  Eigen::VectorXd untouched = Eigen::VectorXd::Constant(3, 7.0);
  m.set_constant("rho", 3.0);  // the inertia's blocks are of rho = 2 until the next assembly
  EXPECT_FALSE(m.residual_derivative(direction, untouched));
  EXPECT_EQ(untouched, Eigen::VectorXd::Constant(3, 7.0));
  m.assemble(false);
  EXPECT_TRUE(m.residual_derivative(direction, untouched));
  EXPECT_THAT(
      [&] {
        (void)m.residual_derivative({{"u", direction.at("u_prev")}}, untouched);
      },
      ::testing::ThrowsMessage<Error>(HasSubstr("along 'u', which is not a data field")));

  // A normal compliance reads u = k v + u_prev, nonlinearly: its residual is no product of blocks.
  Bulk compliant([](Model& model) {
    model.set_constants(law_values(NormalCompliance{1e3, 1, 0}));
    model.add_brick(std::make_shared<NormalResponseBrick<NormalCompliance>>("bottom"));
  });
  compliant.scheme.begin_step(*compliant.model, 0.01);
  compliant.model->assemble(true);
  EXPECT_FALSE(compliant.model->residual_derivative(direction, untouched));
  EXPECT_TRUE(compliant.model->residual_derivative({{"v_prev", direction.at("v_prev")}}, untouched))
      << "v_prev reaches only the inertia's acceleration, a linear brick's";
}

TEST(Model, RejectsBadInputNamingWhatIsWrong) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 2, 2, Shape::Triangle));
  auto expect_error = [](auto&& action, const std::string& fragment) {
    try {
      action();
      ADD_FAILURE() << "expected an error mentioning '" << fragment << "'";
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr(fragment));
    }
  };
  auto fresh = [&] {
    auto m = std::make_unique<Model>(mesh);
    m->add_unknown("v", std::make_shared<const FESpace>(mesh, 1, 2));
    return m;
  };
  {
    auto m = fresh();
    m->set_constant("A", testing::scaled_pzt5h().A);
    expect_error([&] { m->add_brick(std::make_shared<ViscosityBrick>("all", "A", "w")); }, "'w'");
    expect_error([&] { m->add_brick(std::make_shared<ViscosityBrick>("body", "A")); }, "'body'");
    expect_error([&] { m->add_brick(std::make_shared<ViscosityBrick>("all", "C")); }, "'C'");
    expect_error([&] { m->add_brick(std::make_shared<TractionBrick>(std::vector<double>{0, 1}, "all")); }, "'all'");
  }
  {
    auto m = fresh();
    m->set_constant("A", Eigen::MatrixXd::Identity(2, 2));
    expect_error([&] { m->add_brick(std::make_shared<ViscosityBrick>()); }, "'A'");
    m->set_constant("B", Eigen::MatrixXd{{1, 0, 0}, {0, -1, 0}, {0, 0, 1}});
    expect_error([&] { m->add_brick(std::make_shared<ElasticityBrick>("all", "B", "v", "v")); }, "'B'");
    m->set_constant("rho", -3.0);
    m->add_affine_field("a", "v");
    expect_error([&] { m->add_brick(std::make_shared<InertiaBrick>()); }, "rho");
    expect_error([&] { m->set_constant("nan", std::nan("")); }, "'nan'");
  }
  {
    auto m = fresh();
    m->add_unknown("phi", std::make_shared<const FESpace>(mesh, 1, 1));
    m->set_constant("A", testing::scaled_pzt5h().A);
    m->add_brick(std::make_shared<ViscosityBrick>());
    expect_error([&] { m->finalize(); }, "'phi'");
  }
}

// A model with v on a square and a damped normal response on its bottom, which declares c_nu.
std::unique_ptr<Model> model_with_normal_response() {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 2, 2, Shape::Triangle));
  auto m = std::make_unique<Model>(mesh);
  m->add_unknown("v", std::make_shared<const FESpace>(mesh, 1, 2));
  m->set_constants(law_values(LinearDampedResponse{1e3}));
  m->add_brick(std::make_shared<NormalResponseBrick<LinearDampedResponse>>("bottom"));
  return m;
}

TEST(Model, RefusesAParameterDeclaredByASecondBrickNamingBoth) {
  // A second law (a foundation's, a plugin brick's) declaring c_nu with its own value would change the
  // normal response's c_nu behind its back.
  auto m = model_with_normal_response();
  m->set_constant("c_nu", 5.0);
  EXPECT_THAT([&] { m->add_brick(std::make_shared<BoundaryDashpotBrick>("top", "c_nu")); },
              ::testing::ThrowsMessage<Error>(::testing::AllOf(HasSubstr("parameter 'c_nu'"),
                                                               HasSubstr("brick 'normal response on bottom'"),
                                                               HasSubstr("brick 'boundary dashpot (c_nu) on top'"))));
  EXPECT_EQ(m->bricks().size(), 1u) << "the refused brick is not in the model";
}

TEST(Model, AcceptsParametersOfDistinctNamesAndReadersOfAnotherBricksParameter) {
  auto m = model_with_normal_response();
  const auto normal = std::dynamic_pointer_cast<const NormalPressure>(m->bricks().front());
  ASSERT_NE(normal, nullptr);
  // Distinct names from two owners.
  m->set_constant("c_b", 2.0);
  EXPECT_NO_THROW(m->add_brick(std::make_shared<BoundaryDashpotBrick>("top")));
  // A friction brick reads its normal brick's c_nu as it stands: no declaration of it.
  m->set_constants(law_values(RegularizedCoulomb{0.3, 1e-3}));
  EXPECT_NO_THROW(m->add_brick(std::make_shared<FrictionBrick<RegularizedCoulomb>>("bottom", normal)));
  // Its owner declaring it again, and another brick setting it to the value it has, are accepted.
  m->set_constant("c_nu", 7e3);
  EXPECT_NO_THROW(m->add_brick(std::make_shared<NormalResponseBrick<LinearDampedResponse>>("bottom")));
  m->set_constant("c_nu", 7e3);
  EXPECT_NO_THROW(m->add_brick(std::make_shared<BoundaryDashpotBrick>("left", "c_nu")));
  EXPECT_EQ(m->bricks().size(), 5u);
}

}  // namespace
}  // namespace pc

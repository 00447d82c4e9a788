// Coulomb friction without regularisation (bricks/alart_curnier_friction_brick.hpp), against what the
// regularised law cannot do:
//  1. its tangent (a semismooth Newton's, on the active branch) against finite differences, pressed and
//     sliding, sticking, and across both, with the multiplier an unknown the brick brought;
//  2. a block held on a foundation sliding under it feels exactly mu p, whatever the augmentation r
//     (the regularised law gives mu p V / sqrt(V^2 + eps^2), exact only as eps -> 0);
//  3. a block pushed along below the threshold comes to rest: its contact nodes' slip dies out step by
//     step and the friction carries the push; the regularised law creeps on at a speed of order eps;
//  4. the condensed paths (Schur, columns, Krylov) give the full solve's steps. (The motor scene with the
//     exact law: tests/scene/motor_scene_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"
#include "bricks/alart_curnier_friction_brick.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/friction_brick.hpp"
#include "bricks/laws/friction_laws.hpp"
#include "bricks/laws/normal_laws.hpp"
#include "bricks/normal_response_brick.hpp"
#include "bricks/testing/brick_checker.hpp"
#include "bricks/voigt.hpp"
#include "models/piezo/contact_resultant.hpp"
#include "models/piezo/piezo_contact_recipe.hpp"
#include "models/solvers/newton.hpp"
#include "models/stepper.hpp"
#include "support/run_model.hpp"

namespace pc {
namespace {

using testing::run;

constexpr double kMu = 0.3, kLength = 0.1, kHeight = 0.02;

TEST(ExactCoulomb, TangentMatchesFiniteDifferencesStickingSlidingAndAcross) {
  for (int order : {1, 2}) {
    BrickCheckSetup setup = BrickCheckSetup::square(Shape::Triangle, order);
    setup.spaces["lambda_tau"] = setup.spaces.at("v");
    setup.samples = 6;
    ConstantTable data;
    data.set(law_values(LinearDampedResponse{2.0}));
    data.set("mu", 0.5);
    const auto normal = std::make_shared<NormalResponseBrick<LinearDampedResponse>>("bottom");
    normal->update(data);
    // The multiplier's range against mu p decides the branch: small, the nodes stick (|z| < g); large,
    // they slip; in between, both.
    for (const auto& [regime, range, r] :
         {std::tuple{"sticking", 0.01, 0.01}, std::tuple{"sliding", 5.0, 3.0}, std::tuple{"across", 1.0, 0.5}}) {
      data.set("r", r);
      AlartCurnierFrictionBrick<> brick("bottom", normal);
      setup.ranges["lambda_tau"] = {-range, range};
      setup.ranges["v"] = {-1.0, -0.1};  // into the foundation below (n = -y): pressed
      const BrickCheckReport report = check_brick(brick, data, setup);
      EXPECT_TRUE(report.ok()) << "P" << order << ", " << regime << ": " << report;
      EXPECT_GT(report.tangent_checks, 0);
    }
  }
}

// A friction brick (regularised or exact) paired with a normal brick of another foundation motion would
// read the slip against one foundation and the pressure against another: refused, naming the remedy.
TEST(ExactCoulomb, FrictionOfAnotherFoundationMotionThanItsNormalBrickIsRefused) {
  ContactFields moving;
  auto motion = std::make_shared<FoundationMotion>();
  motion->velocity[0] = TimeFunction::constant(1);
  moving.motion = motion;
  const auto at_rest = std::make_shared<NormalResponseBrick<LinearDampedResponse>>("bottom");
  for (const auto& make :
       std::vector<std::function<void()>>{[&] { AlartCurnierFrictionBrick<>("bottom", at_rest, moving); },
                                          [&] { FrictionBrick<RegularizedCoulomb>("bottom", at_rest, moving); }}) {
    try {
      make();
      ADD_FAILURE() << "a friction brick of another motion than its normal brick was accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("give both bricks the same ContactFields::motion"), std::string::npos)
          << e.what();
    }
  }
  EXPECT_NO_THROW(AlartCurnierFrictionBrick<>(
      "bottom", std::make_shared<NormalResponseBrick<LinearDampedResponse>>("bottom", moving), moving));
}

PiezoContactSpec block(Choice friction) {
  PiezoContactSpec spec;
  spec.mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {kLength, kHeight}, 8, 2));
  spec.B = isotropic_stiffness_from_young(2, 1e9, 0.3);
  spec.contact = "bottom";
  spec.normal = {"normal_compliance", {{"c_nu", 1e12}}};
  spec.friction = std::move(friction);
  return spec;
}

double reaction(const Model& m, const std::string& region, int component) {
  double sum = 0;
  for (int dof : m.space("v").dofs_on(region, component)) sum += m.field_residual("v")[dof];
  return sum;
}

TEST(ExactCoulomb, BlockHeldOnASlidingFoundationFeelsExactlyMuPWhateverR) {
  const double pressure = 1e5, v_along = 0.05;
  // r from a wide stick band (mu p / r = 0.3 m/s, above the slip speed: Newton starts sticking) to a
  // narrow one (3e-6 m/s).
  for (double r : {1e5, 1e10}) {
    PiezoContactSpec spec = block({"coulomb_exact", {{"mu", kMu}, {"r", r}}});
    spec.tractions = {
        {"top", [=](const double*, double, double* out) { out[0] = 0, out[1] = -pressure; }, LoadTime::Constant}};
    auto motion = std::make_shared<FoundationMotion>();
    motion->velocity[0] = TimeFunction::constant(v_along);
    spec.foundation_motion = motion;
    spec.extra_bricks = [](Model& m) {
      m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "top", {0})));
    };
    PiezoContactModel built = build_piezo_contact_model(spec);
    ASSERT_TRUE(built.model->has_field("lambda_tau"));
    std::vector<double> holder;
    ContactResultant resultant;
    run(built, 2e-2, 8, [&](const Model& m) {
      holder.push_back(reaction(m, "top", 0));
      resultant = contact_resultant(built);
    });
    const double drag = kMu * pressure * kLength;
    for (size_t n = 1; n < holder.size(); ++n) EXPECT_NEAR(holder[n], -drag, 1e-9 * drag) << "r " << r << " step " << n;
    EXPECT_NEAR(resultant.force[0], drag, 1e-9 * drag);
    // The multiplier's normal part is held at 0 (its tangential part is the L2 projection of the slip
    // bound mu p(x), which varies along the block: the holder's couple tilts the pressure).
    const Model& m = *built.model;
    const FESpace& space = m.space("lambda_tau");
    for (int scalar : space.scalar_dofs_on("bottom"))
      EXPECT_NEAR(m.values("lambda_tau")[space.dof(scalar, 1)], 0, 1e-12 * kMu * pressure);
    EXPECT_EQ(m.layout().num_free(m.layout().field_index("lambda_tau")), 2 * int(space.scalar_dofs_on("bottom").size()))
        << "the multiplier adds the contact dofs only";
  }
}

// Pressed by p and pushed along by 0.3 mu p on its top, on a foundation at rest: the largest slip speed
// of the contact nodes at each step. With a mass: quasi-static, the free block would have no tangential
// stiffness before it touches (a singular first iteration).
std::vector<double> contact_slip_speeds(Choice friction, double* friction_force) {
  const double pressure = 1e5, push = 0.3 * kMu * pressure;
  PiezoContactSpec spec = block(std::move(friction));
  spec.rho = 2000;
  spec.A = isotropic_stiffness_from_young(2, 1e5, 0.3);  // Kelvin-Voigt: the block's vibration settles
  spec.tractions = {
      {"top", [=](const double*, double, double* out) { out[0] = push, out[1] = -pressure; }, LoadTime::Constant}};
  PiezoContactModel built = build_piezo_contact_model(spec);
  std::vector<double> fastest;
  run(built, 1e-2, 4, [&](const Model& m) {
    double f = 0;
    for (int dof : m.space("v").dofs_on("bottom", 0)) f = std::max(f, std::abs(m.values("v")[dof]));
    fastest.push_back(f);
  });
  *friction_force = contact_resultant(built).force[0];
  return fastest;
}

TEST(ExactCoulomb, BlockPushedBelowTheThresholdComesToRestWhereTheRegularisedLawCreeps) {
  const double push_force = 0.3 * kMu * 1e5 * kLength;
  double exact_force = 0, regularised_force = 0;
  // mu p / r = 3 m/s: a stick band wider than any speed of the loading, so Newton stays on the stick branch.
  const std::vector<double> exact = contact_slip_speeds({"coulomb_exact", {{"mu", kMu}, {"r", 1e4}}}, &exact_force);
  const std::vector<double> regularised =
      contact_slip_speeds({"coulomb", {{"mu", kMu}, {"eps", 1e-4}}}, &regularised_force);
  ASSERT_EQ(exact.size(), 4u);
  // The loading step slips at the block's edges, where the shear of a stuck elastic block concentrates
  // and reaches mu p (partial slip); then the exact law's slip dies out, by more than 10 per step, while
  // the regularised law keeps creeping at about eps tau / (mu p) (it carries no force without a slip).
  for (size_t n = 1; n < exact.size(); ++n) {
    std::printf("step %zu: slip speed exact %.3e m/s, regularised %.3e m/s\n", n + 1, exact[n], regularised[n]);
    EXPECT_LT(exact[n], 0.1 * exact[n - 1]) << n;
    EXPECT_GT(regularised[n], 0.5 * regularised[n - 1]) << n;
  }
  EXPECT_GT(regularised.back(), 3e-5);
  EXPECT_LT(exact.back(), 1e-4 * regularised.back());
  EXPECT_NEAR(exact_force, -push_force, 1e-6 * push_force) << "the friction holds the push";
  EXPECT_NEAR(regularised_force, -push_force, 1e-5 * push_force);
}

// The multiplier's rows are empty in the linear part A, so the Schur complement S_c of the condensed
// paths is singular there: each path must still give the full factorisation's steps. A pushed block at
// rest, then sliding on a foundation that starts to move, solved five ways (schur iterating on the contact
// dofs and the multiplier alone, the default, and on the whole system).
TEST(ExactCoulomb, CondensedPathsAgreeWithTheFullSolveThoughTheMultiplierIsNotInTheLinearPart) {
  std::map<std::string, Eigen::VectorXd> lambda, v;
  for (const char* path : {"full", "schur", "schur on the whole system", "columns", "krylov"}) {
    PiezoContactSpec spec = block({"coulomb_exact", {{"mu", kMu}, {"r", 1e5}}});
    spec.order = 2;
    spec.rho = 2000;
    spec.tractions = {
        {"top", [](const double*, double, double* out) { out[0] = 500, out[1] = -1e5; }, LoadTime::Constant}};
    auto motion = std::make_shared<FoundationMotion>();
    motion->velocity[0] = TimeFunction::table({{0, 0}, {4e-3, 0}, {6e-3, 0.02}});
    spec.foundation_motion = motion;
    PiezoContactModel built = build_piezo_contact_model(spec);
    NewtonOptions options;
    if (std::string(path) == "full") {
      options.condensed_max_dofs = 0;
    } else if (std::string(path) == "schur on the whole system") {
      options.condensation = "schur";
      options.contact_newton = false;
    } else {
      options.condensation = path;
    }
    StepperOptions steps;
    steps.end = 1e-2;
    steps.step = 2.5e-3;
    NewtonSolver newton(options);
    const RunSummary summary = Stepper(steps).run(*built.model, *built.scheme, newton, {});
    ASSERT_TRUE(summary.completed) << path << ": " << summary.message;
    lambda[path] = built.model->values("lambda_tau");
    v[path] = built.model->values("v");
  }
  for (const char* path : {"schur", "schur on the whole system", "columns", "krylov"}) {
    EXPECT_LT((lambda[path] - lambda["full"]).norm(), 1e-8 * lambda["full"].norm()) << path;
    EXPECT_LT((v[path] - v["full"]).norm(), 1e-8 * v["full"].norm()) << path;
  }
  EXPECT_GT(lambda["full"].norm(), 0);
}

}  // namespace
}  // namespace pc

// The contact bricks on one side of small meshes (triangles P1 and P2 on "bottom", tetrahedra P1 on
// "zmin"): their closed forms under uniform states (total normal force, friction force and electric flux
// over the side), their tangents against finite differences through check_brick in contact, out of
// contact and across the kink, their declared fields and traits, and the generic weak-form brick.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/error.hpp"
#include "assembly/term_assembly.hpp"
#include "bricks/conductive_foundation_brick.hpp"
#include "bricks/contact_status.hpp"
#include "bricks/friction_brick.hpp"
#include "bricks/laws/foundation_laws.hpp"
#include "bricks/laws/friction_laws.hpp"
#include "bricks/laws/normal_laws.hpp"
#include "bricks/normal_response_brick.hpp"
#include "bricks/testing/brick_checker.hpp"
#include "bricks/weak_form_brick.hpp"

namespace pc {
namespace {

// Paper data.
constexpr double kCNu = 1e12, kCTau = 0.3, kKe = 1.0, kPhiF = -48.0;

using State = std::map<std::string, Eigen::VectorXd>;

// A mesh with the checker's fields, and the contact side with its outward normal and a tangent.
struct ContactCase {
  std::string label;
  BrickCheckSetup setup;
  std::string side;
  Eigen::Vector3d normal;
  Eigen::Vector3d tangent = Eigen::Vector3d::UnitX();

  int dim() const { return setup.mesh->dim(); }
  double side_measure() const { return setup.mesh->region_measure(side); }
  const FESpace& space(const std::string& field) const { return *setup.spaces.at(field); }

  // Every field of the setup, uniform: vector fields `vector`, scalar fields `scalar`.
  State uniform(const Eigen::Vector3d& velocity, const Eigen::Vector3d& displacement = Eigen::Vector3d::Zero(),
                double potential = 0) const {
    State state;
    for (const auto& [name, space] : setup.spaces) {
      const Eigen::Vector3d value = name == "u" ? displacement : velocity;
      state[name] = space->interpolate([&](const double*, double* out) {
        if (space->num_components() == 1)
          out[0] = potential;
        else
          for (int d = 0; d < dim(); ++d) out[d] = value[d];
      });
    }
    return state;
  }

  // Sum over the dofs of each component of a residual: the total force (or flux) on the side.
  Eigen::Vector3d resultant(const Eigen::VectorXd& residual, const std::string& field) const {
    const FESpace& s = space(field);
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (int i = 0; i < s.num_scalar_dofs(); ++i)
      for (int c = 0; c < s.num_components(); ++c) total[c] += residual[s.dof(i, c)];
    return total;
  }
};

std::vector<ContactCase> contact_cases() {
  return {{"triangles P1", BrickCheckSetup::square(Shape::Triangle, 1), "bottom", -Eigen::Vector3d::UnitY()},
          {"triangles P2", BrickCheckSetup::square(Shape::Triangle, 2), "bottom", -Eigen::Vector3d::UnitY()},
          {"tetrahedra P1", BrickCheckSetup::cube(Shape::Tetrahedron, 1), "zmin", -Eigen::Vector3d::UnitZ()}};
}

// The brick's residuals at a state, by test field, each term assembled with TermAssembly.
std::map<std::string, Eigen::VectorXd> residuals(const Brick& brick, const ContactCase& c, const State& state) {
  std::map<std::string, Eigen::VectorXd> out;
  for (const BrickTerm& bt : brick.terms()) {
    std::vector<const FESpace*> spaces;
    std::vector<const Eigen::VectorXd*> values;
    for (const FieldUse& use : bt.term->fields()) {
      spaces.push_back(&c.space(use.name));
      values.push_back(&state.at(use.name));
    }
    TermAssembly assembly(bt.term, bt.region, spaces);
    std::vector<Eigen::VectorXd*> targets;
    for (int t : bt.term->tests()) {
      auto [it, inserted] =
          out.try_emplace(bt.term->fields()[t].name, Eigen::VectorXd::Zero(spaces[t]->num_dofs()));
      targets.push_back(&it->second);
    }
    assembly.assemble(values, 0.0, targets, false);
  }
  return out;
}

// Tangent checks in three regimes: every point pressed into the foundation, every point moving away, and
// random states that cross the kink. The regimes set the normal component through the range of every
// component, which on these sides is -(that component).
void expect_check_brick_passes(Brick& brick, const ContactCase& c) {
  const std::vector<std::pair<std::string, std::pair<double, double>>> regimes = {
      {"into the foundation", {-1.0, -0.2}}, {"moving away", {0.2, 1.0}}, {"across the kink", {-1.0, 1.0}}};
  for (const auto& [regime, range] : regimes) {
    BrickCheckSetup setup = c.setup;
    setup.ranges["v"] = setup.ranges["u"] = range;
    const BrickCheckReport report = check_brick(brick, ConstantTable{}, setup);
    EXPECT_TRUE(report.ok()) << c.label << ", " << regime << ": " << report;
    EXPECT_GT(report.tangent_checks, 0);
  }
}

// ---- normal response ----------------------------------------------------------------------------------

TEST(NormalResponseBrick, UniformApproachGivesCNuTimesSpeedTimesMeasure) {
  const double speed = 0.3;
  for (const ContactCase& c : contact_cases()) {
    const NormalResponseBrick brick(LinearDampedResponse{kCNu}, c.side);
    // A tangential component changes nothing.
    const auto r = residuals(brick, c, c.uniform(speed * c.normal + 0.7 * c.tangent));
    const Eigen::Vector3d force = c.resultant(r.at("v"), "v");
    const double expected = kCNu * speed * c.side_measure();
    EXPECT_NEAR(force.dot(c.normal), expected, 1e-12 * expected) << c.label;
    EXPECT_NEAR((force - force.dot(c.normal) * c.normal).norm(), 0.0, 1e-12 * expected) << c.label;
    // Moving away from the foundation: no contact, exactly.
    const auto away = residuals(brick, c, c.uniform(-speed * c.normal + 0.7 * c.tangent));
    EXPECT_EQ(away.at("v").cwiseAbs().maxCoeff(), 0.0) << c.label;
  }
}

TEST(NormalResponseBrick, PowerLawAndNormalComplianceClosedForms) {
  for (const ContactCase& c : contact_cases()) {
    const NormalResponseBrick power(PowerDampedResponse{kCNu, 2.0}, c.side);
    const auto rp = residuals(power, c, c.uniform(0.3 * c.normal));
    const double expected_power = kCNu * 0.09 * c.side_measure();
    EXPECT_NEAR(c.resultant(rp.at("v"), "v").dot(c.normal), expected_power, 1e-12 * expected_power) << c.label;

    // The compliance law reads u: a penetration of 0.05 - gap, whatever the velocity.
    const NormalCompliance law{1e9, 1.5, 0.01};
    const NormalResponseBrick compliance(law, c.side);
    const auto rc = residuals(compliance, c, c.uniform(-0.5 * c.normal, 0.05 * c.normal));
    const double expected = 1e9 * std::pow(0.04, 1.5) * c.side_measure();
    EXPECT_NEAR(c.resultant(rc.at("v"), "v").dot(c.normal), expected, 1e-12 * expected) << c.label;
    const auto within_gap = residuals(compliance, c, c.uniform(0.5 * c.normal, 0.005 * c.normal));
    EXPECT_EQ(within_gap.at("v").cwiseAbs().maxCoeff(), 0.0) << c.label;
  }
}

TEST(NormalResponseBrick, DeclaresFieldsAndTraitsFromTheLaw) {
  const NormalResponseBrick damped(LinearDampedResponse{kCNu});
  ASSERT_EQ(damped.terms().size(), 1u);
  const Term& t = *damped.terms()[0].term;
  EXPECT_EQ(damped.terms()[0].region, "contact");
  EXPECT_EQ(t.integration(), Integration::Faces);
  ASSERT_EQ(t.fields().size(), 1u);
  EXPECT_EQ(t.fields()[0].name, "v");
  EXPECT_FALSE(damped.linear());
  EXPECT_TRUE(damped.symmetric());

  const NormalResponseBrick compliance(NormalCompliance{1e9, 1.0, 0.0}, "contact", {.displacement = "u_total"});
  const Term& tc = *compliance.terms()[0].term;
  ASSERT_EQ(tc.fields().size(), 2u);
  EXPECT_EQ(tc.fields()[1].name, "u_total");
  ASSERT_EQ(tc.couplings().size(), 1u);
  EXPECT_EQ(tc.couplings()[0].test, 0);
  EXPECT_EQ(tc.couplings()[0].trial, 1);
}

TEST(NormalResponseBrick, TangentMatchesFiniteDifferences) {
  for (const ContactCase& c : contact_cases()) {
    NormalResponseBrick damped(LinearDampedResponse{kCNu}, c.side);
    expect_check_brick_passes(damped, c);
    NormalResponseBrick power(PowerDampedResponse{kCNu, 2.5}, c.side);
    expect_check_brick_passes(power, c);
    NormalResponseBrick compliance(NormalCompliance{1e9, 2.0, 0.01}, c.side);
    expect_check_brick_passes(compliance, c);
  }
}

// ---- friction -----------------------------------------------------------------------------------------

TEST(FrictionBrick, ViscousFrictionGivesCTauTimesSlipTimesMeasure) {
  const double slip = 0.4;
  for (const ContactCase& c : contact_cases()) {
    const FrictionBrick brick(ViscousFriction{kCTau}, c.side);
    // The normal component of v is projected out.
    const auto r = residuals(brick, c, c.uniform(slip * c.tangent - 0.3 * c.normal));
    const Eigen::Vector3d force = c.resultant(r.at("v"), "v");
    const double expected = kCTau * slip * c.side_measure();
    EXPECT_NEAR(force.dot(c.tangent), expected, 1e-13) << c.label;
    EXPECT_NEAR((force - force.dot(c.tangent) * c.tangent).norm(), 0.0, 1e-13) << c.label;
  }
}

TEST(FrictionBrick, CoulombAndTrescaClosedForms) {
  const double slip = 0.4, speed = 0.3, mu = 0.3, eps = 1e-4, g = 5.0;
  const double direction = slip / std::sqrt(slip * slip + eps * eps);
  for (const ContactCase& c : contact_cases()) {
    const FrictionBrick<RegularizedCoulomb, LinearDampedResponse> coulomb({mu, eps}, {kCNu}, c.side);
    const auto pressed = residuals(coulomb, c, c.uniform(slip * c.tangent + speed * c.normal));
    const double expected = mu * kCNu * speed * direction * c.side_measure();
    EXPECT_NEAR(c.resultant(pressed.at("v"), "v").dot(c.tangent), expected, 1e-12 * expected) << c.label;
    const auto lifted = residuals(coulomb, c, c.uniform(slip * c.tangent - speed * c.normal));
    EXPECT_EQ(lifted.at("v").cwiseAbs().maxCoeff(), 0.0) << c.label;

    const FrictionBrick<RegularizedCoulomb, NormalCompliance> on_compliance({mu, eps}, {1e9, 1.0, 0.01}, c.side);
    const auto r = residuals(on_compliance, c, c.uniform(slip * c.tangent, 0.05 * c.normal));
    const double expected_compliance = mu * 1e9 * 0.04 * direction * c.side_measure();
    EXPECT_NEAR(c.resultant(r.at("v"), "v").dot(c.tangent), expected_compliance, 1e-12 * expected_compliance)
        << c.label;

    const FrictionBrick tresca(RegularizedTresca{g, eps}, c.side);
    const auto rt = residuals(tresca, c, c.uniform(slip * c.tangent));
    EXPECT_NEAR(c.resultant(rt.at("v"), "v").dot(c.tangent), g * direction * c.side_measure(), 1e-12) << c.label;
  }
}

TEST(FrictionBrick, DeclaresFieldsAndTraitsFromTheLaws) {
  const FrictionBrick viscous(ViscousFriction{kCTau});
  EXPECT_TRUE(viscous.linear());
  EXPECT_TRUE(viscous.symmetric());
  EXPECT_EQ(viscous.terms()[0].term->fields().size(), 1u);

  const FrictionBrick<RegularizedCoulomb, LinearDampedResponse> coulomb({0.3, 1e-4}, {kCNu});
  EXPECT_FALSE(coulomb.linear());
  EXPECT_FALSE(coulomb.symmetric());  // the pressure couples the normal velocity into the tangential rows
  EXPECT_EQ(coulomb.terms()[0].term->fields().size(), 1u);

  const FrictionBrick<RegularizedCoulomb, NormalCompliance> on_u({0.3, 1e-4}, {1e9, 1.0, 0.0});
  const Term& t = *on_u.terms()[0].term;
  ASSERT_EQ(t.fields().size(), 2u);
  EXPECT_EQ(t.fields()[1].name, "u");
  EXPECT_EQ(t.couplings().size(), 2u);
}

TEST(FrictionBrick, TangentMatchesFiniteDifferences) {
  // eps comparable to the slip velocities: with eps << |v_tau| the friction force saturates, its slope
  // eps^2 / |v_tau|^3 drowns in the round-off of a finite difference of the force itself.
  const double eps = 0.3;
  for (const ContactCase& c : contact_cases()) {
    FrictionBrick viscous(ViscousFriction{kCTau}, c.side);
    expect_check_brick_passes(viscous, c);
    FrictionBrick<RegularizedCoulomb, LinearDampedResponse> coulomb({0.3, eps}, {kCNu}, c.side);
    expect_check_brick_passes(coulomb, c);
    FrictionBrick<RegularizedCoulomb, NormalCompliance> on_compliance({0.3, eps}, {1e9, 2.0, 0.01}, c.side);
    expect_check_brick_passes(on_compliance, c);
    FrictionBrick tresca(RegularizedTresca{5.0, eps}, c.side);
    expect_check_brick_passes(tresca, c);
  }
}

// ---- conductive foundation ----------------------------------------------------------------------------

TEST(ConductiveFoundationBrick, LinearConductanceGivesKeTimesPotentialDropTimesMeasure) {
  for (const ContactCase& c : contact_cases()) {
    const ConductiveFoundationBrick brick(LinearConductance{kKe, kPhiF}, c.side);
    const auto r = residuals(brick, c, c.uniform(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 2.0));
    const double expected = kKe * (2.0 - kPhiF) * c.side_measure();
    EXPECT_NEAR(r.at("phi").sum(), expected, 1e-12 * expected) << c.label;
  }
}

TEST(ConductiveFoundationBrick, PressureActivatedConductanceNeedsPressure) {
  // p = c_nu * 0.3 = 3 p_ref: s(p) = 9 / 10.
  const PressureActivatedConductance law{kKe, kPhiF, 1e11, LinearDampedResponse{kCNu}};
  for (const ContactCase& c : contact_cases()) {
    const ConductiveFoundationBrick brick(law, c.side);
    const auto pressed = residuals(brick, c, c.uniform(0.3 * c.normal, Eigen::Vector3d::Zero(), 2.0));
    const double expected = 0.9 * kKe * (2.0 - kPhiF) * c.side_measure();
    EXPECT_NEAR(pressed.at("phi").sum(), expected, 1e-12 * expected) << c.label;
    const auto lifted = residuals(brick, c, c.uniform(-0.3 * c.normal, Eigen::Vector3d::Zero(), 2.0));
    EXPECT_EQ(lifted.at("phi").cwiseAbs().maxCoeff(), 0.0) << c.label;
  }
}

TEST(ConductiveFoundationBrick, NoFluxWhereThereIsNoPressure) {
  // The bottom side presses where x > 0.5 and lifts off elsewhere: the element [0, 0.5] carries no current,
  // so the dofs only it touches (x < 0.5) get no flux, while x = 1 does.
  const PressureActivatedConductance law{kKe, kPhiF, 1e11, LinearDampedResponse{kCNu}};
  for (const ContactCase& c : contact_cases()) {
    if (c.dim() != 2) continue;
    const ConductiveFoundationBrick brick(law, c.side);
    State state = c.uniform(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 2.0);
    state["v"] = c.space("v").interpolate([](const double* x, double* out) {
      out[0] = 0;
      out[1] = x[0] > 0.5 ? -0.3 : 0.3;
    });
    const Eigen::VectorXd r = residuals(brick, c, state).at("phi");
    const FESpace& phi = c.space("phi");
    for (int dof : phi.scalar_dofs_on(c.side)) {
      const double x = phi.scalar_dof_point(dof)[0];
      if (x < 0.5) {
        EXPECT_EQ(r[dof], 0.0) << c.label << " x = " << x;
      }
      if (x == 1.0) {
        EXPECT_GT(r[dof], 0.0) << c.label;
      }
    }
  }
}

TEST(ConductiveFoundationBrick, DeclaresFieldsAndTraitsFromTheLaw) {
  const ConductiveFoundationBrick linear(LinearConductance{kKe, kPhiF});
  EXPECT_TRUE(linear.linear());
  EXPECT_TRUE(linear.symmetric());
  ASSERT_EQ(linear.terms()[0].term->fields().size(), 1u);
  EXPECT_EQ(linear.terms()[0].term->fields()[0].name, "phi");

  const ConductiveFoundationBrick activated(PressureActivatedConductance{kKe, kPhiF, 1e6, LinearDampedResponse{kCNu}});
  EXPECT_FALSE(activated.linear());
  EXPECT_FALSE(activated.symmetric());
  const Term& t = *activated.terms()[0].term;
  ASSERT_EQ(t.fields().size(), 2u);
  EXPECT_EQ(t.fields()[1].name, "v");
  EXPECT_EQ(t.couplings().size(), 2u);

  const ConductiveFoundationBrick on_u(PressureActivatedConductance{kKe, kPhiF, 1e6, NormalCompliance{1e9, 1.0, 0.0}});
  EXPECT_EQ(on_u.terms()[0].term->fields()[1].name, "u");
}

TEST(ConductiveFoundationBrick, TangentMatchesFiniteDifferences) {
  for (const ContactCase& c : contact_cases()) {
    ConductiveFoundationBrick linear(LinearConductance{kKe, kPhiF}, c.side);
    expect_check_brick_passes(linear, c);
    ConductiveFoundationBrick activated(PressureActivatedConductance{kKe, kPhiF, 1e11, LinearDampedResponse{kCNu}},
                                        c.side);
    expect_check_brick_passes(activated, c);
    ConductiveFoundationBrick on_u(PressureActivatedConductance{kKe, kPhiF, 1e8, NormalCompliance{1e9, 2.0, 0.01}},
                                   c.side);
    expect_check_brick_passes(on_u, c);
  }
}

// ---- parameters and diagnostics -----------------------------------------------------------------------

TEST(ContactBricks, RejectBadLawParametersNamingBrickAndParameter) {
  auto expect_message = [](auto build, const std::string& part) {
    try {
      build();
      ADD_FAILURE() << "accepted " << part;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  expect_message([] { NormalResponseBrick brick(LinearDampedResponse{-1.0}); }, "brick 'normal response on contact'");
  expect_message([] { NormalResponseBrick brick(LinearDampedResponse{-1.0}); }, "c_nu = -1");
  expect_message([] { FrictionBrick<RegularizedCoulomb, LinearDampedResponse> brick({0.3, 0.0}, {kCNu}); },
                 "eps = 0");
  expect_message([] { FrictionBrick<RegularizedCoulomb, LinearDampedResponse> brick({0.3, 1e-3}, {-kCNu}); },
                 "c_nu = -1e+12");
  expect_message([] { ConductiveFoundationBrick brick(LinearConductance{-1.0, kPhiF}); },
                 "brick 'conductive foundation on contact'");
}

TEST(ContactStatus, CountsPressedAndSlidingNodes) {
  const ContactCase c = contact_cases()[0];  // bottom nodes at x = 0, 0.5, 1
  const Eigen::VectorXd v = c.space("v").interpolate([](const double* x, double* out) {
    out[0] = x[0] == 1.0 ? 0.1 : 0.0;   // slides at x = 1
    out[1] = x[0] == 0.0 ? 0.2 : -0.2;  // lifts off at x = 0
  });
  const ContactStatus status =
      contact_status(LinearDampedResponse{kCNu}, c.space("v"), c.side, v, v, {0, -1, 0}, 1e-6);
  EXPECT_EQ(status.nodes, 3);
  EXPECT_EQ(status.in_contact, 2);
  EXPECT_EQ(status.sliding, 1);
  EXPECT_EQ(status.sticking(), 1);
}

// ---- the generic weak-form brick ----------------------------------------------------------------------

// The paper's electric contact term written by a user as a kernel.
struct UserConductance {
  double k_e, phi_f;
  template <class S>
  void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    out.f0[0][0] = k_e * (in.value[0][0] - phi_f);
  }
};

// A nonlinear bulk term coupling both unknowns: f0_v = |v|^2 v + phi v, f1_phi = (1 + phi^2) grad phi.
struct NonlinearBulk {
  template <class S>
  void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    S speed2 = 0;
    for (int d = 0; d < in.dim; ++d) speed2 += in.value[0][d] * in.value[0][d];
    const S phi = in.value[1][0];
    for (int d = 0; d < in.dim; ++d) {
      out.f0[0][d] = speed2 * in.value[0][d] + phi * in.value[0][d];
      out.f1[1][0][d] = (1.0 + phi * phi) * in.grad[1][0][d];
    }
  }
};

TEST(WeakFormBrick, UserKernelReproducesTheConductiveFoundation) {
  for (const ContactCase& c : contact_cases()) {
    WeakFormBrick user(WeakForm{.name = "user conductance", .fields = {{"phi"}}, .tests = {"phi"},
                                .couplings = {{"phi", "phi"}}, .region = c.side, .integration = Integration::Faces,
                                .linear = true, .symmetric = true},
                       UserConductance{kKe, kPhiF});
    const ConductiveFoundationBrick library(LinearConductance{kKe, kPhiF}, c.side);
    State state = c.uniform(Eigen::Vector3d::Zero());
    state["phi"] = Eigen::VectorXd::Random(c.space("phi").num_dofs());
    const Eigen::VectorXd difference = residuals(user, c, state).at("phi") - residuals(library, c, state).at("phi");
    EXPECT_LT(difference.cwiseAbs().maxCoeff(), 1e-13) << c.label;
    const BrickCheckReport report = check_brick(user, ConstantTable{}, c.setup);
    EXPECT_TRUE(report.ok()) << report;
    EXPECT_TRUE(user.linear());
    EXPECT_EQ(user.name(), "user conductance");
  }
}

TEST(WeakFormBrick, NonlinearBulkKernelHasAConsistentTangent) {
  const WeakForm form{.name = "nonlinear bulk", .fields = {{"v"}, {"phi", true}}, .tests = {"v", "phi"},
                      .couplings = {{"v", "v"}, {"v", "phi"}, {"phi", "phi"}}};
  for (const ContactCase& c : contact_cases()) {
    WeakFormBrick brick(form, NonlinearBulk{});
    const BrickCheckReport report = check_brick(brick, ConstantTable{}, c.setup);
    EXPECT_TRUE(report.ok()) << c.label << ": " << report;
    EXPECT_FALSE(brick.linear());
    EXPECT_FALSE(brick.symmetric());
    // The claims are the user's: a false one is caught by the checker.
    WeakForm false_claim = form;
    false_claim.linear = true;
    WeakFormBrick wrong(false_claim, NonlinearBulk{});
    EXPECT_FALSE(check_brick(wrong, ConstantTable{}, c.setup).ok()) << c.label;
  }
}

TEST(WeakFormBrick, RejectsFieldsItDoesNotRead) {
  try {
    WeakFormBrick brick(WeakForm{.name = "broken", .fields = {{"v"}}, .tests = {"w"}}, NonlinearBulk{});
    ADD_FAILURE() << "accepted a test field it does not read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'w'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("broken"), std::string::npos) << e.what();
  }
  EXPECT_THROW(WeakFormBrick(WeakForm{.name = "broken", .fields = {{"v"}, {"phi"}}, .tests = {"v"},
                                      .couplings = {{"phi", "v"}}},
                             NonlinearBulk{}),
               Error);
}

}  // namespace
}  // namespace pc

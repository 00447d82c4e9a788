// The contact bricks on one side of small meshes (triangles P1 and P2 on "bottom", tetrahedra P1 on
// "zmin"): their closed forms under uniform states (total normal force, friction force and electric flux
// over the side), their tangents against finite differences through check_brick in contact, out of
// contact and across the kink, their declared fields and traits; their parameters read from the model's
// constants (a ConstantTable here) in update(), a Coulomb friction or pressure-activated foundation brick
// paired with the normal brick of its surface, the law registries; and the generic weak-form brick.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "assembly/error.hpp"
#include "assembly/parameters.hpp"
#include "assembly/registry.hpp"
#include "assembly/term_assembly.hpp"
#include "bricks/alart_curnier_friction_brick.hpp"
#include "bricks/conductive_foundation_brick.hpp"
#include "bricks/contact_status.hpp"
#include "bricks/friction_brick.hpp"
#include "bricks/law_registry.hpp"
#include "bricks/laws/direction.hpp"
#include "bricks/laws/foundation_laws.hpp"
#include "bricks/laws/friction_laws.hpp"
#include "bricks/laws/law_parameters.hpp"
#include "bricks/laws/normal_laws.hpp"
#include "bricks/normal_pressure.hpp"
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
      auto [it, inserted] = out.try_emplace(bt.term->fields()[t].name, Eigen::VectorXd::Zero(spaces[t]->num_dofs()));
      targets.push_back(&it->second);
    }
    assembly.assemble(values, 0.0, targets, false);
  }
  return out;
}

// The model constants of the given laws' parameters (law_values), as a Model would hold them.
template <class... Laws> ConstantTable constants_of(const Laws&... laws) {
  ConstantTable data;
  auto add = [&data](const ParameterValues& values) {
    for (const auto& [name, value] : values) data.set(name, value);
  };
  (add(law_values(laws)), ...);
  return data;
}

// A brick built, then updated from the model's constants (which is where it reads its parameters).
template <class B, class... Args> std::shared_ptr<B> updated(const DataView& data, Args&&... args) {
  auto brick = std::make_shared<B>(std::forward<Args>(args)...);
  brick->update(data);
  return brick;
}

// Tangent checks in three regimes: every point pressed into the foundation, every point moving away, and
// random states that cross the kink. The regimes set the normal component through the range of every
// component, which on these sides is -(that component). check_brick updates the brick from `data`; a
// paired normal brick must have been updated from the same data (as a model updates every brick).
void expect_check_brick_passes(Brick& brick, const DataView& data, const ContactCase& c) {
  const std::vector<std::pair<std::string, std::pair<double, double>>> regimes = {
      {"into the foundation", {-1.0, -0.2}}, {"moving away", {0.2, 1.0}}, {"across the kink", {-1.0, 1.0}}};
  for (const auto& [regime, range] : regimes) {
    BrickCheckSetup setup = c.setup;
    setup.ranges["v"] = setup.ranges["u"] = range;
    const BrickCheckReport report = check_brick(brick, data, setup);
    EXPECT_TRUE(report.ok()) << c.label << ", " << regime << ": " << report;
    EXPECT_GT(report.tangent_checks, 0);
  }
}

// The largest |entry| of the brick's residual for `field` at a state: a tangent check of a brick whose
// parameters were never read (all zero) would pass on a zero residual, so the checks below first see
// that the brick acts.
double residual_size(const Brick& brick, const ContactCase& c, const State& state, const std::string& field) {
  return residuals(brick, c, state).at(field).cwiseAbs().maxCoeff();
}

// ---- normal response ----------------------------------------------------------------------------------

TEST(NormalResponseBrick, UniformApproachGivesCNuTimesSpeedTimesMeasure) {
  const double speed = 0.3;
  for (const ContactCase& c : contact_cases()) {
    NormalResponseBrick<LinearDampedResponse> brick(c.side);
    brick.update(constants_of(LinearDampedResponse{kCNu}));
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
    NormalResponseBrick<PowerDampedResponse> power(c.side);
    power.update(constants_of(PowerDampedResponse{kCNu, 2.0}));
    const auto rp = residuals(power, c, c.uniform(0.3 * c.normal));
    const double expected_power = kCNu * 0.09 * c.side_measure();
    EXPECT_NEAR(c.resultant(rp.at("v"), "v").dot(c.normal), expected_power, 1e-12 * expected_power) << c.label;

    // The compliance law reads u: a penetration of 0.05 - gap, whatever the velocity.
    NormalResponseBrick<NormalCompliance> compliance(c.side);
    compliance.update(constants_of(NormalCompliance{1e9, 1.5, 0.01}));
    const auto rc = residuals(compliance, c, c.uniform(-0.5 * c.normal, 0.05 * c.normal));
    const double expected = 1e9 * std::pow(0.04, 1.5) * c.side_measure();
    EXPECT_NEAR(c.resultant(rc.at("v"), "v").dot(c.normal), expected, 1e-12 * expected) << c.label;
    const auto within_gap = residuals(compliance, c, c.uniform(0.5 * c.normal, 0.005 * c.normal));
    EXPECT_EQ(within_gap.at("v").cwiseAbs().maxCoeff(), 0.0) << c.label;
  }
}

TEST(NormalResponseBrick, DeclaresFieldsAndTraitsFromTheLaw) {
  NormalResponseBrick<LinearDampedResponse> damped;
  damped.update(constants_of(LinearDampedResponse{kCNu}));
  ASSERT_EQ(damped.terms().size(), 1u);
  const Term& t = *damped.terms()[0].term;
  EXPECT_EQ(damped.terms()[0].region, "contact");
  EXPECT_EQ(t.integration(), Integration::Faces);
  ASSERT_EQ(t.fields().size(), 1u);
  EXPECT_EQ(t.fields()[0].name, "v");
  EXPECT_FALSE(damped.linear());
  EXPECT_TRUE(damped.symmetric());
  EXPECT_FALSE(damped.reads_displacement());
  EXPECT_EQ(damped.data(), (std::vector<std::string>{"c_nu"}));
  EXPECT_EQ(damped.law().c_nu, kCNu);

  NormalResponseBrick<NormalCompliance> compliance("contact", {.displacement = "u_total"});
  compliance.update(constants_of(NormalCompliance{1e9, 1.0, 0.0}));
  const Term& tc = *compliance.terms()[0].term;
  ASSERT_EQ(tc.fields().size(), 2u);
  EXPECT_EQ(tc.fields()[1].name, "u_total");
  ASSERT_EQ(tc.couplings().size(), 1u);
  EXPECT_EQ(tc.couplings()[0].test, 0);
  EXPECT_EQ(tc.couplings()[0].trial, 1);
  EXPECT_TRUE(compliance.reads_displacement());
  EXPECT_EQ(compliance.data(), (std::vector<std::string>{"c_nu", "m", "gap"}));
  EXPECT_EQ(compliance.law().c_nu, 1e9);
}

TEST(NormalResponseBrick, ReadsItsParametersUnderTheirModelNames) {
  // Two contact regions with their own coefficients: the left one reads c_nu_left.
  const ContactCase c = contact_cases()[0];
  NormalResponseBrick<LinearDampedResponse> left(c.side, {}, ParameterNames{{{"c_nu", "c_nu_left"}}});
  EXPECT_EQ(left.data(), (std::vector<std::string>{"c_nu_left"}));
  left.update(ConstantTable{}.set("c_nu", 1.0).set("c_nu_left", kCNu));
  EXPECT_EQ(left.law().c_nu, kCNu);
  const auto r = residuals(left, c, c.uniform(0.3 * c.normal));
  const double expected = kCNu * 0.3 * c.side_measure();
  EXPECT_NEAR(c.resultant(r.at("v"), "v").dot(c.normal), expected, 1e-12 * expected);
}

TEST(NormalResponseBrick, TangentMatchesFiniteDifferences) {
  for (const ContactCase& c : contact_cases()) {
    const State pressed = c.uniform(0.3 * c.normal, 0.05 * c.normal);
    const ConstantTable damped_data = constants_of(LinearDampedResponse{kCNu});
    NormalResponseBrick<LinearDampedResponse> damped(c.side);
    expect_check_brick_passes(damped, damped_data, c);
    EXPECT_GT(residual_size(damped, c, pressed, "v"), 0.0) << c.label;
    const ConstantTable power_data = constants_of(PowerDampedResponse{kCNu, 2.5});
    NormalResponseBrick<PowerDampedResponse> power(c.side);
    expect_check_brick_passes(power, power_data, c);
    EXPECT_GT(residual_size(power, c, pressed, "v"), 0.0) << c.label;
    const ConstantTable compliance_data = constants_of(NormalCompliance{1e9, 2.0, 0.01});
    NormalResponseBrick<NormalCompliance> compliance(c.side);
    expect_check_brick_passes(compliance, compliance_data, c);
    EXPECT_GT(residual_size(compliance, c, pressed, "v"), 0.0) << c.label;
  }
}

// ---- friction -----------------------------------------------------------------------------------------

TEST(FrictionBrick, ViscousFrictionGivesCTauTimesSlipTimesMeasure) {
  const double slip = 0.4;
  for (const ContactCase& c : contact_cases()) {
    FrictionBrick<ViscousFriction> brick(c.side);
    brick.update(constants_of(ViscousFriction{kCTau}));
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
    const ConstantTable data = constants_of(RegularizedCoulomb{mu, eps}, LinearDampedResponse{kCNu});
    const auto normal = updated<NormalResponseBrick<LinearDampedResponse>>(data, c.side);
    const auto coulomb = updated<FrictionBrick<RegularizedCoulomb>>(data, c.side, normal);
    const auto pressed = residuals(*coulomb, c, c.uniform(slip * c.tangent + speed * c.normal));
    const double expected = mu * kCNu * speed * direction * c.side_measure();
    EXPECT_NEAR(c.resultant(pressed.at("v"), "v").dot(c.tangent), expected, 1e-12 * expected) << c.label;
    const auto lifted = residuals(*coulomb, c, c.uniform(slip * c.tangent - speed * c.normal));
    EXPECT_EQ(lifted.at("v").cwiseAbs().maxCoeff(), 0.0) << c.label;

    const ConstantTable compliance_data = constants_of(RegularizedCoulomb{mu, eps}, NormalCompliance{1e9, 1.0, 0.01});
    const auto compliance = updated<NormalResponseBrick<NormalCompliance>>(compliance_data, c.side);
    const auto on_compliance = updated<FrictionBrick<RegularizedCoulomb>>(compliance_data, c.side, compliance);
    const auto r = residuals(*on_compliance, c, c.uniform(slip * c.tangent, 0.05 * c.normal));
    const double expected_compliance = mu * 1e9 * 0.04 * direction * c.side_measure();
    EXPECT_NEAR(c.resultant(r.at("v"), "v").dot(c.tangent), expected_compliance, 1e-12 * expected_compliance)
        << c.label;

    FrictionBrick<RegularizedTresca> tresca(c.side);
    tresca.update(constants_of(RegularizedTresca{g, eps}));
    const auto rt = residuals(tresca, c, c.uniform(slip * c.tangent));
    EXPECT_NEAR(c.resultant(rt.at("v"), "v").dot(c.tangent), g * direction * c.side_measure(), 1e-12) << c.label;
  }
}

TEST(FrictionBrick, CoulombReadsCNuFromTheModel) {
  // |p_tau| = mu c_nu v_nu |v_tau| / sqrt(|v_tau|^2 + eps^2): a new c_nu in the model's constants scales
  // the friction of a pressed, sliding surface by the same factor, through the paired normal brick.
  const double slip = 0.4, speed = 0.3, mu = 0.3, eps = 1e-4;
  for (const ContactCase& c : contact_cases()) {
    ConstantTable data = constants_of(RegularizedCoulomb{mu, eps}, LinearDampedResponse{kCNu});
    const auto normal = updated<NormalResponseBrick<LinearDampedResponse>>(data, c.side);
    const auto coulomb = updated<FrictionBrick<RegularizedCoulomb>>(data, c.side, normal);
    const Term* term = coulomb->terms()[0].term.get();
    const State state = c.uniform(slip * c.tangent + speed * c.normal);
    const Eigen::VectorXd before = residuals(*coulomb, c, state).at("v");
    const double per_c_nu = mu * speed * slip / std::sqrt(slip * slip + eps * eps) * c.side_measure();
    EXPECT_NEAR(c.resultant(before, "v").dot(c.tangent), per_c_nu * kCNu, 1e-12 * per_c_nu * kCNu) << c.label;

    // The model updates every brick that lists the changed constant: here both.
    data.set("c_nu", 2.5 * kCNu);
    for (Brick* brick : std::vector<Brick*>{normal.get(), coulomb.get()}) {
      const auto names = brick->data();
      ASSERT_NE(std::find(names.begin(), names.end(), "c_nu"), names.end()) << brick->name();
      brick->update(data);
    }
    const Eigen::VectorXd after = residuals(*coulomb, c, state).at("v");
    EXPECT_NEAR(c.resultant(after, "v").dot(c.tangent), per_c_nu * 2.5 * kCNu, 1e-12 * per_c_nu * 2.5 * kCNu)
        << c.label;
    EXPECT_LE((after - 2.5 * before).cwiseAbs().maxCoeff(), 1e-12 * after.cwiseAbs().maxCoeff()) << c.label;
    // The parameter change keeps the term (its pattern and slot maps survive).
    EXPECT_EQ(coulomb->terms()[0].term.get(), term) << c.label;

    // mu, read by the friction brick itself.
    data.set("mu", 2 * mu);
    coulomb->update(data);
    EXPECT_EQ(coulomb->law().mu, 2 * mu);
    const Eigen::VectorXd doubled = residuals(*coulomb, c, state).at("v");
    EXPECT_LE((doubled - 2.0 * after).cwiseAbs().maxCoeff(), 1e-12 * doubled.cwiseAbs().maxCoeff()) << c.label;
  }
}

TEST(FrictionBrick, PairsWithANormalBrickExactlyWhenTheLawReadsThePressure) {
  auto expect_message = [](auto build, const std::vector<std::string>& parts) {
    try {
      build();
      ADD_FAILURE() << "accepted: " << parts.back();
    } catch (const Error& e) {
      for (const std::string& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  const auto normal = std::make_shared<NormalResponseBrick<LinearDampedResponse>>();
  expect_message([] { FrictionBrick<RegularizedCoulomb> brick("contact"); },
                 {"brick 'friction on contact'", "reads the contact pressure", "pair it with the normal brick"});
  expect_message([&] { FrictionBrick<ViscousFriction> brick("contact", normal); },
                 {"brick 'friction on contact'", "reads no contact pressure", "takes no normal brick"});
  expect_message([&] { FrictionBrick<RegularizedTresca> brick("contact", normal); },
                 {"brick 'friction on contact'", "takes no normal brick"});
  expect_message([] { ConductiveFoundationBrick<PressureActivatedConductance> brick("contact"); },
                 {"brick 'conductive foundation on contact'", "pair it with the normal brick"});
  expect_message([&] { ConductiveFoundationBrick<LinearConductance> brick("contact", normal); },
                 {"brick 'conductive foundation on contact'", "takes no normal brick"});
  EXPECT_NO_THROW((FrictionBrick<RegularizedCoulomb>("contact", normal)));
  EXPECT_NO_THROW((FrictionBrick<ViscousFriction>("contact")));
}

TEST(FrictionBrick, ListsItsOwnAndTheNormalLawsConstants) {
  const auto damped = std::make_shared<NormalResponseBrick<LinearDampedResponse>>();
  const FrictionBrick<RegularizedCoulomb> coulomb("contact", damped);
  EXPECT_EQ(coulomb.data(), (std::vector<std::string>{"mu", "eps", "c_nu"}));
  const auto compliance = std::make_shared<NormalResponseBrick<NormalCompliance>>();
  const FrictionBrick<RegularizedCoulomb> on_compliance("contact", compliance);
  EXPECT_EQ(on_compliance.data(), (std::vector<std::string>{"mu", "eps", "c_nu", "m", "gap"}));
  // Renamed constants, on either brick.
  const auto left = std::make_shared<NormalResponseBrick<LinearDampedResponse>>(
      "left", ContactFields{}, ParameterNames{{{"c_nu", "c_nu_left"}}});
  const FrictionBrick<RegularizedCoulomb> left_friction("left", left, {}, ParameterNames{{{"mu", "mu_left"}}});
  EXPECT_EQ(left_friction.data(), (std::vector<std::string>{"mu_left", "eps", "c_nu_left"}));
  EXPECT_EQ(FrictionBrick<ViscousFriction>().data(), (std::vector<std::string>{"c_tau"}));
  EXPECT_EQ(FrictionBrick<RegularizedTresca>().data(), (std::vector<std::string>{"g", "eps"}));
  EXPECT_EQ(ConductiveFoundationBrick<LinearConductance>().data(), (std::vector<std::string>{"k_e", "phi_f"}));
  EXPECT_EQ(ConductiveFoundationBrick<PressureActivatedConductance>("contact", damped).data(),
            (std::vector<std::string>{"k_e", "phi_f", "p_ref", "c_nu"}));
}

TEST(FrictionBrick, DeclaresFieldsAndTraitsFromTheLaws) {
  const auto viscous = updated<FrictionBrick<ViscousFriction>>(constants_of(ViscousFriction{kCTau}));
  EXPECT_TRUE(viscous->linear());
  EXPECT_TRUE(viscous->symmetric());
  EXPECT_EQ(viscous->terms()[0].term->fields().size(), 1u);

  const ConstantTable data = constants_of(RegularizedCoulomb{0.3, 1e-4}, LinearDampedResponse{kCNu});
  const auto normal = updated<NormalResponseBrick<LinearDampedResponse>>(data, "contact");
  const auto coulomb = updated<FrictionBrick<RegularizedCoulomb>>(data, "contact", normal);
  EXPECT_FALSE(coulomb->linear());
  EXPECT_FALSE(coulomb->symmetric());  // the pressure couples the normal velocity into the tangential rows
  EXPECT_EQ(coulomb->terms()[0].term->fields().size(), 1u);

  const ConstantTable compliance_data = constants_of(RegularizedCoulomb{0.3, 1e-4}, NormalCompliance{1e9, 1.0, 0.0});
  const auto compliance = updated<NormalResponseBrick<NormalCompliance>>(compliance_data, "contact");
  const auto on_u = updated<FrictionBrick<RegularizedCoulomb>>(compliance_data, "contact", compliance);
  const Term& t = *on_u->terms()[0].term;
  ASSERT_EQ(t.fields().size(), 2u);
  EXPECT_EQ(t.fields()[1].name, "u");
  EXPECT_EQ(t.couplings().size(), 2u);
}

TEST(FrictionBrick, TangentMatchesFiniteDifferences) {
  // eps comparable to the slip velocities: with eps << |v_tau| the friction force saturates, its slope
  // eps^2 / |v_tau|^3 drowns in the round-off of a finite difference of the force itself.
  const double eps = 0.3;
  for (const ContactCase& c : contact_cases()) {
    const State pressed = c.uniform(0.3 * c.normal + 0.4 * c.tangent, 0.05 * c.normal);
    const ConstantTable viscous_data = constants_of(ViscousFriction{kCTau});
    FrictionBrick<ViscousFriction> viscous(c.side);
    expect_check_brick_passes(viscous, viscous_data, c);
    EXPECT_GT(residual_size(viscous, c, pressed, "v"), 0.0) << c.label;

    const ConstantTable coulomb_data = constants_of(RegularizedCoulomb{0.3, eps}, LinearDampedResponse{kCNu});
    const auto normal = updated<NormalResponseBrick<LinearDampedResponse>>(coulomb_data, c.side);
    FrictionBrick<RegularizedCoulomb> coulomb(c.side, normal);
    expect_check_brick_passes(coulomb, coulomb_data, c);
    EXPECT_GT(residual_size(coulomb, c, pressed, "v"), 0.0) << c.label;

    const ConstantTable compliance_data = constants_of(RegularizedCoulomb{0.3, eps}, NormalCompliance{1e9, 2.0, 0.01});
    const auto compliance = updated<NormalResponseBrick<NormalCompliance>>(compliance_data, c.side);
    FrictionBrick<RegularizedCoulomb> on_compliance(c.side, compliance);
    expect_check_brick_passes(on_compliance, compliance_data, c);
    EXPECT_GT(residual_size(on_compliance, c, pressed, "v"), 0.0) << c.label;

    const ConstantTable tresca_data = constants_of(RegularizedTresca{5.0, eps});
    FrictionBrick<RegularizedTresca> tresca(c.side);
    expect_check_brick_passes(tresca, tresca_data, c);
    EXPECT_GT(residual_size(tresca, c, pressed, "v"), 0.0) << c.label;
  }
}

// Coulomb friction saturated by tanh, a user's law with fixed values: p_tau = mu p tanh(|v_tau| / eps)
// v_tau / |v_tau|. `pressure_slope` scales the derivative in the pressure (1: correct), to make a wrong
// tangent in the columns of the normal velocity.
struct TanhCoulomb {
  double mu = 0.3, eps = 0.1, pressure_slope = 1.0;
  static constexpr bool dissipative = true;
  static constexpr bool uses_normal_pressure = true;
  template <class S> void operator()(const S* r, int dim, const S& normal_pressure, S* out) const {
    const S p = chain_rule(normal_pressure, value_of(normal_pressure), pressure_slope);
    const double e = eps;
    scaled_direction(
        r, dim,
        [e](const auto& rho) {
          using std::tanh;
          return tanh(rho / e);
        },
        out);
    for (int i = 0; i < dim; ++i) out[i] *= mu * p;
  }
};

TEST(FrictionBrick, SaturatedFrictionPassesAndAWrongTangentIsCaught) {
  // |v_tau| >= 0.2 = 2 eps: the force is nearly saturated, its slope along v_tau small next to the
  // force, so a finite difference of the residual at the default step is mostly round-off.
  for (const ContactCase& c : contact_cases()) {
    const ConstantTable data = constants_of(LinearDampedResponse{kCNu});
    const auto normal = updated<NormalResponseBrick<LinearDampedResponse>>(data, c.side);
    BrickCheckSetup setup = c.setup;
    setup.ranges["v"] = {-1.0, -0.2};  // into the foundation, |v_tau| >= 0.2
    FrictionBrick<TanhCoulomb> saturated(TanhCoulomb{}, c.side, normal);
    const BrickCheckReport report = check_brick(saturated, data, setup);
    EXPECT_TRUE(report.ok()) << c.label << ": " << report;
    EXPECT_LT(report.max_tangent_error, 1e-7) << c.label << ": " << report;
    // The same law with its pressure derivative 1% off: the columns of the normal velocity are wrong.
    FrictionBrick<TanhCoulomb> wrong(TanhCoulomb{.pressure_slope = 1.01}, c.side, normal);
    const BrickCheckReport caught = check_brick(wrong, data, setup);
    EXPECT_FALSE(caught.ok()) << c.label << ": " << caught;
    EXPECT_GT(caught.max_tangent_error, 5e-3) << c.label << ": " << caught;
  }
}

// ---- conductive foundation ----------------------------------------------------------------------------

TEST(ConductiveFoundationBrick, LinearConductanceGivesKeTimesPotentialDropTimesMeasure) {
  for (const ContactCase& c : contact_cases()) {
    ConductiveFoundationBrick<LinearConductance> brick(c.side);
    brick.update(constants_of(LinearConductance{kKe, kPhiF}));
    const auto r = residuals(brick, c, c.uniform(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 2.0));
    const double expected = kKe * (2.0 - kPhiF) * c.side_measure();
    EXPECT_NEAR(r.at("phi").sum(), expected, 1e-12 * expected) << c.label;
  }
}

TEST(ConductiveFoundationBrick, PressureActivatedConductanceNeedsPressure) {
  // p = c_nu * 0.3 = 3 p_ref: s(p) = 9 / 10.
  const ConstantTable data = constants_of(PressureActivatedConductance{kKe, kPhiF, 1e11}, LinearDampedResponse{kCNu});
  for (const ContactCase& c : contact_cases()) {
    const auto normal = updated<NormalResponseBrick<LinearDampedResponse>>(data, c.side);
    const auto brick = updated<ConductiveFoundationBrick<PressureActivatedConductance>>(data, c.side, normal);
    const auto pressed = residuals(*brick, c, c.uniform(0.3 * c.normal, Eigen::Vector3d::Zero(), 2.0));
    const double expected = 0.9 * kKe * (2.0 - kPhiF) * c.side_measure();
    EXPECT_NEAR(pressed.at("phi").sum(), expected, 1e-12 * expected) << c.label;
    const auto lifted = residuals(*brick, c, c.uniform(-0.3 * c.normal, Eigen::Vector3d::Zero(), 2.0));
    EXPECT_EQ(lifted.at("phi").cwiseAbs().maxCoeff(), 0.0) << c.label;
  }
}

TEST(ConductiveFoundationBrick, NoFluxWhereThereIsNoPressure) {
  // The bottom side presses where x > 0.5 and lifts off elsewhere: the element [0, 0.5] carries no current,
  // so the dofs only it touches (x < 0.5) get no flux, while x = 1 does.
  const ConstantTable data = constants_of(PressureActivatedConductance{kKe, kPhiF, 1e11}, LinearDampedResponse{kCNu});
  for (const ContactCase& c : contact_cases()) {
    if (c.dim() != 2) continue;
    const auto normal = updated<NormalResponseBrick<LinearDampedResponse>>(data, c.side);
    const auto brick = updated<ConductiveFoundationBrick<PressureActivatedConductance>>(data, c.side, normal);
    State state = c.uniform(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 2.0);
    state["v"] = c.space("v").interpolate([](const double* x, double* out) {
      out[0] = 0;
      out[1] = x[0] > 0.5 ? -0.3 : 0.3;
    });
    const Eigen::VectorXd r = residuals(*brick, c, state).at("phi");
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
  const auto linear =
      updated<ConductiveFoundationBrick<LinearConductance>>(constants_of(LinearConductance{kKe, kPhiF}));
  EXPECT_TRUE(linear->linear());
  EXPECT_TRUE(linear->symmetric());
  ASSERT_EQ(linear->terms()[0].term->fields().size(), 1u);
  EXPECT_EQ(linear->terms()[0].term->fields()[0].name, "phi");

  const ConstantTable data = constants_of(PressureActivatedConductance{kKe, kPhiF, 1e6}, LinearDampedResponse{kCNu});
  const auto normal = updated<NormalResponseBrick<LinearDampedResponse>>(data, "contact");
  const auto activated = updated<ConductiveFoundationBrick<PressureActivatedConductance>>(data, "contact", normal);
  EXPECT_FALSE(activated->linear());
  EXPECT_FALSE(activated->symmetric());
  const Term& t = *activated->terms()[0].term;
  ASSERT_EQ(t.fields().size(), 2u);
  EXPECT_EQ(t.fields()[1].name, "v");
  EXPECT_EQ(t.couplings().size(), 2u);

  const ConstantTable compliance_data =
      constants_of(PressureActivatedConductance{kKe, kPhiF, 1e6}, NormalCompliance{1e9, 1.0, 0.0});
  const auto compliance = updated<NormalResponseBrick<NormalCompliance>>(compliance_data, "contact");
  const auto on_u =
      updated<ConductiveFoundationBrick<PressureActivatedConductance>>(compliance_data, "contact", compliance);
  EXPECT_EQ(on_u->terms()[0].term->fields()[1].name, "u");
}

TEST(ConductiveFoundationBrick, TangentMatchesFiniteDifferences) {
  for (const ContactCase& c : contact_cases()) {
    const State pressed = c.uniform(0.3 * c.normal, 0.05 * c.normal, 2.0);
    const ConstantTable linear_data = constants_of(LinearConductance{kKe, kPhiF});
    ConductiveFoundationBrick<LinearConductance> linear(c.side);
    expect_check_brick_passes(linear, linear_data, c);
    EXPECT_GT(residual_size(linear, c, pressed, "phi"), 0.0) << c.label;

    const ConstantTable activated_data =
        constants_of(PressureActivatedConductance{kKe, kPhiF, 1e11}, LinearDampedResponse{kCNu});
    const auto normal = updated<NormalResponseBrick<LinearDampedResponse>>(activated_data, c.side);
    ConductiveFoundationBrick<PressureActivatedConductance> activated(c.side, normal);
    expect_check_brick_passes(activated, activated_data, c);
    EXPECT_GT(residual_size(activated, c, pressed, "phi"), 0.0) << c.label;

    const ConstantTable on_u_data =
        constants_of(PressureActivatedConductance{kKe, kPhiF, 1e8}, NormalCompliance{1e9, 2.0, 0.01});
    const auto compliance = updated<NormalResponseBrick<NormalCompliance>>(on_u_data, c.side);
    ConductiveFoundationBrick<PressureActivatedConductance> on_u(c.side, compliance);
    expect_check_brick_passes(on_u, on_u_data, c);
    EXPECT_GT(residual_size(on_u, c, pressed, "phi"), 0.0) << c.label;
  }
}

// ---- laws that declare no parameters keep the values they are built with --------------------------------

// A user's quick laws: no parameters(), so the bricks hold them by value and read no model constants.
struct UserDampedResponse {
  double c_nu;
  template <class S> S operator()(const S& r) const { return r < 0.0 ? S(0.0) : c_nu * r; }
};
struct UserCoulomb {
  double mu, eps;
  static constexpr bool uses_normal_pressure = true;
  template <class S> void operator()(const S* r, int dim, const S& p, S* out) const {
    RegularizedCoulomb{mu, eps}(r, dim, p, out);
  }
};
struct UserFoundation {
  double k_e, phi_f;
  template <class S> S operator()(const S& phi, const S&) const { return k_e * (phi - phi_f); }
};

TEST(ContactBricks, LawsWithoutDeclaredParametersKeepTheirValues) {
  const double slip = 0.4, speed = 0.3, mu = 0.3, eps = 1e-4;
  for (const ContactCase& c : contact_cases()) {
    const auto normal = std::make_shared<NormalResponseBrick<UserDampedResponse>>(UserDampedResponse{kCNu}, c.side);
    EXPECT_TRUE(normal->data().empty());
    normal->update(ConstantTable{});
    const FrictionBrick<UserCoulomb> friction(UserCoulomb{mu, eps}, c.side, normal);
    EXPECT_TRUE(friction.data().empty());
    const ConductiveFoundationBrick<UserFoundation> foundation(UserFoundation{kKe, kPhiF}, c.side);
    EXPECT_TRUE(foundation.data().empty());

    // The same residuals as the library's laws with these values read from the model.
    const ConstantTable data =
        constants_of(LinearDampedResponse{kCNu}, RegularizedCoulomb{mu, eps}, LinearConductance{kKe, kPhiF});
    const auto library_normal = updated<NormalResponseBrick<LinearDampedResponse>>(data, c.side);
    const auto library_friction = updated<FrictionBrick<RegularizedCoulomb>>(data, c.side, library_normal);
    const auto library_foundation = updated<ConductiveFoundationBrick<LinearConductance>>(data, c.side);
    const State state = c.uniform(slip * c.tangent + speed * c.normal, Eigen::Vector3d::Zero(), 2.0);
    auto difference = [&](const Brick& a, const Brick& b, const std::string& field) {
      const Eigen::VectorXd ra = residuals(a, c, state).at(field), rb = residuals(b, c, state).at(field);
      return (ra - rb).cwiseAbs().maxCoeff() / rb.cwiseAbs().maxCoeff();
    };
    EXPECT_LT(difference(*normal, *library_normal, "v"), 1e-14) << c.label;
    EXPECT_LT(difference(friction, *library_friction, "v"), 1e-14) << c.label;
    EXPECT_LT(difference(foundation, *library_foundation, "phi"), 1e-14) << c.label;
    // Updating from any constants leaves them as they were built.
    normal->update(constants_of(LinearDampedResponse{1.0}));
    EXPECT_EQ(normal->law().c_nu, kCNu);
  }
}

// ---- parameters and diagnostics -----------------------------------------------------------------------

TEST(ContactBricks, RejectBadLawParametersNamingBrickAndParameter) {
  // Bricks read their parameters in update(): it is update() that refuses a constant out of its range,
  // naming the brick, the model constant, the parameter and the value.
  auto expect_message = [](Brick& brick, const DataView& data, const std::vector<std::string>& parts) {
    try {
      brick.update(data);
      ADD_FAILURE() << brick.name() << " accepted " << parts.back();
    } catch (const Error& e) {
      for (const std::string& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  NormalResponseBrick<LinearDampedResponse> normal;
  expect_message(normal, constants_of(LinearDampedResponse{-1.0}),
                 {"brick 'normal response on contact'", "model constant 'c_nu'", "c_nu must be >= 0, got -1"});
  NormalResponseBrick<LinearDampedResponse> left("contact", {}, ParameterNames{{{"c_nu", "c_nu_left"}}});
  expect_message(left, ConstantTable{}.set("c_nu", kCNu).set("c_nu_left", -1.0),
                 {"brick 'normal response on contact'", "model constant 'c_nu_left'", "c_nu must be >= 0, got -1"});

  const auto paired = std::make_shared<NormalResponseBrick<LinearDampedResponse>>();
  FrictionBrick<RegularizedCoulomb> coulomb("contact", paired);
  expect_message(coulomb, constants_of(RegularizedCoulomb{0.3, 0.0}, LinearDampedResponse{kCNu}),
                 {"brick 'friction on contact'", "model constant 'eps'", "eps must be > 0, got 0"});
  // A bad c_nu of the normal law that Coulomb reads is refused by the normal brick, which reads it: the
  // friction brick lists c_nu among its data, so a model updates both when it changes.
  const ConstantTable bad_normal = constants_of(RegularizedCoulomb{0.3, 1e-3}, LinearDampedResponse{-kCNu});
  expect_message(*paired, bad_normal,
                 {"brick 'normal response on contact'", "model constant 'c_nu'", "c_nu must be >= 0, got -1e+12"});
  const auto data = coulomb.data();
  EXPECT_NE(std::find(data.begin(), data.end(), "c_nu"), data.end());

  ConductiveFoundationBrick<LinearConductance> foundation;
  expect_message(foundation, constants_of(LinearConductance{-1.0, kPhiF}),
                 {"brick 'conductive foundation on contact'", "model constant 'k_e'", "k_e must be >= 0, got -1"});
}

TEST(ContactStatus, CountsPressedAndSlidingNodes) {
  const ContactCase c = contact_cases()[0];  // bottom nodes at x = 0, 0.5, 1
  const Eigen::VectorXd v = c.space("v").interpolate([](const double* x, double* out) {
    out[0] = x[0] == 1.0 ? 0.1 : 0.0;   // slides at x = 1
    out[1] = x[0] == 0.0 ? 0.2 : -0.2;  // lifts off at x = 0
  });
  const auto normal =
      updated<NormalResponseBrick<LinearDampedResponse>>(constants_of(LinearDampedResponse{kCNu}), c.side);
  const ContactNodes nodes = contact_nodes(c.space("v"), c.side);
  for (const auto& n : nodes.normals) {
    EXPECT_EQ(n[0], 0.0);
    EXPECT_EQ(n[1], -1.0);
  }
  const ContactStatus status = contact_status(*normal, c.space("v"), nodes, v, v, 1e-6, 0.0);
  EXPECT_EQ(status.nodes, 3);
  EXPECT_EQ(status.in_contact, 2);
  EXPECT_EQ(status.sliding, 1);
  EXPECT_EQ(status.sticking(), 1);
}

// ---- the law registries -------------------------------------------------------------------------------

template <class Factory>
void expect_registered(const Registry<Factory>& registry, const std::vector<std::string>& names) {
  for (const std::string& name : names) EXPECT_NE(registry.find(name), nullptr) << registry.kind() << " " << name;
}

template <class Law, class Factory>
void expect_declares_like_the_law(const Registry<Factory>& registry, const std::string& name) {
  const auto* entry = registry.find(name);
  ASSERT_NE(entry, nullptr) << name;
  const std::vector<ParameterDeclaration> declared = parameter_declarations<Law>();
  ASSERT_EQ(entry->parameters.size(), declared.size()) << name;
  for (size_t i = 0; i < declared.size(); ++i) EXPECT_EQ(entry->parameters[i].name, declared[i].name) << name;
  EXPECT_FALSE(entry->doc.empty()) << name;
}

TEST(LawRegistries, HoldTheBuiltInLaws) {
  expect_registered(normal_law_registry(), {"linear_damped", "power_damped", "normal_compliance"});
  expect_registered(friction_law_registry(), {"none", "viscous", "coulomb", "tresca", "coulomb_exact"});
  expect_registered(foundation_law_registry(), {"insulated", "conductive", "pressure_activated"});
  expect_declares_like_the_law<LinearDampedResponse>(normal_law_registry(), "linear_damped");
  expect_declares_like_the_law<PowerDampedResponse>(normal_law_registry(), "power_damped");
  expect_declares_like_the_law<NormalCompliance>(normal_law_registry(), "normal_compliance");
  expect_declares_like_the_law<ViscousFriction>(friction_law_registry(), "viscous");
  expect_declares_like_the_law<RegularizedCoulomb>(friction_law_registry(), "coulomb");
  expect_declares_like_the_law<RegularizedTresca>(friction_law_registry(), "tresca");
  expect_declares_like_the_law<AugmentedCoulomb>(friction_law_registry(), "coulomb_exact");
  expect_declares_like_the_law<LinearConductance>(foundation_law_registry(), "conductive");
  expect_declares_like_the_law<PressureActivatedConductance>(foundation_law_registry(), "pressure_activated");
  EXPECT_TRUE(friction_law_registry().find("none")->parameters.empty());
  EXPECT_TRUE(foundation_law_registry().find("insulated")->parameters.empty());
  // An unknown name is refused with the known ones listed.
  try {
    normal_law_registry().at("hertz", "contact.law_normal");
    ADD_FAILURE() << "found a normal law 'hertz'";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'hertz'"), std::string::npos) << what;
    EXPECT_NE(what.find("linear_damped"), std::string::npos) << what;
  }
}

// The entry's brick and the brick built by hand, updated from the same constants, give the same residual.
void expect_same_residual(const Brick& from_registry, const Brick& by_hand, const ContactCase& c, const State& state,
                          const std::string& field, const std::string& what) {
  EXPECT_EQ(from_registry.name(), by_hand.name()) << what;
  EXPECT_EQ(from_registry.data(), by_hand.data()) << what;
  EXPECT_EQ(from_registry.linear(), by_hand.linear()) << what;
  EXPECT_EQ(from_registry.symmetric(), by_hand.symmetric()) << what;
  const Eigen::VectorXd a = residuals(from_registry, c, state).at(field);
  const Eigen::VectorXd b = residuals(by_hand, c, state).at(field);
  EXPECT_GT(b.cwiseAbs().maxCoeff(), 0.0) << what;
  EXPECT_EQ((a - b).cwiseAbs().maxCoeff(), 0.0) << what;
}

TEST(LawRegistries, FactoriesMakeTheBricksBuiltByHand) {
  const double mu = 0.3, eps = 1e-4;
  for (const ContactCase& c : contact_cases()) {
    const ContactSurface surface{c.side, {}, {}};
    const State state = c.uniform(0.3 * c.normal + 0.4 * c.tangent, 0.05 * c.normal, 2.0);
    const ConstantTable data = constants_of(LinearDampedResponse{kCNu}, RegularizedCoulomb{mu, eps},
                                            ViscousFriction{kCTau}, PressureActivatedConductance{kKe, kPhiF, 1e11});
    const std::string label = c.label + ": ";

    // Normal laws.
    const auto normal = normal_law_registry().at("linear_damped", "test").create(surface);
    ASSERT_NE(normal, nullptr);
    EXPECT_EQ(normal->region(), c.side);
    normal->update(data);
    const auto normal_by_hand = updated<NormalResponseBrick<LinearDampedResponse>>(data, c.side);
    expect_same_residual(*normal, *normal_by_hand, c, state, "v", label + "linear_damped");

    const ConstantTable power_data = constants_of(PowerDampedResponse{kCNu, 2.0});
    const auto power = normal_law_registry().at("power_damped", "test").create(surface);
    power->update(power_data);
    expect_same_residual(*power, *updated<NormalResponseBrick<PowerDampedResponse>>(power_data, c.side), c, state, "v",
                         label + "power_damped");

    const ConstantTable compliance_data = constants_of(NormalCompliance{1e9, 1.5, 0.01});
    const auto compliance = normal_law_registry().at("normal_compliance", "test").create(surface);
    compliance->update(compliance_data);
    EXPECT_TRUE(compliance->reads_displacement());
    expect_same_residual(*compliance, *updated<NormalResponseBrick<NormalCompliance>>(compliance_data, c.side), c,
                         state, "v", label + "normal_compliance");

    // Friction laws, paired with the registry's normal brick.
    EXPECT_EQ(friction_law_registry().at("none", "test").create(surface, normal), nullptr);
    const auto coulomb = friction_law_registry().at("coulomb", "test").create(surface, normal);
    ASSERT_NE(coulomb, nullptr);
    coulomb->update(data);
    expect_same_residual(*coulomb, *updated<FrictionBrick<RegularizedCoulomb>>(data, c.side, normal_by_hand), c, state,
                         "v", label + "coulomb");
    // A law that reads no pressure ignores the normal brick it is offered.
    const auto viscous = friction_law_registry().at("viscous", "test").create(surface, normal);
    ASSERT_NE(viscous, nullptr);
    viscous->update(data);
    expect_same_residual(*viscous, *updated<FrictionBrick<ViscousFriction>>(data, c.side), c, state, "v",
                         label + "viscous");
    const ConstantTable tresca_data = constants_of(RegularizedTresca{5.0, eps});
    const auto tresca = friction_law_registry().at("tresca", "test").create(surface, normal);
    tresca->update(tresca_data);
    expect_same_residual(*tresca, *updated<FrictionBrick<RegularizedTresca>>(tresca_data, c.side), c, state, "v",
                         label + "tresca");

    // Foundation laws.
    EXPECT_EQ(foundation_law_registry().at("insulated", "test").create(surface, normal), nullptr);
    const ConstantTable conductive_data = constants_of(LinearConductance{kKe, kPhiF});
    const auto conductive = foundation_law_registry().at("conductive", "test").create(surface, normal);
    conductive->update(conductive_data);
    expect_same_residual(*conductive, *updated<ConductiveFoundationBrick<LinearConductance>>(conductive_data, c.side),
                         c, state, "phi", label + "conductive");
    const auto activated = foundation_law_registry().at("pressure_activated", "test").create(surface, normal);
    activated->update(data);
    expect_same_residual(
        *activated, *updated<ConductiveFoundationBrick<PressureActivatedConductance>>(data, c.side, normal_by_hand), c,
        state, "phi", label + "pressure_activated");
  }
}

TEST(LawRegistries, FactoriesReadRenamedConstants) {
  const ContactSurface left{"left", {}, ParameterNames{{{"c_nu", "c_nu_left"}, {"mu", "mu_left"}}}};
  const auto normal = normal_law_registry().at("linear_damped", "test").create(left);
  EXPECT_EQ(normal->data(), (std::vector<std::string>{"c_nu_left"}));
  const auto coulomb = friction_law_registry().at("coulomb", "test").create(left, normal);
  EXPECT_EQ(coulomb->name(), "friction on left");
  EXPECT_EQ(coulomb->data(), (std::vector<std::string>{"mu_left", "eps", "c_nu_left"}));
}

// ---- the generic weak-form brick ----------------------------------------------------------------------

// The paper's electric contact term written by a user as a kernel.
struct UserConductance {
  double k_e, phi_f;
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    out.f0[0][0] = k_e * (in.value[0][0] - phi_f);
  }
};

// A nonlinear bulk term coupling both unknowns: f0_v = |v|^2 v + phi v, f1_phi = (1 + phi^2) grad phi.
struct NonlinearBulk {
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
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
    WeakFormBrick user(WeakForm{.name = "user conductance",
                                .fields = {{"phi"}},
                                .tests = {"phi"},
                                .couplings = {{"phi", "phi"}},
                                .region = c.side,
                                .integration = Integration::Faces,
                                .linear = true,
                                .symmetric = true},
                       UserConductance{kKe, kPhiF});
    ConductiveFoundationBrick<LinearConductance> library(c.side);
    library.update(constants_of(LinearConductance{kKe, kPhiF}));
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
  const WeakForm form{.name = "nonlinear bulk",
                      .fields = {{"v"}, {"phi", true}},
                      .tests = {"v", "phi"},
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
  EXPECT_THROW(
      WeakFormBrick(WeakForm{.name = "broken", .fields = {{"v"}, {"phi"}}, .tests = {"v"}, .couplings = {{"phi", "v"}}},
                    NonlinearBulk{}),
      Error);
}

}  // namespace
}  // namespace pc

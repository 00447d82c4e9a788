// The contact and foundation laws, each through the law checker (Dual derivatives against finite
// differences away from and at kinks, the affine and dissipative claims, finite values at extreme
// arguments), their closed forms, their declared parameters and the bricks' refusal of out-of-range model
// constants; and the checker itself against laws that break each of its rules.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "assembly/dual.hpp"
#include "assembly/error.hpp"
#include "assembly/parameters.hpp"
#include "bricks/conductive_foundation_brick.hpp"
#include "bricks/friction_brick.hpp"
#include "bricks/laws/direction.hpp"
#include "bricks/laws/foundation_laws.hpp"
#include "bricks/laws/friction_laws.hpp"
#include "bricks/laws/law_parameters.hpp"
#include "bricks/laws/normal_laws.hpp"
#include "bricks/normal_response_brick.hpp"
#include "bricks/testing/brick_checker.hpp"
#include "bricks/testing/law_checker.hpp"

namespace pc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- the paper's laws (12), (13), (10) with its data ------------------------------------------------

TEST(Laws, PaperLawsHaveTheirClosedForms) {
  using D = Dual<2>;
  const LinearDampedResponse p_nu{1e12};
  EXPECT_DOUBLE_EQ(p_nu(2e-3), 2e9);
  EXPECT_EQ(p_nu(-1.0), 0.0);
  EXPECT_EQ(p_nu(D::variable(0.0, 0)).d[0], 1e12);  // right-sided at the kink
  EXPECT_EQ(p_nu(D::variable(-1e-9, 0)).d[0], 0.0);

  const ViscousFriction p_tau{0.3};
  const double r[2] = {2.0, -1.0};
  double out[2];
  p_tau(r, 2, 0.0, out);
  EXPECT_DOUBLE_EQ(out[0], 0.6);
  EXPECT_DOUBLE_EQ(out[1], -0.3);

  const LinearConductance conductance{1.0, -48.0};
  EXPECT_EQ(conductance(2.0, 0.0), 50.0);
}

TEST(Laws, PaperLawsPassTheChecker) {
  const auto normal = check_scalar_law(LinearDampedResponse{1e12}, {.name = "LinearDampedResponse"});
  EXPECT_TRUE(normal.ok()) << normal;
  const auto friction = check_friction_law(ViscousFriction{0.3}, {.name = "ViscousFriction"});
  EXPECT_TRUE(friction.ok()) << friction;
  const auto foundation = check_foundation_law(LinearConductance{1.0, -48.0}, {.name = "LinearConductance"});
  EXPECT_TRUE(foundation.ok()) << foundation;
}

// ---- normal laws --------------------------------------------------------------------------------------

TEST(NormalLaws, PassTheChecker) {
  const auto stiff = check_scalar_law(LinearDampedResponse{1e16}, {.name = "stiff damped response"});
  EXPECT_TRUE(stiff.ok()) << stiff;
  // r_+^m with 1 < m < 2 has an unbounded second derivative at 0: the kink is checked by right-sided
  // quotients that converge as h^(m-1).
  for (double m : {1.0, 1.5, 2.0, 2.5, 3.0}) {
    const auto report = check_scalar_law(PowerDampedResponse{1e12, m}, {.name = message("PowerDampedResponse m = ", m),
                                                                        .extremes = {1e-300, 1e-12, 1e12, 1e90}});
    EXPECT_TRUE(report.ok()) << report;
  }
  const auto compliance = check_scalar_law(NormalCompliance{1e9, 2.0, 0.1},
                                           {.name = "NormalCompliance", .kinks = {0.1}, .extremes = {1e-300, 1e140}});
  EXPECT_TRUE(compliance.ok()) << compliance;
}

TEST(NormalLaws, ClosedForms) {
  const PowerDampedResponse power{3.0, 2.0};
  EXPECT_DOUBLE_EQ(power(0.5), 0.75);
  EXPECT_EQ(power(-0.5), 0.0);
  const NormalCompliance compliance{2.0, 1.0, 0.1};
  EXPECT_DOUBLE_EQ(compliance(0.4), 0.6);
  EXPECT_EQ(compliance(0.05), 0.0);  // within the gap: no contact
  EXPECT_TRUE(NormalCompliance::uses_displacement);
  EXPECT_FALSE(LinearDampedResponse::uses_displacement);
}

// ---- friction laws ------------------------------------------------------------------------------------

TEST(FrictionLaws, PassTheChecker) {
  for (double eps : {1e-2, 0.5}) {
    const auto coulomb =
        check_friction_law(RegularizedCoulomb{0.3, eps}, {.name = message("RegularizedCoulomb eps = ", eps)});
    EXPECT_TRUE(coulomb.ok()) << coulomb;
    const auto tresca =
        check_friction_law(RegularizedTresca{5.0, eps}, {.name = message("RegularizedTresca eps = ", eps)});
    EXPECT_TRUE(tresca.ok()) << tresca;
  }
  // Large pressures, as c_nu = 1e12 produces.
  const auto pressed =
      check_friction_law(RegularizedCoulomb{0.3, 1e-3}, {.name = "pressed Coulomb", .pressure_high = 1e12});
  EXPECT_TRUE(pressed.ok()) << pressed;
}

TEST(FrictionLaws, TinyRegularizationStaysFiniteAndDissipative) {
  // eps = 1e-12 is below any finite-difference step: only the claims and the extremes are checked.
  const LawCheckOptions options{.name = "eps = 1e-12", .derivatives = false};
  const auto coulomb = check_friction_law(RegularizedCoulomb{0.3, 1e-12}, options);
  EXPECT_TRUE(coulomb.ok()) << coulomb;
  const auto tresca = check_friction_law(RegularizedTresca{5.0, 1e-12}, options);
  EXPECT_TRUE(tresca.ok()) << tresca;
}

TEST(FrictionLaws, ClosedForms) {
  // Sliding fast (|r| >> eps) Coulomb gives mu p along r; Tresca g along r.
  const double r[3] = {3.0, 0.0, -4.0};
  double out[3];
  RegularizedCoulomb{0.5, 1e-9}(r, 3, 2.0, out);
  EXPECT_NEAR(out[0], 0.5 * 2.0 * 0.6, 1e-12);
  EXPECT_NEAR(out[2], -0.5 * 2.0 * 0.8, 1e-12);
  RegularizedTresca{7.0, 1e-9}(r, 3, 0.0, out);
  EXPECT_NEAR(out[0], 7.0 * 0.6, 1e-12);
  // |r|^2 would overflow here, and eps^2 underflow: the scaled norm needs neither.
  const double huge[2] = {1e300, -1e300};
  RegularizedTresca{7.0, 1e-200}(huge, 2, 0.0, out);
  EXPECT_NEAR(out[0], 7.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(out[1], -7.0 / std::sqrt(2.0), 1e-12);
  // At the stick state the regularized slope is threshold / eps.
  using D = Dual<2>;
  const D rd[2] = {D::variable(0.0, 0), D::variable(0.0, 1)};
  D td[2];
  RegularizedCoulomb{0.5, 1e-3}(rd, 2, D(4.0), td);
  EXPECT_DOUBLE_EQ(td[0].d[0], 0.5 * 4.0 / 1e-3);
  EXPECT_DOUBLE_EQ(td[0].d[1], 0.0);
  // Pressure 0 (no contact): no friction, but the right-sided slope in the pressure.
  const D v[2] = {D(1.0), D(0.0)};
  RegularizedCoulomb{0.5, 1e-9}(v, 2, D::variable(0.0, 0), td);
  EXPECT_EQ(td[0].v, 0.0);
  EXPECT_NEAR(td[0].d[0], 0.5, 1e-12);
}

// ---- the direction term g(|r|) r / |r| ------------------------------------------------------------------

template <int N> bool all_finite(const Dual<N>* x, int n) {
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(x[i].v)) return false;
    for (double d : x[i].d)
      if (!std::isfinite(d)) return false;
  }
  return true;
}

TEST(Direction, ScaledDirectionIsSafeAtZeroTinyAndHuge) {
  using D = Dual<3>;
  const double eps = 0.1;
  const auto tanh_of = [eps](const auto& rho) {
    using std::tanh;
    return tanh(rho / eps);
  };
  for (const int dim : {2, 3}) {
    // r = 0: the limit g'(0) r, with the derivative g'(0) I = I / eps.
    D zero[3] = {D::variable(0.0, 0), D::variable(0.0, 1), D::variable(0.0, 2)};
    D out[3];
    scaled_direction(zero, dim, tanh_of, out);
    ASSERT_TRUE(all_finite(out, dim)) << dim;
    for (int i = 0; i < dim; ++i) {
      EXPECT_EQ(out[i].v, 0.0);
      for (int j = 0; j < dim; ++j) EXPECT_NEAR(out[i].d[j], i == j ? 1 / eps : 0.0, 1e-12 / eps) << i << j;
    }
    // |r| = 1e-300 (|r|^2 underflows): value g'(0) r, derivative I / eps.
    D tiny[3] = {D::variable(1e-300, 0), D::variable(-1e-300, 1), D::variable(0.5e-300, 2)};
    scaled_direction(tiny, dim, tanh_of, out);
    ASSERT_TRUE(all_finite(out, dim)) << dim;
    for (int i = 0; i < dim; ++i) {
      EXPECT_NEAR(out[i].v, tiny[i].v / eps, 1e-12 * 1e-300 / eps);
      for (int j = 0; j < dim; ++j) EXPECT_NEAR(out[i].d[j], i == j ? 1 / eps : 0.0, 1e-9 / eps) << i << j;
    }
    // |r| = 1e300 (|r|^2 overflows): the unit vector r / |r|, derivative (I - e e^T) / |r|.
    D huge[3] = {D::variable(1e300, 0), D::variable(-1e300, 1), D::variable(2e300, 2)};
    scaled_direction(huge, dim, tanh_of, out);
    ASSERT_TRUE(all_finite(out, dim)) << dim;
    const double norm = dim == 2 ? std::sqrt(2.0) * 1e300 : std::sqrt(6.0) * 1e300;
    for (int i = 0; i < dim; ++i) {
      EXPECT_NEAR(out[i].v, huge[i].v / norm, 1e-15);
      for (int j = 0; j < dim; ++j) {
        const double expected = ((i == j ? 1.0 : 0.0) - huge[i].v / norm * huge[j].v / norm) / norm;
        EXPECT_NEAR(out[i].d[j], expected, 1e-12 / norm) << i << j;
      }
    }
  }
}

TEST(Direction, RegularizedDirectionIsSafeAtZeroTinyAndHuge) {
  using D = Dual<2>;
  for (const double eps : {1e-200, 1e-6, 0.5}) {
    D zero[2] = {D::variable(0.0, 0), D::variable(0.0, 1)}, out[2];
    regularized_direction(zero, 2, eps, out);
    ASSERT_TRUE(all_finite(out, 2)) << eps;
    EXPECT_EQ(out[0].v, 0.0);
    EXPECT_DOUBLE_EQ(out[0].d[0], 1 / eps);
    EXPECT_EQ(out[0].d[1], 0.0);
    D tiny[2] = {D::variable(1e-300, 0), D::variable(0.0, 1)};
    regularized_direction(tiny, 2, eps, out);
    ASSERT_TRUE(all_finite(out, 2)) << eps;
    EXPECT_NEAR(out[0].v, 1e-300 / eps, 1e-12 * 1e-300 / eps);
    EXPECT_NEAR(out[0].d[0], 1 / eps, 1e-9 / eps);
    D huge[2] = {D::variable(1e300, 0), D::variable(-1e300, 1)};
    regularized_direction(huge, 2, eps, out);
    ASSERT_TRUE(all_finite(out, 2)) << eps;
    EXPECT_NEAR(out[0].v, 1 / std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(out[1].v, -1 / std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(out[0].d[0], 0.5 / (std::sqrt(2.0) * 1e300), 1e-12 / 1e300);
  }
}

// ---- foundation laws ----------------------------------------------------------------------------------

TEST(FoundationLaws, PassTheChecker) {
  // The law reads the pressure as an argument; the normal law that produces it belongs to the normal brick.
  const PressureActivatedConductance unit{1.0, -48.0, 1.0};
  const auto report = check_foundation_law(unit, {.name = "PressureActivatedConductance", .pressure_high = 4});
  EXPECT_TRUE(report.ok()) << report;
  const PressureActivatedConductance paper_scale{1.0, -48.0, 1e6};
  const auto scaled = check_foundation_law(paper_scale, {.name = "p_ref = 1e6", .pressure_high = 4e6});
  EXPECT_TRUE(scaled.ok()) << scaled;
}

TEST(FoundationLaws, ClosedForms) {
  const PressureActivatedConductance law{2.0, -48.0, 3.0};
  EXPECT_EQ(law(2.0, 0.0), 0.0);   // no pressure, no current
  EXPECT_EQ(law(2.0, -5.0), 0.0);  // a negative pressure is no pressure
  EXPECT_DOUBLE_EQ(law(2.0, 3.0), 2.0 * 0.5 * 50.0);
  EXPECT_NEAR(law(2.0, 1e200), 2.0 * 50.0, 1e-12);
  EXPECT_TRUE(std::isfinite(law(1e150, 1e300)));
}

// ---- declared parameters --------------------------------------------------------------------------------

// What a declaration should say: the range, and the default (none: required).
struct ExpectedParameter {
  std::string name;
  Range range;
  std::optional<double> default_value;
};

template <class Law> void expect_declarations(const std::string& law, const std::vector<ExpectedParameter>& expected) {
  const std::vector<ParameterDeclaration> declared = parameter_declarations<Law>();
  ASSERT_EQ(declared.size(), expected.size()) << law;
  for (size_t i = 0; i < expected.size(); ++i) {
    const ParameterDeclaration& d = declared[i];
    const ExpectedParameter& e = expected[i];
    const std::string where = law + " parameter " + e.name;
    EXPECT_EQ(d.name, e.name) << where;
    EXPECT_EQ(d.range.lower, e.range.lower) << where;
    EXPECT_EQ(d.range.upper, e.range.upper) << where;
    EXPECT_EQ(d.range.lower_open, e.range.lower_open) << where;
    EXPECT_EQ(d.range.upper_open, e.range.upper_open) << where;
    EXPECT_EQ(d.default_value, e.default_value) << where;
    EXPECT_FALSE(d.unit.empty()) << where;
    EXPECT_FALSE(d.doc.empty()) << where;
  }
}

// The declared ranges are the checks the laws' validate() made before the parameters moved into the
// model: finite and >= 0 for coefficients, >= 1 for exponents, > 0 for p_ref and the regularisations,
// finite for potentials and gaps.
TEST(Laws, DeclaredRangesAreTheOldValidation) {
  const Range nonnegative = Range::at_least(0), positive = Range::positive(), finite = Range::any();
  expect_declarations<LinearDampedResponse>("LinearDampedResponse", {{"c_nu", nonnegative, {}}});
  expect_declarations<PowerDampedResponse>("PowerDampedResponse",
                                           {{"c_nu", nonnegative, {}}, {"m", Range::at_least(1), 1.0}});
  expect_declarations<NormalCompliance>(
      "NormalCompliance", {{"c_nu", nonnegative, {}}, {"m", Range::at_least(1), 1.0}, {"gap", finite, 0.0}});
  expect_declarations<ViscousFriction>("ViscousFriction", {{"c_tau", nonnegative, {}}});
  expect_declarations<RegularizedCoulomb>("RegularizedCoulomb", {{"mu", nonnegative, {}}, {"eps", positive, {}}});
  expect_declarations<RegularizedTresca>("RegularizedTresca", {{"g", nonnegative, {}}, {"eps", positive, {}}});
  expect_declarations<LinearConductance>("LinearConductance", {{"k_e", nonnegative, {}}, {"phi_f", finite, {}}});
  expect_declarations<PressureActivatedConductance>(
      "PressureActivatedConductance", {{"k_e", nonnegative, {}}, {"phi_f", finite, {}}, {"p_ref", positive, {}}});
  // The ranges as the messages state them.
  EXPECT_EQ(nonnegative.describe(), ">= 0");
  EXPECT_EQ(positive.describe(), "> 0");
  EXPECT_EQ(finite.describe(), "finite");
  EXPECT_FALSE(finite.contains(kNaN));
  EXPECT_FALSE(finite.contains(kInf));
  EXPECT_FALSE(nonnegative.contains(kInf));
  EXPECT_FALSE(positive.contains(0.0));
  EXPECT_TRUE(nonnegative.contains(0.0));
}

TEST(Laws, ValuesByParameterName) {
  EXPECT_EQ(law_values(LinearDampedResponse{1e12}), (ParameterValues{{"c_nu", 1e12}}));
  EXPECT_EQ(law_values(NormalCompliance{1e9, 2.0, 0.1}), (ParameterValues{{"c_nu", 1e9}, {"m", 2.0}, {"gap", 0.1}}));
  EXPECT_EQ(law_values(RegularizedCoulomb{0.3, 1e-3}), (ParameterValues{{"mu", 0.3}, {"eps", 1e-3}}));
  EXPECT_EQ(law_values(PressureActivatedConductance{1.0, -48.0, 1e6}),
            (ParameterValues{{"k_e", 1.0}, {"phi_f", -48.0}, {"p_ref", 1e6}}));
  const ParameterNames names{{{"c_nu", "c_nu_left"}}};
  EXPECT_EQ(names("c_nu"), "c_nu_left");
  EXPECT_EQ(names("m"), "m");
}

// ---- parameter checks: the brick's update() refuses an out-of-range model constant ----------------------

constexpr double kCNu = 1e12;

template <class Law>
concept ScalarLaw = requires(const Law& law) {
  law(0.0);
};
template <class Law>
concept FoundationLaw = requires(const Law& law) {
  law(0.0, 0.0);
};

// The brick that reads a law's parameters, with the normal brick it is paired with (if the law reads the
// contact pressure): a LinearDampedResponse reading c_nu.
struct BricksOfLaw {
  std::shared_ptr<Brick> brick;
  std::shared_ptr<Brick> normal;
};

template <class Law> BricksOfLaw bricks_of_law(const ParameterNames& names) {
  if constexpr (ScalarLaw<Law>) {
    return {std::make_shared<NormalResponseBrick<Law>>("contact", ContactFields{}, names), nullptr};
  } else {
    std::shared_ptr<NormalResponseBrick<LinearDampedResponse>> normal;
    if constexpr (law_uses_normal_pressure<Law>) normal = std::make_shared<NormalResponseBrick<LinearDampedResponse>>();
    if constexpr (FoundationLaw<Law>)
      return {std::make_shared<ConductiveFoundationBrick<Law>>("contact", normal, ContactFields{}, names), normal};
    else
      return {std::make_shared<FrictionBrick<Law>>("contact", normal, ContactFields{}, names), normal};
  }
}

// The model constants holding the law's values under `names` (and c_nu for a paired normal brick).
template <class Law> ConstantTable constants_of(const Law& law, const ParameterNames& names, bool paired) {
  ConstantTable data;
  for (const auto& [parameter, value] : law_values(law)) data.set(names(parameter), value);
  if (paired) data.set("c_nu", kCNu);
  return data;
}

// The brick's update() throws pc::Error whose message names the brick, the parameter, the model constant
// and the value: under the parameter's own name, and renamed (the constant then differs from the parameter).
template <class Law> void expect_rejected(const Law& law, const std::string& parameter, const std::string& value) {
  for (const bool renamed : {false, true}) {
    const std::string constant = renamed ? parameter + "_left" : parameter;
    ParameterNames names;
    if (renamed) names.renamed[parameter] = constant;
    const BricksOfLaw b = bricks_of_law<Law>(names);
    const ConstantTable data = constants_of(law, names, b.normal != nullptr);
    if (b.normal) {
      EXPECT_NO_THROW(b.normal->update(data));
    }
    try {
      b.brick->update(data);
      ADD_FAILURE() << "accepted the constant " << constant << " = " << value;
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("brick '" + b.brick->name() + "'"), std::string::npos) << what;
      EXPECT_NE(what.find("model constant '" + constant + "'"), std::string::npos) << what;
      EXPECT_NE(what.find(parameter + " must be "), std::string::npos) << what;
      EXPECT_NE(what.find(", got " + value), std::string::npos) << what;
    }
  }
}

template <class Law> void expect_accepted(const Law& law) {
  const BricksOfLaw b = bricks_of_law<Law>({});
  const ConstantTable data = constants_of(law, {}, b.normal != nullptr);
  if (b.normal) {
    EXPECT_NO_THROW(b.normal->update(data));
  }
  EXPECT_NO_THROW(b.brick->update(data));
}

TEST(Laws, BadParametersAreRejectedByName) {
  expect_rejected(LinearDampedResponse{-1.0}, "c_nu", "-1");
  expect_rejected(LinearDampedResponse{kNaN}, "c_nu", "nan");
  expect_rejected(PowerDampedResponse{1.0, 0.5}, "m", "0.5");
  expect_rejected(PowerDampedResponse{kInf, 2.0}, "c_nu", "inf");
  expect_rejected(NormalCompliance{1.0, 1.0, kInf}, "gap", "inf");
  expect_rejected(NormalCompliance{-2.0, 1.0, 0.0}, "c_nu", "-2");
  expect_rejected(ViscousFriction{-0.3}, "c_tau", "-0.3");
  expect_rejected(RegularizedCoulomb{-0.1, 1e-3}, "mu", "-0.1");
  expect_rejected(RegularizedCoulomb{0.3, 0.0}, "eps", "0");
  expect_rejected(RegularizedTresca{-1.0, 1e-3}, "g", "-1");
  expect_rejected(RegularizedTresca{1.0, -1e-3}, "eps", "-0.001");
  expect_rejected(LinearConductance{-1.0, 0.0}, "k_e", "-1");
  expect_rejected(LinearConductance{1.0, kNaN}, "phi_f", "nan");
  expect_rejected(PressureActivatedConductance{1.0, -48.0, 0.0}, "p_ref", "0");
  // The pressure-activated law's normal law is the paired normal brick's: that brick refuses its c_nu.
  expect_rejected(LinearDampedResponse{-1e12}, "c_nu", "-1e+12");
  // Zero coefficients are allowed: they switch a term off.
  expect_accepted(LinearDampedResponse{0.0});
  expect_accepted(RegularizedCoulomb{0.0, 1e-3});
  expect_accepted(PressureActivatedConductance{0.0, -48.0, 1e6});
}

TEST(Laws, AMissingConstantIsNamed) {
  NormalResponseBrick<NormalCompliance> brick("contact", {}, ParameterNames{{{"gap", "gap_left"}}});
  try {
    brick.update(ConstantTable{}.set("c_nu", 1e9).set("m", 1.0));
    ADD_FAILURE() << "updated without the constant gap_left";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'gap_left'"), std::string::npos) << e.what();
  }
}

// ---- the checker catches laws that break its rules ------------------------------------------------------

// Loses its derivative: the value goes through a plain double.
struct DetachedDerivative {
  template <class S> S operator()(const S& r) const {
    const double x = value_of(r);
    return S(x * x);
  }
};
struct FalselyAffine {
  static constexpr bool affine = true;
  template <class S> S operator()(const S& r) const { return r * r; }
};
struct FalselyDissipative {
  static constexpr bool dissipative = true;
  template <class S> S operator()(const S& r) const { return -2.0 * r; }
};
struct Overflowing {
  template <class S> S operator()(const S& r) const {
    using std::exp;
    return exp(r);
  }
};
// Right-sided at the kink is the library's rule; this law takes the left-sided derivative there.
struct LeftSidedKink {
  template <class S> S operator()(const S& r) const { return r <= 0.0 ? S(0.0) : r; }
};
// A Coulomb law that forgets the derivative in the pressure.
struct PressureBlindCoulomb {
  template <class S> void operator()(const S* r, int dim, const S& p, S* out) const {
    for (int d = 0; d < dim; ++d) out[d] = value_of(p) * r[d];
  }
};
struct NonMonotoneFoundation {
  static constexpr bool dissipative = true;
  template <class S> S operator()(const S& phi, const S&) const { return -phi; }
};

TEST(LawChecker, CatchesEachBrokenRule) {
  EXPECT_FALSE(check_scalar_law(DetachedDerivative{}).ok());
  EXPECT_FALSE(check_scalar_law(FalselyAffine{}).ok());
  EXPECT_FALSE(check_scalar_law(FalselyDissipative{}).ok());
  EXPECT_FALSE(check_scalar_law(Overflowing{}, {.extremes = {1e3}}).ok());
  EXPECT_FALSE(check_scalar_law(LeftSidedKink{}).ok());
  // c_nu = -1 is outside the range the law declares.
  const auto out_of_range = check_scalar_law(LinearDampedResponse{-1.0});
  EXPECT_FALSE(out_of_range.ok());
  std::ostringstream range_text;
  range_text << out_of_range;
  EXPECT_NE(range_text.str().find("c_nu must be >= 0, got -1"), std::string::npos) << range_text.str();
  EXPECT_FALSE(check_friction_law(PressureBlindCoulomb{}).ok());
  EXPECT_FALSE(check_foundation_law(NonMonotoneFoundation{}).ok());
  const auto report = check_scalar_law(DetachedDerivative{}, {.name = "detached"});
  std::ostringstream text;
  text << report;
  EXPECT_NE(text.str().find("detached"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("finite differences"), std::string::npos) << text.str();
}

// ---- derivatives at kinks: what holds there ---------------------------------------------------------

// c r_+^1.5: C^1, with an unbounded second derivative at the kink r = 0, where difference quotients
// converge to the derivative 0 only as h^0.5.
struct ThreeHalvesResponse {
  static constexpr bool dissipative = true;
  template <class S> S operator()(const S& r) const {
    using std::pow;
    return r < 0.0 ? S(0.0) : 2.0 * pow(r, 1.5);
  }
};
// c r_+ reporting 1.01 c at the kink: a wrong right-sided derivative.
struct KinkSlopeOff {
  template <class S> S operator()(const S& r) const {
    if (r < 0.0) return S(0.0);
    if (value_of(r) == 0.0) return chain_rule(r, 0.0, 1.01 * 3.0);
    return 3.0 * r;
  }
};
// c r_+^1.5 reporting the slope 1 at the kink instead of 0.
struct ThreeHalvesWrongAtKink {
  template <class S> S operator()(const S& r) const {
    using std::pow;
    if (r < 0.0) return S(0.0);
    if (value_of(r) == 0.0) return chain_rule(r, 0.0, 1.0);
    return 2.0 * pow(r, 1.5);
  }
};

TEST(LawChecker, AcceptsAC1LawWithAnUnboundedSecondDerivativeAtItsKink) {
  // Default options: the kink at 0 is checked, by right-sided quotients converging as h^0.5.
  const auto user = check_scalar_law(ThreeHalvesResponse{}, {.name = "2 r_+^1.5"});
  EXPECT_TRUE(user.ok()) << user;
  for (double m : {1.25, 1.5, 1.75}) {
    const auto library = check_scalar_law(PowerDampedResponse{1e12, m}, {.name = message("PowerDampedResponse m = ", m),
                                                                         .extremes = {1e-300, 1e-12, 1e12, 1e90}});
    EXPECT_TRUE(library.ok()) << library;
  }
  const auto compliance =
      check_scalar_law(NormalCompliance{1e9, 1.5, 0.1},
                       {.name = "NormalCompliance m = 1.5", .kinks = {0.1}, .extremes = {1e-300, 1e140}});
  EXPECT_TRUE(compliance.ok()) << compliance;
}

TEST(LawChecker, CatchesAWrongDerivativeAtAKink) {
  const auto left = check_scalar_law(LeftSidedKink{}, {.name = "left-sided"});
  EXPECT_FALSE(left.ok()) << left;
  std::ostringstream text;
  text << left;
  EXPECT_NE(text.str().find("right-sided"), std::string::npos) << text.str();
  EXPECT_FALSE(check_scalar_law(KinkSlopeOff{}).ok());
  EXPECT_FALSE(check_scalar_law(ThreeHalvesWrongAtKink{}).ok());
}

// ---- friction laws at extreme arguments: the limits their class has -------------------------------------

// Coulomb's law regularised as mu p r / sqrt(|r|^2 + eps^2) written naively in (r / eps)^2, which
// overflows to inf at |r| = 1e150 for eps = 1e-6: the force collapses to 0 instead of mu p, and stays
// finite.
struct NaiveCoulomb {
  double mu = 0.3, eps = 1e-6;
  static constexpr bool dissipative = true;
  static constexpr bool uses_normal_pressure = true;
  template <class S> void operator()(const S* r, int dim, const S& p, S* out) const {
    using std::sqrt;
    S sum = 1.0;
    for (int i = 0; i < dim; ++i) sum += (r[i] / eps) * (r[i] / eps);
    const S scale = 1.0 / sqrt(sum);
    for (int i = 0; i < dim; ++i) out[i] = mu * p * (r[i] / eps) * scale;
  }
};
// Friction that falls off at large speeds (mu p r / |r| for |r| < 1e6, then mu p 1e6 r / |r|^2): dissipative
// but not monotone; declared monotone, it is caught.
struct FallingFriction {
  static constexpr bool dissipative = true;
  static constexpr bool monotone = true;
  template <class S> void operator()(const S* r, int dim, const S& /*p*/, S* out) const {
    const double eps = 0.5;
    scaled_direction(
        r, dim,
        [eps](const auto& rho) {
          using T = std::decay_t<decltype(rho)>;
          if (rho <= eps) return T(rho / eps);
          if (rho <= 1e6) return T(1.0 + 0.0 * rho);
          return T(1e6 / rho);
        },
        out);
  }
};

TEST(LawChecker, CatchesAFrictionLawThatCollapsesAtLargeSpeeds) {
  const LawCheckOptions options{.name = "naive Coulomb", .derivatives = false};
  // Finite values at every extreme, but 0 instead of mu p at |r| = 1e150.
  const double r[2] = {1e150, 0.0};
  double out[2];
  NaiveCoulomb{}(r, 2, 1.0, out);
  EXPECT_EQ(out[0], 0.0);
  const auto report = check_friction_law(NaiveCoulomb{}, options);
  EXPECT_FALSE(report.ok()) << report;
  std::ostringstream text;
  text << report;
  EXPECT_NE(text.str().find("collapses"), std::string::npos) << text.str();
  // The library's Coulomb and Tresca laws at the same eps hold mu p and g up to 1e150.
  const auto library = check_friction_law(RegularizedCoulomb{0.3, 1e-6}, options);
  EXPECT_TRUE(library.ok()) << library;
  const auto tresca = check_friction_law(RegularizedTresca{5.0, 1e-6}, options);
  EXPECT_TRUE(tresca.ok()) << tresca;
  // A law declared monotone must not fall off along a ray.
  const auto falling = check_friction_law(FallingFriction{}, {.name = "falling", .derivatives = false});
  EXPECT_FALSE(falling.ok()) << falling;
}

// What a user writes for a law of their own: the law and a five-line test.
struct QuadraticResponse {
  static constexpr bool dissipative = true;
  template <class S> S operator()(const S& r) const { return r < 0.0 ? S(0.0) : 4.0 * r * r; }
};

TEST(LawChecker, AUserLawInFiveLines) {
  const auto report = check_scalar_law(QuadraticResponse{}, {.name = "QuadraticResponse"});
  EXPECT_TRUE(report.ok()) << report;
  EXPECT_GT(report.checks, 100);
}

}  // namespace
}  // namespace pc

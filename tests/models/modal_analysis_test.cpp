// Modal analysis against closed forms and exact inequalities:
//  1. a clamped-free bar on lateral rollers vibrates in its longitudinal modes, f_n = (2n - 1) c / (4 L)
//     with c = sqrt((lambda + 2 mu) / rho), an exact mode of the continuum: P1 converges at the rate 2
//     and P2 at the rate 4 under refinement, from above (Rayleigh-Ritz); a shift finds the mode nearest it;
//  2. piezoelectric stiffening: a PZT bar's frequencies lie above those of its c^E alone, and grounding
//     more of the potential lowers them (fewer electric dofs to relax into), the order Courant-Fischer
//     gives;
//  3. open- and short-circuit: a clamped-free PZT bar on lateral rollers, poled and electroded along its
//     axis (grounded at the clamp), is a 1D piezoelectric rod. With its free-end electrode floating (no
//     charge) D vanishes and the rod vibrates with c^D = c^E + e^2 / eps: f_n = (2n - 1) sqrt(c^D / rho)
//     / (4 L). Short-circuited, D = e <S> is uniform and the modes solve kL cot(kL) = k33^2 = e^2 /
//     (eps c^D), f = k sqrt(c^D / rho) / (2 pi). P2 meets both to its discretisation error, converging.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

#include "assembly/mesh_generators.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/piezo_materials.hpp"
#include "bricks/voigt.hpp"
#include "models/modal_analysis.hpp"
#include "models/piezo/electrodes.hpp"
#include "models/piezo/piezo_contact_recipe.hpp"
#include "support/piezo_circuit.hpp"

namespace pc {
namespace {

constexpr double kLength = 1, kHeight = 0.05, kRho = 2700, kYoung = 70e9, kPoisson = 0.3;

ModalResult bar_modes(int order, int cells, int modes = 3, double shift_hz = 0) {
  PiezoContactSpec spec;
  spec.mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {kLength, kHeight}, cells, 1));
  spec.order = order;
  spec.rho = kRho;
  spec.B = isotropic_stiffness_from_young(2, kYoung, kPoisson);
  spec.extra_bricks = [](Model& m) {
    m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "left", {0})));
    for (const char* side : {"top", "bottom"})
      m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", side, {1})));
  };
  PiezoContactModel built = build_piezo_contact_model(spec);
  ModalOptions options;
  options.modes = modes;
  options.shift_hz = shift_hz;
  return modal_analysis(*built.model, options);
}

double exact_frequency(int n) {
  const double lambda = kYoung * kPoisson / ((1 + kPoisson) * (1 - 2 * kPoisson));
  const double mu = kYoung / (2 * (1 + kPoisson));
  return (2 * n - 1) * std::sqrt((lambda + 2 * mu) / kRho) / (4 * kLength);
}

TEST(ModalAnalysis, ClampedFreeBarConvergesToTheLongitudinalFrequenciesAtTheElementsOrders) {
  for (int order : {1, 2}) {
    std::vector<double> errors;
    for (int cells : {8, 16, 32}) {
      const ModalResult r = bar_modes(order, cells);
      ASSERT_EQ(r.frequencies_hz.size(), 3u);
      for (int n = 1; n <= 3; ++n) EXPECT_GT(r.frequencies_hz[n - 1], exact_frequency(n) * (1 - 1e-12)) << "bound";
      errors.push_back(std::abs(r.frequencies_hz[2] / exact_frequency(3) - 1));
    }
    for (size_t k = 1; k < errors.size(); ++k) {
      const double rate = std::log2(errors[k - 1] / errors[k]);
      std::printf("P%d third frequency: relative error %.3e -> %.3e, rate %.2f\n", order, errors[k - 1], errors[k],
                  rate);
      EXPECT_NEAR(rate, 2.0 * order, 0.25) << "P" << order << " errors " << errors[k - 1] << " -> " << errors[k];
    }
  }
  EXPECT_LT(std::abs(bar_modes(2, 32).frequencies_hz[0] / exact_frequency(1) - 1), 1e-7);
}

TEST(ModalAnalysis, ShapesAreTheLongitudinalModesAndAShiftPicksTheNearest) {
  const ModalResult r = bar_modes(2, 16, 2);
  // The first mode is u_x ~ sin(pi x / 2L), v_y = 0: the transverse motion is the discretisation's only
  // (P2's mid-edge nodes inside the layer are free in y).
  const Eigen::VectorXd first = r.velocity_shapes.col(0);
  double largest_y = 0;
  for (int i = 1; i < first.size(); i += 2) largest_y = std::max(largest_y, std::abs(first[i]));
  EXPECT_LT(largest_y, 1e-4 * first.cwiseAbs().maxCoeff());
  // Near the third frequency the shifted solve finds it first.
  const double third = exact_frequency(3);
  EXPECT_NEAR(bar_modes(2, 16, 1, third * 1.01).frequencies_hz[0], third, 1e-4 * third);
  EXPECT_NEAR(bar_modes(2, 16, 1, exact_frequency(2) * 0.99).frequencies_hz[0], exact_frequency(2),
              1e-4 * exact_frequency(2));
}

// A PZT-5H bar poled along x, clamped at x = 0.
ModalResult pzt_modes(bool electric, const std::vector<std::string>& grounded) {
  const PiezoTensors t = piezo_material("PZT-5H").tensors(2, Axis::x);
  PiezoContactSpec spec;
  spec.mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {10e-3, 2e-3}, 20, 4));
  spec.rho = t.rho;
  spec.B = t.B;
  if (electric) {
    spec.E = t.E;
    spec.beta = t.beta;
  }
  spec.clamped = {"left"};
  spec.grounded = grounded;
  PiezoContactModel built = build_piezo_contact_model(spec);
  ModalOptions o;
  o.modes = 4;
  return modal_analysis(*built.model, o);
}

TEST(ModalAnalysis, PiezoelectricStiffeningOrdersTheFrequencies) {
  const ModalResult mechanical = pzt_modes(false, {});
  const ModalResult shorted = pzt_modes(true, {"left", "right"});  // electrodes at both ends, short-circuited
  const ModalResult one_side = pzt_modes(true, {"left"});          // the far end carries no charge
  ASSERT_EQ(one_side.potential_shapes.cols(), 4);
  for (int m = 0; m < 4; ++m) {
    EXPECT_GT(shorted.frequencies_hz[m], mechanical.frequencies_hz[m]) << m;
    EXPECT_GE(one_side.frequencies_hz[m], shorted.frequencies_hz[m] * (1 - 1e-12)) << m;
  }
  // The coupling is strong (k33 ~ 0.75): stiffening raises some mode by more than 5 %.
  double largest = 0;
  for (int m = 0; m < 4; ++m) largest = std::max(largest, one_side.frequencies_hz[m] / mechanical.frequencies_hz[m]);
  EXPECT_GT(largest, 1.05);
}

// ---- 3. open and short circuit ---------------------------------------------------------------------

struct PiezoRod {
  static constexpr double length = 10e-3, height = 0.5e-3;
  PiezoTensors t = piezo_material("PZT-5H").tensors(2, Axis::x);
  // The 1D rod's constants: along x, E_x couples to eps_xx only (u_y = 0, phi = phi(x)).
  double c_e = t.B(0, 0), e = t.E(0, 0), eps = t.beta(0, 0);
  double c_d = c_e + e * e / eps;
  double coupling = e * e / (eps * c_d);

  // The modes, and the free end's potential dofs in end_dofs.
  ModalResult modes(bool open_circuit, int cells, std::vector<int>* end_dofs = nullptr) const {
    PiezoContactSpec spec;
    spec.mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {length, height}, cells, 1));
    spec.order = 2;
    testing::set_piezo_tensors(spec, t, true);
    testing::set_circuit(spec, "left", "right", open_circuit);
    spec.extra_bricks = [](Model& m) {
      m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "left", {0})));
      for (const char* side : {"top", "bottom"})
        m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", side, {1})));
    };
    PiezoContactModel built = build_piezo_contact_model(spec);
    if (end_dofs) *end_dofs = built.model->space("phi").dofs_on("right");
    ModalOptions o;
    o.modes = 2;
    return modal_analysis(*built.model, o);
  }
  double open_frequency(int n) const { return (2 * n - 1) * std::sqrt(c_d / t.rho) / (4 * length); }
  // The n-th root of kL cot(kL) = coupling, in ((n - 1) pi, (n - 1/2) pi), by bisection.
  double short_frequency(int n) const {
    double lo = (n - 1) * std::numbers::pi + 1e-12, hi = (n - 0.5) * std::numbers::pi;
    const auto f = [&](double x) { return x * std::cos(x) - coupling * std::sin(x); };
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (f(mid) > 0) == (f(lo) > 0) ? lo = mid : hi = mid;
    }
    return 0.5 * (lo + hi) / length * std::sqrt(c_d / t.rho) / (2 * std::numbers::pi);
  }
};

TEST(ModalAnalysis, FloatingElectrodeGivesTheOpenCircuitRodAndGroundingItTheShortCircuitRoot) {
  const PiezoRod rod;
  // Clamped laterally, the rod's coupling is the thickness coupling k_t, 0.50 to 0.52 for PZT-5H.
  EXPECT_NEAR(std::sqrt(rod.coupling), 0.51, 0.02);
  std::vector<int> end;
  const ModalResult open_coarse = rod.modes(true, 10), open = rod.modes(true, 20, &end);
  const ModalResult shorted_coarse = rod.modes(false, 10), shorted = rod.modes(false, 20);
  for (int n = 1; n <= 2; ++n) {
    const double fo = rod.open_frequency(n), fs = rod.short_frequency(n);
    std::printf("mode %d: open %.6e (exact %.6e), short %.6e (exact %.6e)\n", n, open.frequencies_hz[n - 1], fo,
                shorted.frequencies_hz[n - 1], fs);
    EXPECT_NEAR(open.frequencies_hz[n - 1], fo, 1e-5 * fo) << n;
    EXPECT_NEAR(shorted.frequencies_hz[n - 1], fs, 1e-5 * fs) << n;
    EXPECT_LT(fs, fo) << "the short circuit relaxes the potential: a softer rod";
    // P2's error falls by 2^4 (Rayleigh-Ritz: from above, the square of the shape's energy error).
    const double open_rate = std::log2((open_coarse.frequencies_hz[n - 1] - fo) / (open.frequencies_hz[n - 1] - fo));
    const double short_rate =
        std::log2((shorted_coarse.frequencies_hz[n - 1] - fs) / (shorted.frequencies_hz[n - 1] - fs));
    EXPECT_NEAR(open_rate, 4, 0.3) << n;
    EXPECT_NEAR(short_rate, 4, 0.3) << n;
  }
  // The floating electrode's dofs move as one in every open-circuit mode; the short circuit's stay at 0.
  ASSERT_EQ(open.potential_shapes.cols(), 2);
  for (int m = 0; m < 2; ++m) {
    EXPECT_GT(std::abs(open.potential_shapes(end.front(), m)), 0) << m;
    for (int d : end) EXPECT_EQ(open.potential_shapes(d, m), open.potential_shapes(end.front(), m)) << m;
    for (int d : end) EXPECT_EQ(shorted.potential_shapes(d, m), 0) << m;
  }
}

}  // namespace
}  // namespace pc

// A foundation law of your own, in the driver: a conductive foundation that can only deliver a limited
// charge flux. It is checked by the law checker at start-up, plugged into ConductiveFoundationBrick, and
// the paper's strip is run with it and with the paper's linear law, D.n = k_e (phi - phi_f).
//
//   build/release/examples/custom_foundation_law
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"
#include "bricks/conductive_foundation_brick.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/elasticity_brick.hpp"
#include "bricks/friction_brick.hpp"
#include "bricks/inertia_brick.hpp"
#include "bricks/law_registry.hpp"
#include "bricks/laws/foundation_laws.hpp"
#include "bricks/laws/friction_laws.hpp"
#include "bricks/laws/law_parameters.hpp"
#include "bricks/laws/normal_laws.hpp"
#include "bricks/normal_response_brick.hpp"
#include "bricks/permittivity_brick.hpp"
#include "bricks/piezoelectric_brick.hpp"
#include "bricks/source_bricks.hpp"
#include "bricks/testing/law_checker.hpp"
#include "bricks/viscosity_brick.hpp"
#include "models/model.hpp"
#include "models/piezo/initial_potential.hpp"
#include "models/solvers/newton.hpp"
#include "models/stepper.hpp"
#include "models/time_scheme.hpp"

using namespace pc;

// ---- the new law ----------------------------------------------------------------------------------------
// D.n = k_e phi_s tanh((phi - phi_f) / phi_s): the paper's k_e (phi - phi_f) for small differences, but
// saturating at the flux k_e phi_s. A foundation law is a value type with
//   template <class S> S operator()(const S& phi, const S& pressure) const
// (S is double or a Dual number, which gives the brick its tangent), compile-time traits, and its
// parameters declared once: name, member, unit, documentation, valid range, required or defaulted. The
// brick reads them from the model's constants by these names, checked against these ranges.
struct SaturatingConductance {
  double k_e = 0, phi_f = 0, phi_s = 1;

  static constexpr bool affine = false;                // tanh: the brick is nonlinear
  static constexpr bool dissipative = true;            // monotone in phi
  static constexpr bool uses_normal_pressure = false;  // conducts whether pressed or not

  static constexpr auto parameters() {
    return std::array{
        law_parameter("k_e", &SaturatingConductance::k_e, "C/(V m^2)", "conductance at small potential differences",
                      Range::at_least(0), Required::yes),
        law_parameter("phi_f", &SaturatingConductance::phi_f, "V", "potential of the foundation", Range::any(),
                      Required::yes),
        law_parameter("phi_s", &SaturatingConductance::phi_s, "V", "potential difference where the flux saturates",
                      Range::positive())};
  }

  template <class S>
  S operator()(const S& phi, const S& /*pressure*/) const {
    using std::tanh;  // std::tanh for double; pc::tanh (found by argument-dependent lookup) for Dual
    return k_e * phi_s * tanh((phi - phi_f) / phi_s);
  }
};
// One line makes it a foundation law that recipes (PiezoContactSpec::foundation = {"saturating", {...}})
// and scenes can name, documented by `piezocontact describe` like the built-in ones.
PC_REGISTER_FOUNDATION_LAW(SaturatingConductance, "saturating",
                           "D.n = k_e phi_s tanh((phi - phi_f) / phi_s): conduction that saturates")

// ---- the paper's strip, with the foundation law as a parameter --------------------------------------------
// Runs T = 0.2 s in 20 steps on a coarse mesh; returns (x, phi) at the nodes of the contact boundary.
template <class FoundationLaw>
std::vector<std::pair<double, double>> potential_on_contact(const FoundationLaw& foundation) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {0.03, 0.01}, 12, 4, Shape::Triangle));
  Model model(mesh);
  model.add_unknown("v", std::make_shared<const FESpace>(mesh, 1, 2));
  model.add_unknown("phi", std::make_shared<const FESpace>(mesh, 1, 1));
  BackwardEuler scheme;
  scheme.attach(model, /*with_acceleration=*/true);

  // PZT-5H, plane strain, poled along +y (scenes/paper2d.json); Kelvin-Voigt viscosity A = 0.01 s * B.
  const Eigen::MatrixXd B{{127.205e9, 84.6702e9, 0}, {84.6702e9, 117.436e9, 0}, {0, 0, 22.9885e9}};
  model.set_constant("rho", 7800.0);
  model.set_constant("A", Eigen::MatrixXd(0.01 * B));
  model.set_constant("B", B);
  model.set_constant("E", Eigen::MatrixXd{{0, 0, 17.0345}, {-6.62281, 23.2403, 0}});
  model.set_constant("beta", Eigen::MatrixXd{{1.5091e-8, 0}, {0, 1.2693e-8}});

  model.add_brick(std::make_shared<InertiaBrick>());
  model.add_brick(std::make_shared<ViscosityBrick>());
  model.add_brick(std::make_shared<ElasticityBrick>());
  model.add_brick(std::make_shared<PiezoelectricCouplingBrick>());
  model.add_brick(std::make_shared<PermittivityBrick>());
  const Load traction = [](const double*, double t, double* out) {
    out[0] = 0;
    out[1] = -t;
  };
  model.add_brick(std::make_shared<TractionBrick>(traction, LoadTime::Varying, "top"));
  model.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "left")));
  model.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("phi", "top")));
  // Law parameters are model constants: c_nu, c_tau, and the foundation law's own (k_e, phi_f, ...).
  model.set_constants(law_values(LinearDampedResponse{1e12}));
  model.set_constants(law_values(ViscousFriction{0.3}));
  model.set_constants(law_values(foundation));
  model.add_brick(std::make_shared<NormalResponseBrick<LinearDampedResponse>>("bottom"));
  model.add_brick(std::make_shared<FrictionBrick<ViscousFriction>>("bottom"));
  // The law under study: any law type the brick accepts.
  model.add_brick(std::make_shared<ConductiveFoundationBrick<FoundationLaw>>("bottom"));
  model.finalize();

  StepperOptions options;
  options.end = 0.2;
  options.step = 0.2 / 20;
  options.prediction = Prediction::Previous;
  NewtonSolver newton;
  StepperCallbacks callbacks;
  callbacks.on_start = [&](Model& m) { return solve_initial_potential(m, scheme, newton); };  // phi_0
  const RunSummary run = Stepper(options).run(model, scheme, newton, callbacks);
  require(run.completed, "the run stopped: ", run.message);
  std::printf("  %d steps, %d Newton iterations (at most %d per step)\n", run.steps, run.newton_iterations_total,
              run.newton_iterations_max_per_step);

  const FESpace& space = model.space("phi");
  std::vector<std::pair<double, double>> phi;
  for (const int node : space.scalar_dofs_on("bottom"))
    phi.emplace_back(space.scalar_dof_point(node)[0], model.values("phi")[node]);
  std::sort(phi.begin(), phi.end());
  return phi;
}

int main() {
  try {
    // The paper's k_e = 1 and phi_f = -48 V, saturating at the flux k_e phi_s = 3e-5 C/m^2: a quarter of
    // the flux the linear law drives through the contact in this scene (k_e (phi - phi_f) ~ 1.2e-4 C/m^2).
    const SaturatingConductance saturating{1.0, -48.0, 3e-5};

    // Check the law before using it: its Dual derivatives against finite differences, its dissipative
    // claim (monotone in phi), its values inside their declared ranges, finite values at extreme arguments. The derivatives are checked
    // with parameters of order one: next to phi_f = -48 V, phi is only known to ~1e-14 V, too coarse for
    // finite differences over phi_s = 3e-5 V. The run's own parameters get the other checks.
    auto check = [](const SaturatingConductance& law, const LawCheckOptions& options) {
      const LawCheckReport report = check_foundation_law(law, options);
      std::cout << "law check: " << report << "\n";
      return report.ok();
    };
    if (!check({2.0, 0.5, 0.7}, {.name = "SaturatingConductance"}) ||
        !check(saturating, {.name = "SaturatingConductance (run parameters)", .derivatives = false}))
      return 1;

    // Registered: the same entry that `piezocontact describe` prints and a scene's foundation type names.
    const auto& entry = foundation_law_registry().at("saturating", "example");
    std::printf("registered foundation law '%s': %s\n", entry.name.c_str(), entry.doc.c_str());
    for (const ParameterDeclaration& p : entry.parameters)
      std::printf("  %s [%s] %s: %s\n", p.name.c_str(), p.unit.c_str(), p.required() ? "required" : "defaulted",
                  p.doc.c_str());

    std::printf("linear conductance, D.n = k_e (phi - phi_f):\n");
    const auto linear = potential_on_contact(LinearConductance{1.0, -48.0});
    std::printf("saturating conductance, D.n = k_e phi_s tanh((phi - phi_f) / phi_s):\n");
    const auto limited = potential_on_contact(saturating);

    std::printf("\nphi on the contact boundary y = 0 at T = 0.2 s [V]\n%10s %12s %12s\n", "x [m]", "linear",
                "saturating");
    for (std::size_t i = 0; i < linear.size(); ++i)
      std::printf("%10.4f %12.5f %12.5f\n", linear[i].first, linear[i].second, limited[i].second);
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}

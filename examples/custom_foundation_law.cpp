// A foundation law of your own (consumer/saturating_conductance.hpp): a conductive foundation that can only
// deliver a limited charge flux. It declares its parameters, registers itself under a name, is checked by
// the law checker at start-up, and the paper's strip (stacked by the recipe) is run with it and with the
// paper's linear law, D.n = k_e (phi - phi_f), each chosen by its registered name.
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
#include "bricks/law_registry.hpp"
#include "bricks/laws/foundation_laws.hpp"
#include "bricks/laws/friction_laws.hpp"
#include "bricks/laws/law_parameters.hpp"
#include "bricks/laws/normal_laws.hpp"
#include "bricks/piezo_materials.hpp"
#include "bricks/testing/law_checker.hpp"
#include "consumer/saturating_conductance.hpp"
#include "models/piezo/initial_potential.hpp"
#include "models/piezo/piezo_contact_recipe.hpp"
#include "models/solvers/newton.hpp"
#include "models/stepper.hpp"

using namespace pc;

// ---- the new law ----------------------------------------------------------------------------------------
// D.n = k_e phi_s tanh((phi - phi_f) / phi_s): the paper's k_e (phi - phi_f) for small differences, but
// saturating at the flux k_e phi_s. A foundation law is a value type with
//   template <class S> S operator()(const S& phi, const S& pressure) const
// (S is double or a Dual number, which gives the brick its tangent), compile-time traits, and its
// parameters declared once. It lives in the consumer project (the README shows it from there), which also
// builds it into a plugin and tests it against the installed package: consumer/saturating_conductance.hpp.
// One line makes it a foundation law that recipes (PiezoContactSpec::foundation = {"saturating", {...}})
// and scenes can name, documented by `piezocontact describe` like the built-in ones.
PC_REGISTER_FOUNDATION_LAW(SaturatingConductance, "saturating",
                           "D.n = k_e phi_s tanh((phi - phi_f) / phi_s): conduction that saturates")

// ---- the paper's strip, with the foundation law chosen by its registered name ------------------------------
// The recipe stacks the paper's bricks (examples/paper_bricks.cpp stacks them by hand) and makes the
// foundation brick of the law the spec names, writing its parameters into the model's constants. Runs
// T = 0.2 s in 20 steps on a coarse mesh; returns (x, phi) at the nodes of the contact boundary.
std::vector<std::pair<double, double>> potential_on_contact(const Choice& foundation) {
  PiezoContactSpec spec;
  spec.mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {0.03, 0.01}, 12, 4, Shape::Triangle));
  const PiezoTensors pzt = piezo_material("PZT-5H").tensors(2, Axis::y);  // plane strain, poled along +y
  spec.rho = 7800;                                                        // the paper's density
  spec.B = pzt.B;
  spec.A = 0.01 * pzt.B;  // Kelvin-Voigt, tau_v = 0.01 s
  spec.E = pzt.E;
  spec.beta = pzt.beta;
  spec.clamped = {"left"};
  spec.grounded = {"top"};
  spec.tractions = {{"top", [](const double*, double t, double* out) { out[0] = 0, out[1] = -t; }}};
  spec.contact = "bottom";
  spec.normal = {"linear_damped", law_values(LinearDampedResponse{1e12})};
  spec.friction = {"viscous", law_values(ViscousFriction{0.3})};
  spec.foundation = foundation;  // the law under study, by name
  PiezoContactModel built = build_piezo_contact_model(spec);
  Model& model = *built.model;

  StepperOptions options;
  options.end = 0.2;
  options.step = 0.2 / 20;
  options.prediction = Prediction::Previous;
  NewtonSolver newton;
  StepperCallbacks callbacks;
  callbacks.on_start = [&](Model& m) { return solve_initial_potential(m, *built.scheme, newton); };  // phi_0
  const RunSummary run = Stepper(options).run(model, *built.scheme, newton, callbacks);
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
    // claim (monotone in phi), its values inside their declared ranges, finite values at extreme arguments. The
    // derivatives are checked with parameters of order one: next to phi_f = -48 V, phi is only known to ~1e-14 V, too
    // coarse for finite differences over phi_s = 3e-5 V. The run's own parameters get the other checks.
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
    const auto linear = potential_on_contact({"conductive", law_values(LinearConductance{1.0, -48.0})});
    std::printf("saturating conductance, D.n = k_e phi_s tanh((phi - phi_f) / phi_s):\n");
    const auto limited = potential_on_contact({"saturating", law_values(saturating)});

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

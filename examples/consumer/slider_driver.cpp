// A driver outside the library: the paper's piezoelectric strip stacked brick by brick, pulled along its
// contact surface so that it slides, with the user's velocity-weakening friction law (velocity_weakening.hpp)
// paired with the library's damped normal response. Built against the installed package only.
#include <cstdio>
#include <memory>

#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"
#include "assembly/version.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/elasticity_brick.hpp"
#include "bricks/friction_brick.hpp"
#include "bricks/inertia_brick.hpp"
#include "bricks/laws/normal_laws.hpp"
#include "bricks/normal_response_brick.hpp"
#include "bricks/permittivity_brick.hpp"
#include "bricks/piezoelectric_brick.hpp"
#include "bricks/source_bricks.hpp"
#include "bricks/viscosity_brick.hpp"
#include "models/model.hpp"
#include "models/piezo/initial_potential.hpp"
#include "models/piezo/material_constants.hpp"
#include "models/solvers/newton.hpp"
#include "models/stepper.hpp"
#include "models/time_scheme.hpp"
#include "velocity_weakening.hpp"

using namespace pc;

int main() {
  try {
    std::printf("piezocontact %s (built against %s)\n", library_version(), PIEZOCONTACT_VERSION);
    auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {0.03, 0.01}, 24, 8, Shape::Triangle));
    Model model(mesh);
    model.add_unknown("v", std::make_shared<const FESpace>(mesh, 1, 2));
    model.add_unknown("phi", std::make_shared<const FESpace>(mesh, 1, 1));
    BackwardEuler scheme;
    scheme.attach(model, /*with_acceleration=*/true);

    // PZT-5H from the library's presets, plane strain, poled along +y; Kelvin-Voigt viscosity A = 0.01 s B.
    set_material_constants(model, piezo_material("PZT-5H").tensors(2, Axis::y), 0.01);
    // The contact laws' parameters are model constants too: the normal law's and the user's law's.
    model.set_constants(law_values(LinearDampedResponse{1e10}));
    model.set_constants(law_values(VelocityWeakeningCoulomb{0.6, 0.3, 1e-9, 1e-12}));

    model.add_brick(std::make_shared<InertiaBrick>());
    model.add_brick(std::make_shared<ViscosityBrick>());
    model.add_brick(std::make_shared<ElasticityBrick>());
    model.add_brick(std::make_shared<PiezoelectricCouplingBrick>());
    model.add_brick(std::make_shared<PermittivityBrick>());
    // Pressed down and pulled along x on the top, grounded there, clamped on the left.
    model.add_brick(std::make_shared<TractionBrick>(
        [](const double*, double t, double* out) {
          out[0] = 2e3 * t;
          out[1] = -1e4 * t;
        },
        LoadTime::Varying, "top"));
    model.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "left")));
    model.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("phi", "top")));
    auto normal = std::make_shared<NormalResponseBrick<LinearDampedResponse>>("bottom");
    model.add_brick(normal);
    model.add_brick(std::make_shared<FrictionBrick<VelocityWeakeningCoulomb>>("bottom", normal));
    model.finalize();

    StepperOptions options;
    options.end = 0.02;
    options.step = 0.001;
    options.prediction = Prediction::Previous;
    NewtonSolver newton;
    StepperCallbacks callbacks;
    callbacks.on_start = [&](Model& m) { return solve_initial_potential(m, scheme, newton); };
    const RunSummary run = Stepper(options).run(model, scheme, newton, callbacks);
    require(run.completed, "the run stopped: ", run.message);
    const Eigen::VectorXd& u = model.values("u");
    double ux = 0;
    for (int i = 0; i < u.size(); i += 2) ux = std::max(ux, std::abs(u[i]));
    std::printf("%d steps, %d Newton iterations; max |u_x| = %.4g m\n", run.steps, run.newton_iterations_total, ux);
    require(ux > 0, "the strip did not move");
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}

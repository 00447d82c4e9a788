// The paper's 2D test (section 4), with every brick stacked by hand: the program to copy when a scene
// needs something the recipe (models/piezo/piezo_contact_recipe.hpp) does not offer.
//
// A piezoelectric Kelvin-Voigt strip (0, 0.03) x (0, 0.01) m of PZT-5H, clamped on the left, pressed by
// the traction (0, -t) N/m on the top, grounded (phi = 0) on the top, and in frictional contact with a
// conductive foundation (phi_f = -48 V) on the bottom. Unknowns: the velocity v and the potential phi;
// the displacement u = u_prev + k v and the acceleration a = (v - v_prev) / k are affine fields of v.
//
//   build/release/examples/paper_bricks [output directory, default paper_bricks_out]
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"
#include "assembly/point_locator.hpp"
#include "assembly/vtu_writer.hpp"
#include "bricks/conductive_foundation_brick.hpp"
#include "bricks/contact_status.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/elasticity_brick.hpp"
#include "bricks/friction_brick.hpp"
#include "bricks/inertia_brick.hpp"
#include "bricks/laws/foundation_laws.hpp"
#include "bricks/laws/friction_laws.hpp"
#include "bricks/laws/normal_laws.hpp"
#include "bricks/normal_response_brick.hpp"
#include "bricks/permittivity_brick.hpp"
#include "bricks/piezoelectric_brick.hpp"
#include "bricks/source_bricks.hpp"
#include "bricks/viscosity_brick.hpp"
#include "models/model.hpp"
#include "models/output/piezo_fields.hpp"
#include "models/output/result_series.hpp"
#include "models/piezo/initial_potential.hpp"
#include "models/piezo/material_constants.hpp"
#include "models/solvers/newton.hpp"
#include "models/stepper.hpp"
#include "models/time_scheme.hpp"

using namespace pc;

int main(int argc, char** argv) {
  const std::string output = argc > 1 ? argv[1] : "paper_bricks_out";
  try {
    // ---- mesh and unknowns ------------------------------------------------------------------------
    // rectangle_mesh names the sides "left", "right", "bottom", "top"; the cell region is "all".
    // [snippet stack]
    // [snippet stack_and_run]
    auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {0.03, 0.01}, 30, 10, Shape::Triangle));
    Model model(mesh);
    model.add_unknown("v", std::make_shared<const FESpace>(mesh, 1, 2));    // P1, 2 components
    model.add_unknown("phi", std::make_shared<const FESpace>(mesh, 1, 1));  // P1, scalar

    // The time scheme adds the affine fields u and a (with_acceleration = true: there is inertia).
    BackwardEuler scheme;
    scheme.attach(model, /*with_acceleration=*/true);
    // [snippet stack end]

    // [snippet stack_and_run end]
    // ---- constants: the bricks (and the output) read them by name ---------------------------------
    // PZT-5H from the presets, plane strain, poled along +y (Voigt xx, yy, xy, engineering shear): rho,
    // B = c^E, E = e, beta = eps^S, and the Kelvin-Voigt viscosity A = 0.01 s * B; then the paper's density.
    // The values are those of scenes/paper2d.json (tests/bricks/piezo_materials_test.cpp checks it).
    // [snippet stack]
    // [snippet stack_and_run]
    set_material_constants(model, piezo_material("PZT-5H").tensors(2, Axis::y), 0.01);  // B, E, beta, rho; A = 0.01 B
    model.set_constant("rho", 7800.0);
    // [snippet stack end]

    // [snippet stack_and_run end]
    // ---- bricks -----------------------------------------------------------------------------------
    // [snippet stack]
    // [snippet stack_and_run]
    // Bulk: rho a.w + A eps(v):eps(w) + B eps(u):eps(w) + E^T grad phi:eps(w) - E eps(u).grad psi
    //       + beta grad phi.grad psi, all on "all" and reading the constants above.
    model.add_brick(std::make_shared<InertiaBrick>());
    model.add_brick(std::make_shared<ViscosityBrick>());
    model.add_brick(std::make_shared<ElasticityBrick>());
    model.add_brick(std::make_shared<PiezoelectricCouplingBrick>());
    model.add_brick(std::make_shared<PermittivityBrick>());
    // Loads and boundary values: the traction grows with time, f_N = (0, -t) N/m.
    const Load traction = [](const double* /*x*/, double t, double* out) {
      out[0] = 0;
      out[1] = -t;
    };
    model.add_brick(std::make_shared<TractionBrick>(traction, LoadTime::Varying, "top"));
    model.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", "left")));   // u = u0 = 0
    model.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("phi", "top")));  // grounded
    // Contact on the bottom, each brick templated on its law: p_nu = c_nu (v.n)_+, p_tau = c_tau v_tau,
    // D.n = k_e (phi - phi_f). The laws' parameters are model constants, read by name like the tensors:
    // model.set_constant("phi_f", 10.0) later changes the foundation brick alone.
    model.set_constant("c_nu", 1e12);
    model.set_constant("c_tau", 0.3);
    model.set_constants(law_values(LinearConductance{1.0, -48.0}));  // k_e, phi_f
    const auto normal = std::make_shared<NormalResponseBrick<LinearDampedResponse>>("bottom");
    model.add_brick(normal);
    model.add_brick(std::make_shared<FrictionBrick<ViscousFriction>>("bottom"));
    model.add_brick(std::make_shared<ConductiveFoundationBrick<LinearConductance>>("bottom"));
    model.finalize();  // binds the bricks to their regions and checks that every field is used
    // [snippet stack end]

    // [snippet stack_and_run end]
    // ---- time loop --------------------------------------------------------------------------------
    // [snippet stack_and_run]
    StepperOptions options;
    options.end = 0.2;
    options.step = 0.2 / 50;
    options.output_every = 10;
    options.prediction = Prediction::Previous;  // start each Newton solve from v_{n-1}
    NewtonSolver newton;                        // default options: see models/solvers/newton.hpp

    // [snippet stack_and_run end]
    const PointLocator locator(*mesh);
    const double corner[2] = {0.03, 0.01}, centre[2] = {0.015, 0.005};
    ResultSeries series(output, "paper");

    // [snippet stack_and_run]
    StepperCallbacks callbacks;
    // Before the first step: phi_0 from the electric equation at u = u_0 (the paper's initial potential).
    callbacks.on_start = [&](Model& m) { return solve_initial_potential(m, scheme, newton); };
    // [snippet stack_and_run end]
    callbacks.on_step = [&](const Model& m, const StepRecord& step) {
      if (step.step % 10 != 0) return;
      const double u_y = evaluate_at(m.space("u"), m.values("u"), locator, corner)[1];
      const double phi = evaluate_at(m.space("phi"), m.values("phi"), locator, centre)[0];
      std::printf("step %3d  t = %.4f  Newton %d  u_y(corner) = %+.4e m  phi(centre) = %+.4e V\n", step.step, step.time,
                  step.newton.iterations, u_y, phi);
    };
    callbacks.on_output = [&](const Model& m, const StepRecord& step) {
      VtuWriter writer(m.mesh());
      add_piezo_output(writer, m);  // v, u, phi, strain, stress, von Mises, E and D fields
      series.write(step.step, step.time, writer);
    };

    // [snippet stack_and_run]
    const RunSummary run = Stepper(options).run(model, scheme, newton, callbacks);
    // [snippet stack_and_run end]
    if (!run.completed) {
      std::fprintf(stderr, "run stopped: %s\n", run.message.c_str());
      return 1;
    }
    // Contact status at the final time: the nodes of the bottom where the model's normal brick gives a
    // pressure, i.e. (damped response) that still move into the foundation, v.n > 0.
    const ContactStatus status = contact_status(*normal, model.space("v"), contact_nodes(model.space("v"), "bottom"),
                                                model.values("v"), model.values("v"), 0.0, model.time());
    std::printf("contact at T: %d of %d bottom nodes in compression\n", status.in_contact, status.nodes);
    std::printf("%d steps, %d Newton iterations (at most %d per step), %.2f s; results in %s\n", run.steps,
                run.newton_iterations_total, run.newton_iterations_max_per_step, run.wall_seconds,
                series.pvd_path().c_str());
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}

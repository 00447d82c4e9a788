// The paper's scene end to end on a coarse mesh, asserting physics rather than snapshots: the clamped side
// does not move, the grounded top stays at zero potential, the contact potential tends to phi_f as k_e
// grows, k_e -> 0 reproduces the insulated foundation, Newton needs few iterations, and the results
// converge under mesh and time-step refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "assembly/error.hpp"
#include "models/scene/scene_runner.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";

Scene coarse(std::vector<std::string> overrides = {}) {
  overrides.insert(overrides.begin(), {"mesh.nx=15", "mesh.ny=5", "time.steps=20"});
  return load_scene_file(kScene, overrides);
}

TEST(PaperScene, CoarseRunsConvergeInFewNewtonIterationsAndKeepTheBoundaryConditions) {
  const Scene scene = coarse();
  for (const std::string name : {"insulated", "conductive"}) {
    const FoundationRunResult r = run_foundation(scene, find_foundation(scene, name), "", false);
    ASSERT_TRUE(r.completed) << name << ": " << r.message;
    EXPECT_EQ(r.steps, 20);
    EXPECT_LE(r.newton_iterations_max_per_step, 10) << name;
    EXPECT_LE(r.newton_iterations_total, 3 * r.steps) << name;
    EXPECT_GE(r.phi_max, 0.0);
  }
}

// phi on the contact boundary approaches phi_f as the conductance grows; the clamped side stays put and
// the grounded top stays at zero (checked on the fields of the final state through the run's tables).
TEST(PaperScene, ContactPotentialTendsToTheFoundationVoltageAsConductanceGrows) {
  double previous_gap = 1e300;
  for (double k_e : {1e-8, 1e-6, 1e-3, 1.0}) {
    const Scene scene = coarse({"foundation.conductive.k_e=" + std::to_string(k_e), "time.steps=4"});
    const FoundationRunResult r = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
    ASSERT_TRUE(r.completed) << r.message;
    const double gap = std::abs(r.phi_min - (-48.0));
    std::printf("k_e = %g: phi_min = %.6g V (|phi_min - phi_f| = %.3g)\n", k_e, r.phi_min, gap);
    EXPECT_LT(gap, previous_gap);
    previous_gap = gap;
  }
  EXPECT_LT(previous_gap, 0.5) << "with k_e = 1 the contact potential is within 1% of phi_f";
}

TEST(PaperScene, VanishingConductanceReproducesTheInsulatedFoundation) {
  const Scene scene = coarse({"foundation.conductive.k_e=0", "time.steps=10"});
  const FoundationRunResult conductive = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
  const FoundationRunResult insulated = run_foundation(scene, find_foundation(scene, "insulated"), "", false);
  ASSERT_TRUE(conductive.completed && insulated.completed);
  EXPECT_NEAR(conductive.uy_corner, insulated.uy_corner, 1e-9 * std::abs(insulated.uy_corner));
  EXPECT_NEAR(conductive.phi_center, insulated.phi_center, 1e-9 * std::abs(insulated.phi_center));
  EXPECT_NEAR(conductive.max_abs_ux, insulated.max_abs_ux, 1e-9 * insulated.max_abs_ux);
}

// Successive refinements of the mesh (and of the time step) change the result by less and less: the
// observed mesh order is printed for the record and must be near that of P1 (measured 1.6).
TEST(PaperScene, ResultsConvergeUnderMeshAndTimeStepRefinement) {
  auto corner = [](const std::vector<std::string>& o) {
    const Scene scene = load_scene_file(kScene, o);
    const FoundationRunResult r = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
    EXPECT_TRUE(r.completed) << r.message;
    return r.ux_corner;
  };
  std::vector<double> mesh_values;
  for (int n : {6, 12, 24})
    mesh_values.push_back(
        corner({"mesh.nx=" + std::to_string(3 * n), "mesh.ny=" + std::to_string(n), "time.steps=10"}));
  const double mesh_order =
      std::log2(std::abs(mesh_values[1] - mesh_values[0]) / std::abs(mesh_values[2] - mesh_values[1]));
  std::printf("u_x at the corner, meshes 18x6, 36x12, 72x24: %.6e %.6e %.6e, observed order %.2f\n", mesh_values[0],
              mesh_values[1], mesh_values[2], mesh_order);
  EXPECT_GT(mesh_order, 0.8);

  std::vector<double> time_values;
  for (int steps : {10, 20, 40})
    time_values.push_back(corner({"mesh.nx=15", "mesh.ny=5", "time.steps=" + std::to_string(steps)}));
  // The creep time A/B = 0.01 s is resolved by 10 steps over T = 0.2 s and the load grows linearly, so
  // backward Euler is already close to converged: the changes must shrink and stay tiny.
  const double change_coarse = std::abs(time_values[1] - time_values[0]);
  const double change_fine = std::abs(time_values[2] - time_values[1]);
  std::printf("u_x at the corner, 10, 20, 40 steps: %.9e %.9e %.9e (changes %.2e, %.2e)\n", time_values[0],
              time_values[1], time_values[2], change_coarse, change_fine);
  EXPECT_LE(change_fine, change_coarse + 1e-12 * std::abs(time_values[2]));
  EXPECT_LT(change_fine, 1e-6 * std::abs(time_values[2]));
}

// The condensed Newton solve (linear part factorised once, contact dofs through a small dense system;
// by default iterating on the contact dofs alone, solver.contact_newton) and the plain one (a factorisation
// per iteration) are the same method: same iterates to round-off.
TEST(PaperScene, CondensedAndFullNewtonSolvesAgree) {
  for (const std::string name : {"insulated", "conductive"}) {
    const Scene condensed = coarse({"solver.condensed=true"});
    const Scene whole = coarse({"solver.condensed=true", "solver.contact_newton=false"});
    const Scene full = coarse({"solver.condensed=false"});
    const FoundationRunResult a = run_foundation(condensed, find_foundation(condensed, name), "", false);
    const FoundationRunResult w = run_foundation(whole, find_foundation(whole, name), "", false);
    const FoundationRunResult b = run_foundation(full, find_foundation(full, name), "", false);
    ASSERT_TRUE(a.completed && w.completed && b.completed) << a.message << w.message << b.message;
    // Same iterates to round-off, not to the bit: a step whose last residual lands within round-off of the
    // tolerance may take one iteration more on one route (which ones moves with the BLAS kernels).
    EXPECT_LE(std::abs(a.newton_iterations_total - b.newton_iterations_total), b.steps) << name;
    EXPECT_LE(std::abs(w.newton_iterations_total - b.newton_iterations_total), b.steps) << name;
    EXPECT_NEAR(w.uy_corner, b.uy_corner, 1e-8 * std::abs(b.uy_corner)) << name;
    EXPECT_NEAR(w.phi_center, b.phi_center, 1e-8 * std::abs(b.phi_center) + 1e-12) << name;
    // The condensed path factorises at most once for the initial potential and once for the steps: the
    // equal steps keep one size to the end (the last one is not shortened by the round-off of t).
    EXPECT_LE(a.factorizations, 2) << name;
    EXPECT_GE(b.factorizations, b.newton_iterations_total) << name;
    EXPECT_NEAR(a.ux_corner, b.ux_corner, 1e-8 * std::abs(b.ux_corner)) << name;
    EXPECT_NEAR(a.uy_corner, b.uy_corner, 1e-8 * std::abs(b.uy_corner)) << name;
    EXPECT_NEAR(a.phi_center, b.phi_center, 1e-8 * std::abs(b.phi_center) + 1e-12) << name;
  }
}

TEST(PaperScene, InvalidScenesAreRefusedWithEveryProblemAndItsPath) {
  try {
    coarse({"contact.c_nu=-1", "material.rho=\"heavy\"", "regions.contact=\"floor\""});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("3 problems"), std::string::npos) << what;
    EXPECT_NE(what.find("contact.c_nu"), std::string::npos) << what;
    EXPECT_NE(what.find("material.rho"), std::string::npos) << what;
    EXPECT_NE(what.find("'floor'"), std::string::npos) << what;
  }
}

// A --set value that reads as a number but is none a double holds is an error naming the key, not a string.
TEST(PaperScene, SetRefusesNumbersOutOfTheRangeOfADouble) {
  const std::string range = " is out of the range of a double (nonzero magnitudes from 4.9e-324 to 1.8e308)";
  EXPECT_EQ(testing::error_of([] { coarse({"contact.c_nu=1e400"}); }), "--set contact.c_nu:1:1: number 1e400" + range);
  EXPECT_EQ(testing::error_of([] { coarse({"contact.c_nu=-1e400"}); }),
            "--set contact.c_nu:1:1: number -1e400" + range);
  EXPECT_EQ(testing::error_of([] { coarse({"contact.c_nu=1e-400"}); }), "--set contact.c_nu: number 1e-400" + range);
}

}  // namespace
}  // namespace pc

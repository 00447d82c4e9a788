// Numerical stability at the extremes of the paper's scene, on a coarse mesh (12 x 4, 10 steps): every
// case of tests/support/extreme_cases.hpp (contact and foundation coefficients from 0 to 1e16, foundation
// voltages of +-1e5 V, steps from 1e-9 s to the whole span, no inertia or viscosity, cells of aspect
// ratio 150, P2, a single element) either completes with finite results or stops with completed == false
// and a message, and each is expected to complete. Then the limits the physics dictates: k_e = 0 is the
// insulated foundation, k_e = 1e15 imposes phi_f on the contact boundary, the penetration falls as c_nu
// grows, the contact potential follows phi_f = +-1e5 V. benchmarks/extremes_study.cpp runs the same cases
// on the scene's own mesh.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "assembly/error.hpp"
#include "models/scene/scene_runner.hpp"
#include "support/extreme_cases.hpp"

namespace pc::testing {
// gtest names a failing case by this rather than by its bytes.
void PrintTo(const ExtremeCase& c, std::ostream* out) { *out << c.name; }
}  // namespace pc::testing

namespace pc {
namespace {

namespace fs = std::filesystem;
using testing::ExtremeCase;

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";
const std::vector<std::string> kCoarse = {"mesh.nx=12", "mesh.ny=4", "time.steps=10"};

Scene coarse(const std::vector<std::string>& overrides) {
  std::vector<std::string> all = kCoarse;
  all.insert(all.end(), overrides.begin(), overrides.end());
  return load_scene_file(kScene, all);
}

// Every number a run reports, by name, to say which one is not finite.
std::vector<std::pair<const char*, double>> numbers(const FoundationRunResult& r) {
  return {
      {"wall_seconds", r.wall_seconds}, {"max_abs_ux", r.max_abs_ux}, {"max_abs_uy", r.max_abs_uy},
      {"phi_min", r.phi_min},           {"phi_max", r.phi_max},       {"uy_corner", r.uy_corner},
      {"ux_corner", r.ux_corner},       {"phi_center", r.phi_center}, {"max_abs_vtau_contact", r.max_abs_vtau_contact}};
}

// A run that writes its tables into a scratch directory, removed afterwards; gamma_c() reads the contact
// boundary's table (x, ux, uy, vx, vy, phi, contact_pressure per node).
class TableRun {
 public:
  TableRun(const Scene& scene, const std::string& foundation_name, const std::string& tag)
      : dir_(fs::temp_directory_path() / ("pc_extremes_" + std::to_string(getpid()) + "_" + tag)) {
    result = run_foundation(scene, find_foundation(scene, foundation_name), dir_.string(), false);
  }
  ~TableRun() {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  std::vector<std::vector<double>> gamma_c() const {
    std::ifstream in(dir_ / "gamma_c.csv");
    std::vector<std::vector<double>> rows;
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::vector<double> row;
      std::stringstream fields(line);
      for (std::string field; std::getline(fields, field, ',');) row.push_back(std::strtod(field.c_str(), nullptr));
      rows.push_back(row);
    }
    return rows;
  }
  FoundationRunResult result;

 private:
  fs::path dir_;
};

constexpr int kUy = 2, kPhi = 5;  // columns of gamma_c.csv in 2D

// ---- every case: complete with finite numbers, or stop and say why; and complete -----------------------

class ExtremeCaseTest : public ::testing::TestWithParam<ExtremeCase> {};

TEST_P(ExtremeCaseTest, CompletesWithFiniteResultsOrStopsWithAMessage) {
  const ExtremeCase& c = GetParam();
  const Scene scene = coarse(c.overrides);
  const FoundationRunResult r = run_foundation(scene, find_foundation(scene, c.foundation), "", false);
  std::printf("%s: %s, %d steps, Newton %d (max %d per step), max|uy| = %.4g m, phi in [%.6g, %.6g] V, %.3f s%s%s\n",
              c.name.c_str(), r.completed ? "completed" : "STOPPED", r.steps, r.newton_iterations_total,
              r.newton_iterations_max_per_step, r.max_abs_uy, r.phi_min, r.phi_max, r.wall_seconds,
              r.message.empty() ? "" : ": ", r.message.c_str());
  if (r.completed) {
    for (const auto& [name, value] : numbers(r)) EXPECT_TRUE(std::isfinite(value)) << name << " = " << value;
    EXPECT_GE(r.steps, scene.steps);
    EXPECT_GT(r.ndof, 0);
  } else {
    EXPECT_FALSE(r.message.empty()) << "a run that stops must say why";
  }
  // The contract above is the floor; each of these cases has a solution Newton must find.
  EXPECT_TRUE(r.completed) << r.message;
}

INSTANTIATE_TEST_SUITE_P(PaperScene, ExtremeCaseTest, ::testing::ValuesIn(testing::extreme_cases()),
                         [](const ::testing::TestParamInfo<ExtremeCase>& info) { return info.param.name; });

// ---- the limits ---------------------------------------------------------------------------------------------

// k_e = 0: the conductive foundation brick adds nothing, so the run is the insulated one.
TEST(Extremes, ZeroConductanceIsTheInsulatedFoundation) {
  const Scene scene = coarse({"foundation.conductive.k_e=0"});
  const FoundationRunResult conductive = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
  const FoundationRunResult insulated = run_foundation(scene, find_foundation(scene, "insulated"), "", false);
  ASSERT_TRUE(conductive.completed && insulated.completed) << conductive.message << insulated.message;
  const auto a = numbers(conductive), b = numbers(insulated);
  for (size_t i = 1; i < a.size(); ++i)  // all but the wall time
    EXPECT_NEAR(a[i].second, b[i].second, 1e-9 * std::abs(b[i].second)) << a[i].first;
  EXPECT_NE(insulated.phi_max, 0.0) << "the insulated run must have a potential to compare";
}

// k_e = 1e15 S/m^2 against a permittivity of 1e-8 F/m: the foundation imposes phi_f on the contact
// boundary to round-off, for any step size.
TEST(Extremes, HugeConductanceImposesTheFoundationPotential) {
  for (const char* steps : {"time.steps=10", "time.steps=1"}) {
    for (const double phi_f : {-48.0, 1e5}) {
      const Scene scene =
          coarse({"foundation.conductive.k_e=1e15", steps, "foundation.conductive.phi_f=" + std::to_string(phi_f)});
      const TableRun run(scene, "conductive", "k_e_1e15");
      ASSERT_TRUE(run.result.completed) << steps << ", phi_f = " << phi_f << ": " << run.result.message;
      const auto rows = run.gamma_c();
      ASSERT_EQ(rows.size(), 13u);
      double worst = 0;
      for (const auto& row : rows) worst = std::max(worst, std::abs(row[kPhi] - phi_f));
      std::printf("k_e = 1e15, %s, phi_f = %g V: max |phi - phi_f| on the contact boundary %.3g V\n", steps, phi_f,
                  worst);
      EXPECT_LE(worst, 1e-12 * std::abs(phi_f)) << steps << ", phi_f = " << phi_f;
    }
  }
}

// The normal damping resists the motion into the foundation: the penetration max(-u_y) over the contact
// nodes (insulated foundation, so the strip is pressed down) falls strictly as c_nu grows, to nothing.
TEST(Extremes, PenetrationFallsAsTheNormalDampingGrows) {
  std::vector<double> penetrations;
  for (const double c_nu : testing::penetration_c_nu()) {
    char value[64];
    std::snprintf(value, sizeof value, "contact.c_nu=%g", c_nu);
    const TableRun run(coarse({value}), "insulated", "c_nu");
    ASSERT_TRUE(run.result.completed) << value << ": " << run.result.message;
    double penetration = -INFINITY;
    for (const auto& row : run.gamma_c()) penetration = std::max(penetration, -row[kUy]);
    std::printf("c_nu = %g: penetration %.6e m, max|uy| %.6e m\n", c_nu, penetration, run.result.max_abs_uy);
    ASSERT_TRUE(std::isfinite(penetration));
    if (!penetrations.empty()) {
      EXPECT_LT(penetration, penetrations.back()) << value;
    }
    penetrations.push_back(penetration);
  }
  EXPECT_GT(penetrations.front(), 0.0) << "the soft foundation must be penetrated";
  EXPECT_LT(penetrations.back(), 1e-3 * penetrations.front()) << "c_nu = 1e16 must all but stop the penetration";
}

// phi_f = +-1e5 V through k_e = 1: the contact potential follows the foundation's (the scene's k_e puts
// it within 1%, see paper_scene_test), whatever the sign; phi_f = 0 leaves only the piezoelectric potential.
TEST(Extremes, ContactPotentialFollowsLargeFoundationVoltagesOfEitherSign) {
  for (const double phi_f : {1e5, -1e5}) {
    const Scene scene = coarse({"foundation.conductive.phi_f=" + std::to_string(phi_f)});
    const FoundationRunResult r = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
    ASSERT_TRUE(r.completed) << r.message;
    const double extreme = phi_f > 0 ? r.phi_max : r.phi_min;
    EXPECT_NEAR(extreme, phi_f, 0.01 * std::abs(phi_f)) << "phi_f = " << phi_f;
  }
  const Scene scene = coarse({"foundation.conductive.phi_f=0"});
  const FoundationRunResult r = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
  ASSERT_TRUE(r.completed) << r.message;
  EXPECT_LT(std::max(std::abs(r.phi_min), std::abs(r.phi_max)), 1e-2) << "no voltage source but the strain";
}

// With c_nu = 1e16 the contact block of the tangent exceeds the linear part's by ten orders: the
// condensed solve, by both methods (Schur complement of the interior; Woodbury columns of A^-1), must
// still reach the plain Newton's solution, in many steps and in one. Its steps may be less accurate there
// (columns: the residual after the first iteration of a step 3e-12 against 5e-19, from the cancellation
// in b - P^T D z), which may cost one more iteration per step, not more.
TEST(Extremes, CondensedSolveMatchesTheFullOneAtTheStiffestContact) {
  for (const char* steps : {"time.steps=10", "time.steps=1"})
    for (const char* method : {"schur", "columns"}) {
      const std::string where = std::string(steps) + ", " + method;
      const Scene condensed = coarse(
          {"contact.c_nu=1e16", steps, "solver.condensed=true", "solver.condensation=\"" + std::string(method) + "\""});
      const Scene full = coarse({"contact.c_nu=1e16", steps, "solver.condensed=false"});
      for (const std::string name : {"insulated", "conductive"}) {
        const FoundationRunResult a = run_foundation(condensed, find_foundation(condensed, name), "", false);
        const FoundationRunResult b = run_foundation(full, find_foundation(full, name), "", false);
        ASSERT_TRUE(a.completed && b.completed) << where << ", " << name << ": " << a.message << b.message;
        EXPECT_LE(a.newton_iterations_total, b.newton_iterations_total + a.steps) << where << ", " << name;
        const auto x = numbers(a), y = numbers(b);
        for (size_t i = 1; i < x.size(); ++i)
          EXPECT_NEAR(x[i].second, y[i].second, 1e-8 * std::abs(y[i].second) + 1e-20)
              << where << ", " << name << ": " << x[i].first;
      }
    }
}

// The stiffest contact without inertia or viscosity, P2 on 24 x 8: at rest every contact node sits on the
// kink of c_nu r_+, whose right-sided derivative makes the first Newton step hold them all; the active set
// then changes a few nodes per iteration, and a node that crosses the kink changes the residual by
// c_nu h |v_n|, so the residual norm jumps up and down by 1e3 while the full steps converge (semismooth
// Newton, at most 17 iterations on 60 x 20, P1 and P2). Armijo backtracking at every iteration stalls
// there (alpha 1e-3..1e-4, 25 iterations are not enough, and on 60 x 20 P2 the run stopped after
// cut-backs); the default globalisation, a watchdog, lets the full steps run as long as they improve on
// the best iterate within `watchdog` steps, and must need no cut-back.
Scene stiffest_contact() {
  return coarse({"mesh.nx=24", "mesh.ny=8", "mesh.order=2", "material.rho=0",
                 "material.viscosity_A=[[0,0,0],[0,0,0],[0,0,0]]", "contact.c_nu=1e16"});
}

TEST(Extremes, StiffestContactConvergesWithoutCutBack) {
  const Scene scene = stiffest_contact();
  const FoundationRunResult r = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
  ASSERT_TRUE(r.completed) << r.message;
  EXPECT_EQ(r.steps, scene.steps) << "a step was cut back";
  EXPECT_LT(r.newton_iterations_max_per_step, scene.newton.max_iterations);
}

// Budgets: a run stops cleanly when its step attempts or its wall time are spent, saying which.
TEST(Extremes, RunsStopAtTheirBudgetWithAMessageNamingIt) {
  const Scene capped = coarse({"time.max_attempts=3"});
  const FoundationRunResult a = run_foundation(capped, find_foundation(capped, "conductive"), "", false);
  EXPECT_FALSE(a.completed);
  EXPECT_EQ(a.steps, 3);
  EXPECT_NE(a.message.find("max_attempts = 3"), std::string::npos) << a.message;

  const Scene timed = coarse({"time.max_wall_seconds=1e-9"});
  const FoundationRunResult b = run_foundation(timed, find_foundation(timed, "conductive"), "", false);
  EXPECT_FALSE(b.completed);
  EXPECT_NE(b.message.find("wall-time limit"), std::string::npos) << b.message;

  EXPECT_THROW(coarse({"time.max_attempts=-1"}), Error);
}

}  // namespace
}  // namespace pc

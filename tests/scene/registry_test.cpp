// The registries as a scene meets them: every name a scene can give is registered with its parameters,
// the documentation's tables are the registries' own, `check` refuses what `run` would refuse with the
// key and the value named, and a parameter study reuses one model.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "models/scene/registry_catalog.hpp"
#include "models/scene/scene_runner.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

using testing::error_of;
using testing::read_text;

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";

Scene coarse(std::vector<std::string> overrides = {}) {
  overrides.insert(overrides.begin(), {"mesh.nx=15", "mesh.ny=5", "time.steps=20"});
  return load_scene_file(kScene, overrides);
}

std::string problem(const std::vector<std::string>& overrides) {
  return error_of([&] { coarse(overrides); });
}

TEST(Registry, DocsTablesAreTheRegistriesOwn) {
  const std::string docs = read_text(std::string(PIEZOCONTACT_SCENES) + "/../docs/scenes.md");
  const auto begin = docs.find("<!-- registry:begin"), end = docs.find("<!-- registry:end -->");
  ASSERT_NE(begin, std::string::npos);
  ASSERT_NE(end, std::string::npos);
  const auto first_line = docs.find('\n', begin) + 1;
  const std::string tables = docs.substr(first_line, end - first_line);
  std::string expected = catalog_markdown(registry_catalog());
  expected = expected.substr(expected.find_first_not_of('\n'));
  EXPECT_EQ(tables, expected) << "docs/scenes.md is out of date: run scripts/update_docs.sh";
}

TEST(Registry, EveryNameAScenesGivesIsRegistered) {
  const std::string list = catalog_list(registry_catalog());
  for (const char* line :
       {"piezoelectric materials (material.preset): BaTiO3 PZT-4 PZT-5A PZT-5H",
        "normal laws (contact.law_normal): linear_damped normal_compliance power_damped",
        "friction laws (contact.law_tangential): coulomb coulomb_exact none tresca viscous",
        "foundation laws (foundation.<name>.type): conductive insulated pressure_activated",
        "bricks (bricks[].type): boundary_dashpot", "time schemes (time.scheme): backward_euler bdf2 theta",
        "linear solvers (solver.linear): cholmod eigen-lu mumps umfpack",
        "condensations (solver.condensation): auto columns krylov schur"})
    EXPECT_CONTAINS(list, line);
  const std::string theta = catalog_describe(registry_catalog(), "theta");
  EXPECT_CONTAINS(theta, "time.scheme = \"theta\" (time scheme)");
  EXPECT_CONTAINS(theta, "time.theta [1] default 0.5, in (0, 1]");
  EXPECT_CONTAINS(catalog_describe(registry_catalog(), "coulomb"), "contact.eps [m/s] required, > 0");
  EXPECT_EQ(catalog_describe(registry_catalog(), "banana"), "");
}

// What a scene gets wrong is refused on loading, which `check` does, before any step is run.
TEST(Registry, CheckRefusesWhatRunWouldRefuseWithTheKeyAndTheValue) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"contact.law_normal=linaer_damped"},
       "'contact.law_normal': unknown normal law 'linaer_damped' (known: linear_damped, normal_compliance, "
       "power_damped)"},
      {{"contact.law_tangential=banana"},
       "unknown friction law 'banana' (known: coulomb, coulomb_exact, none, tresca, viscous)"},
      {{"foundation.conductive.type=superconductive"}, "unknown foundation law 'superconductive'"},
      {{"solver.condensation=diagonal"},
       "'solver.condensation': unknown condensation 'diagonal' (known: auto, columns, krylov, schur)"},
      {{"solver.linear=superlu"}, "'solver.linear': unknown linear solver 'superlu'"},
      {{"contact.c_nu=-1"}, "'contact.c_nu' (Pa s/m) must be >= 0, got -1"},
      {{"foundation.conductive.k_e=-2"}, "'foundation.conductive.k_e' (C/(V m^2)) must be >= 0, got -2"},
      {{"contact.law_tangential=coulomb", "contact.mu=0.3"},
       "'contact.c_tau' is read by law_tangential viscous, not by the chosen law_normal 'linear_damped' and "
       "law_tangential 'coulomb'"},
      {{"contact.mu=0.3"},
       "'contact.mu' is read by law_tangential coulomb, law_tangential coulomb_exact, not by the chosen"},
      {{"foundation.conductive.p_ref=1e3"},
       "'foundation.conductive.p_ref' is read by foundation type pressure_activated"},
      {{"contact.typo=1"}, "unknown key 'contact.typo'"},
      {{"foundation.conductive.type=pressure_activated"},
       "'foundation.conductive.p_ref' is required by foundation type 'pressure_activated'"},
      {{"time.scheme=bdf2", "time.theta=0.5"}, "'time.theta' is read by time.scheme theta, not by the chosen"},
      {{"regions.contact=\"\""}, "'regions.contact' is empty"},
      {{"name=\"\""}, "'name' is empty"},
      {{"name=../../escaped"}, "'name' = '../../escaped' must be a plain file name"},
      {{"output.probes.corner=[0.05,0.01]"}, "'output.probes.corner': the point (0.05, 0.01, 0) is outside the mesh"},
      {{"output.grid.x=[0,0.06,31]"}, "'output.grid': the point (0.032, 0, 0) is outside the mesh"},
      {{"mesh.gmsh=strip2d.geo"}, "'mesh' gives both generator and gmsh"},
      {{"material.viscosity_tau_v=0.02"}, "'material.viscosity_A' and 'material.viscosity_tau_v' disagree"},
      {{"solver.condensed_max_dofs=-1"}, "'solver.condensed_max_dofs'"},
      {{"solver.contact_newton=2"}, "'solver.contact_newton'"},
  };
  for (const auto& [overrides, expected] : cases) EXPECT_CONTAINS(problem(overrides), expected);
}

TEST(Registry, DefaultsAndRequiredParametersComeFromTheDeclarations) {
  // m and gap default to the law's own defaults; c_nu is required.
  const Scene compliance = coarse({"contact.law_normal=normal_compliance"});
  EXPECT_EQ(compliance.spec.normal.parameters, (ParameterValues{{"c_nu", 1e12}, {"m", 1.0}, {"gap", 0.0}}));
  const Scene paper = coarse();
  EXPECT_EQ(paper.spec.friction.name, "viscous");
  EXPECT_EQ(paper.spec.friction.parameters, (ParameterValues{{"c_tau", 0.3}}));
  EXPECT_EQ(find_foundation(paper, "conductive").law.parameters, (ParameterValues{{"k_e", 1.0}, {"phi_f", -48.0}}));
  EXPECT_EQ(paper.spec.scheme.name, "backward_euler");
}

// viscosity_tau_v is read: A = tau_v B when viscosity_A is absent.
TEST(Registry, ViscosityFromTheRelaxationTime) {
  std::string text = read_text(kScene);
  const auto key = text.find("\"viscosity_A\"");
  ASSERT_NE(key, std::string::npos);
  const auto close = text.find("]\n    ]", key);  // the matrix's last row and its own bracket
  ASSERT_NE(close, std::string::npos);
  text.replace(key, close + 7 - key, "\"viscosity_tau_v\": 0.02");
  const Scene scene = load_scene(parse_json(text, "tau_v scene"), PIEZOCONTACT_SCENES);
  EXPECT_EQ(scene.spec.A, 0.02 * scene.spec.B);
}

// The Figure 5 sweep: one model, phi_f changed between runs. The pattern, the symbolic analysis and the
// cached bulk bricks are kept (no element loop of a bulk brick runs again), and each run equals a run of a
// model built afresh for that phi_f.
TEST(Registry, AParameterStudyReusesOneModel) {
  const Scene scene = coarse({"time.steps=10"});
  const SceneFoundation& conductive = find_foundation(scene, "conductive");
  FoundationRun sweep(scene, conductive);
  const FoundationRunResult first = sweep.run("", false);
  ASSERT_TRUE(first.completed) << first.message;
  const Model& m = sweep.model();
  std::vector<std::int64_t> loops;
  for (int b = 0; b < int(m.bricks().size()); ++b) loops.push_back(m.elements_assembled(b));
  const int analyses = sweep.newton().analyses();

  for (double phi_f : {10.0, -48.0}) {
    sweep.model().set_constant("phi_f", phi_f);
    const FoundationRunResult reused = sweep.run("", false);
    SceneFoundation fresh_foundation = conductive;
    fresh_foundation.law.parameters["phi_f"] = phi_f;
    const FoundationRunResult fresh = run_foundation(scene, fresh_foundation, "", false);
    ASSERT_TRUE(reused.completed && fresh.completed);
    EXPECT_NEAR(reused.uy_corner, fresh.uy_corner, 1e-12 * std::abs(fresh.uy_corner)) << phi_f;
    EXPECT_NEAR(reused.phi_center, fresh.phi_center, 1e-12 * std::abs(fresh.phi_center)) << phi_f;
    // (Agreeing to 1e-12, not to the bit, a step may end one iteration apart on the two models.)
    EXPECT_LE(std::abs(reused.newton_iterations_total - fresh.newton_iterations_total), fresh.steps) << phi_f;
  }
  EXPECT_EQ(sweep.newton().analyses(), analyses) << "a new symbolic analysis";
  for (int b = 0; b < int(m.bricks().size()); ++b) {
    const std::string& name = m.bricks()[b]->name();
    // The foundation brick reads phi_f; nonlinear bricks and loads that vary in time run every step anyway.
    const Brick& brick = *m.bricks()[b];
    if (name.find("conductive foundation") != std::string::npos || !brick.linear() || brick.time_dependent()) continue;
    EXPECT_EQ(m.elements_assembled(b), loops[b]) << name << " was assembled again";
  }
  // And the voltage did act: phi at the centre moved with phi_f.
  sweep.model().set_constant("phi_f", 10.0);
  EXPECT_GT(sweep.run("", false).phi_center, first.phi_center + 1.0);
}

// A law parameter is a model constant: changing it re-runs the element loops of the bricks that read it
// and of no other; setting the value it already has re-runs none.
TEST(Registry, AChangedParameterRebuildsOnlyTheBricksThatReadIt) {
  const Scene scene = coarse();
  FoundationRun run(scene, find_foundation(scene, "conductive"));
  Model& m = run.model();
  m.assemble(true);
  auto loops = [&] {
    std::map<std::string, std::int64_t> out;
    for (int b = 0; b < int(m.bricks().size()); ++b) out[m.bricks()[b]->name()] = m.elements_assembled(b);
    return out;
  };
  const auto before = loops();
  m.set_constant("c_tau", 0.3);  // the value it has
  m.assemble(true);
  const auto same = loops();
  m.set_constant("c_tau", 0.6);
  m.assemble(true);
  const auto changed = loops();
  for (const auto& [name, count] : before) {
    const bool reads_c_tau = name == "friction on bottom";
    const bool nonlinear = name == "normal response on bottom";  // assembled at every Newton iteration
    if (nonlinear) continue;
    EXPECT_EQ(same.at(name), count) << name;
    if (reads_c_tau)
      EXPECT_GT(changed.at(name), same.at(name)) << name;
    else
      EXPECT_EQ(changed.at(name), same.at(name)) << name;
  }
  EXPECT_EQ(before.count("friction on bottom"), 1u);
}

}  // namespace
}  // namespace pc

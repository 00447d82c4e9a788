// One rule for keys (docs/scenes.md, "Keys: used or refused"): every key a scene gives is used by it or
// refused saying why, and a misspelt key or registered name is answered with the close known ones. The
// walk over every key of a generated scene; the gmsh scene's is scene_keys_rule_gmsh_test.cpp.
#include <gtest/gtest.h>

#include "assembly/suggestions.hpp"
#include "models/scene/json.hpp"
#include "models/scene/scene.hpp"
#include "scene/scene_keys_walk.hpp"
#include "support/shipped_scenes.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

using testing::error_of;
using testing::kPaperScene;

std::string problem_of(const std::vector<std::string>& overrides) {
  return error_of([&] { load_scene_file(kPaperScene, overrides); });
}

std::string one_problem(const std::string& problem) { return "scene 'paper2d' has 1 problem:\n  - " + problem; }

TEST(Suggestions, EditDistanceCountsInsertionsDeletionsSubstitutionsAndSwaps) {
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("c_nu", "c_nu"), 0u);
  EXPECT_EQ(edit_distance("c_nuu", "c_nu"), 1u);
  EXPECT_EQ(edit_distance("linaer_damped", "linear_damped"), 1u) << "a swapped pair is one typo";
  EXPECT_EQ(edit_distance("ab", "ba"), 1u);
}

TEST(Suggestions, OnlyCloseNamesAreSuggestedAndTiesAllOfThem) {
  const std::vector<std::string> contact = {"c_nu", "c_tau", "law_normal"};
  EXPECT_EQ(closest_names("c_nuu", contact), std::vector<std::string>{"c_nu"});
  EXPECT_EQ(closest_names("law_normla", contact), std::vector<std::string>{"law_normal"});
  EXPECT_TRUE(closest_names("mu", contact).empty()) << "two edits from c_nu, on a name of 4";
  EXPECT_TRUE(closest_names("friction", contact).empty());
  EXPECT_TRUE(closest_names("c_nu", contact).empty()) << "a known name needs no suggestion";
  EXPECT_EQ(closest_names("PZT-5X", {"BaTiO3", "PZT-4", "PZT-5A", "PZT-5H"}),
            (std::vector<std::string>{"PZT-5A", "PZT-5H"}));
  EXPECT_EQ(did_you_mean("c_nuu", contact), "; did you mean 'c_nu'?");
  EXPECT_EQ(did_you_mean("PZT-5X", {"PZT-5A", "PZT-5H"}), "; did you mean 'PZT-5A' or 'PZT-5H'?");
  EXPECT_EQ(did_you_mean("zzz", contact), "");
}

TEST(Suggestions, AMisspeltKeyIsAnsweredWithTheCloseKnownOne) {
  EXPECT_EQ(problem_of({"contact.c_nuu=1"}),
            one_problem("unknown key 'contact.c_nuu' (known: c_nu, c_tau, foundation_velocity, law_normal, "
                        "law_tangential); did you mean 'c_nu'?"));
  EXPECT_EQ(problem_of({"contact.zzzz=1"}),
            one_problem("unknown key 'contact.zzzz' (known: c_nu, c_tau, foundation_velocity, law_normal, "
                        "law_tangential)"));
  EXPECT_EQ(problem_of({"solver.thread=2", "solver.linaer=\"mumps\""}),
            one_problem("unknown keys 'solver.thread', 'solver.linaer' (known: condensation, condensed, "
                        "condensed_max_dofs, contact_newton, cutback_factor, line_search, linear, max_iterations, "
                        "max_memory_gib, relative_tolerance, threads, watchdog); did you mean 'threads' for "
                        "'thread', 'linear' for 'linaer'?"));
  EXPECT_CONTAINS(problem_of({"colour=1"}), "unknown key 'colour' (known: about,");
  EXPECT_CONTAINS(problem_of({"mesh.nxx=3"}), "; did you mean 'nx'?");
}

TEST(Suggestions, AMisspeltRegisteredNameIsAnsweredWithTheCloseKnownOnes) {
  EXPECT_EQ(problem_of({"contact.law_normal=linaer_damped"}),
            one_problem("'contact.law_normal': unknown normal law 'linaer_damped' (known: linear_damped, "
                        "normal_compliance, power_damped); did you mean 'linear_damped'?"));
  EXPECT_EQ(problem_of({"time.scheme=bdf3"}),
            one_problem("'time.scheme': unknown time scheme 'bdf3' (known: backward_euler, bdf2, theta); did you "
                        "mean 'bdf2'?"));
  EXPECT_CONTAINS(problem_of({"foundation.conductive.type=conductiv"}),
                  "'foundation.conductive.type': unknown foundation law 'conductiv' (known: conductive, insulated, "
                  "pressure_activated); did you mean 'conductive'?");
  EXPECT_CONTAINS(problem_of({R"(material={"preset": "PZT-5X", "poling": "y"})"}),
                  "(known: BaTiO3, PZT-4, PZT-5A, PZT-5H); did you mean 'PZT-5A' or 'PZT-5H'?");
  EXPECT_CONTAINS(problem_of({"output.vtu_fields=[\"stres\"]"}), "; did you mean 'stress'?");
  EXPECT_CONTAINS(problem_of({"solver.linear=superlu"}), "(known: cholmod, eigen-lu, mumps, umfpack)");
  EXPECT_EQ(problem_of({"solver.linear=superlu"}).find("did you mean"), std::string::npos);
}

// Each key that only another variant of its section reads, refused where it does not apply.
TEST(SceneKeysRule, AKeyOfAnotherVariantIsRefusedSayingWhy) {
  EXPECT_EQ(problem_of({"mesh.size_factor=0"}),
            one_problem("'mesh.size_factor' applies to gmsh meshes; this scene generates a rectangle"));
  EXPECT_EQ(problem_of({"mesh.size_factor=-0.5"}),
            one_problem("'mesh.size_factor' applies to gmsh meshes; this scene generates a rectangle"));
  EXPECT_EQ(problem_of({"mesh.max_seconds=60"}),
            one_problem("'mesh.max_seconds' applies to gmsh meshes; this scene generates a rectangle"));
  EXPECT_EQ(problem_of({"mesh.nz=4"}), one_problem("'mesh.nz' applies to a box; this scene generates a rectangle"));
  // A .msh file is read as it is: only a script's mesh sizes scale (refused before the file is read).
  EXPECT_EQ(problem_of({R"(mesh={"gmsh": "strip.msh", "order": 1, "size_factor": 2})"}),
            one_problem("'mesh.size_factor' scales the mesh sizes of a .geo script; this scene reads the mesh file "
                        "'strip.msh'"));
  EXPECT_EQ(problem_of({R"(mesh={"gmsh": "strip.geo", "order": 1, "nx": 2})"}),
            one_problem("'mesh.nx' applies to generated meshes (mesh.generator); this scene reads the gmsh file "
                        "'strip.geo'"));
  std::vector<std::string> box = testing::generated_box(3, 1, 1, "hexahedron");
  box.push_back("mesh.size_factor=2");
  EXPECT_CONTAINS(error_of([&] { load_scene_file(testing::kBoxScene, box); }),
                  "'mesh.size_factor' applies to gmsh meshes; this scene generates a box");
  EXPECT_EQ(problem_of({"solver.condensed=false", "solver.contact_newton=true"}),
            one_problem("'solver.contact_newton' applies to condensed solves; solver.condensed = false factorises "
                        "the whole system at every iteration"));
  EXPECT_EQ(problem_of({"solver.condensed=false", "solver.condensed_max_dofs=10"}),
            one_problem("'solver.condensed_max_dofs' applies to condensed solves; solver.condensed = false "
                        "factorises the whole system at every iteration"));
  EXPECT_EQ(problem_of({"solver.condensation=krylov", "solver.contact_newton=false"}),
            one_problem("'solver.contact_newton' applies to the schur path (solver.condensation schur, or auto); "
                        "this scene's is 'krylov'"));
  EXPECT_EQ(problem_of({"solver.line_search=false", "solver.watchdog=3"}),
            one_problem("'solver.watchdog' applies to the line search; solver.line_search = false takes full steps"));
  EXPECT_EQ(problem_of({"output.phi_f_sweep=[]", "output.sweep_steps=5"}),
            one_problem("'output.sweep_steps' is the steps of each run of the output.phi_f_sweep sweep, which this "
                        "scene lacks"));
  EXPECT_EQ(problem_of({"time.scheme=bdf2", "output.energy_books=true"}),
            one_problem("'output.energy_books' = true: the energy books are backward Euler's identities, and "
                        "time.scheme is 'bdf2'"));
}

// The same keys where they apply: read, with their effect.
TEST(SceneKeysRule, TheSameKeysAreReadWhereTheyApply) {
  const Scene schur = load_scene_file(kPaperScene, {"solver.condensation=schur", "solver.contact_newton=false"});
  EXPECT_FALSE(schur.newton.contact_newton);
  const Scene watched = load_scene_file(kPaperScene, {"solver.line_search=true", "solver.watchdog=3"});
  EXPECT_EQ(watched.newton.watchdog, 3);
  EXPECT_EQ(load_scene_file(kPaperScene, {"output.sweep_steps=7"}).output.sweep_steps, 7);
  EXPECT_FALSE(load_scene_file(kPaperScene, {"solver.condensed=false"}).newton.condensed_max_fraction > 0);
  // With target_error the mode chooses the scheme: the books are kept when it chooses backward Euler.
  EXPECT_TRUE(load_scene_file(kPaperScene, {"time.scheme=bdf2", "output.energy_books=true", "target_error=0.1"})
                  .output.energy_books);
}

// The paper scene made mechanical (no piezoelectric tensors), on an insulated foundation, with overrides.
Json mechanical_paper_scene(const std::vector<std::string>& overrides) {
  Json json = read_json_file(kPaperScene);
  Json material = Json::object();
  for (const auto& [key, value] : json.at("material").members())
    if (key != "piezo_E" && key != "permittivity_beta") material.set(key, value);
  json.set("material", material);
  apply_overrides(json, {R"(foundation={"insulated": {"type": "insulated"}})"});
  apply_overrides(json, overrides);
  return json;
}

TEST(SceneKeysRule, KeysOfAPotentialOrAContactRegionAreRefusedWithout) {
  const auto problems = [](const std::vector<std::string>& overrides) {
    return error_of([&] { load_scene(mechanical_paper_scene(overrides), PIEZOCONTACT_SCENES); });
  };
  EXPECT_EQ(problems({}), "(no error)");
  EXPECT_EQ(problems({"loads.q0=1e-3", "loads.q_b=0"}),
            one_problem("'loads.q0' = 0.001: a purely mechanical body (no material.piezo_E) has no charge to load"));
  EXPECT_EQ(problems({"time.u0=[1e-9, 0]", "output.energy_books=true"}),
            one_problem("'output.energy_books' = true: a purely mechanical body's books start at rest, and time.u0 "
                        "is not 0"));
  EXPECT_EQ(problems({"time.u0=[1e-9, 0]", "output.energy_books=false"}), "(no error)");
  // No contact region: the contact laws and the contact nodes' outputs have nothing to read them.
  EXPECT_EQ(problems({R"(regions={"clamped": ["left"], "grounded": ["top"]})", "output.contact_history=true"}),
            "scene 'paper2d' has 2 problems:\n"
            "  - 'contact' applies to a contact region (regions.contact); this scene has none\n"
            "  - 'output.contact_history' applies to a contact region (regions.contact); this scene has none");
  // ... and the same body without them loads.
  Json json = mechanical_paper_scene({R"(regions={"clamped": ["left"], "grounded": ["top"]})"});
  Json without_contact = Json::object();
  for (const auto& [key, value] : json.members())
    if (key != "contact") without_contact.set(key, value);
  Json output = Json::object();
  for (const auto& [key, value] : json.at("output").members())
    if (key != "slip_threshold") output.set(key, value);
  without_contact.set("output", output);
  EXPECT_TRUE(load_scene(without_contact, PIEZOCONTACT_SCENES).spec.contact.empty());
}

TEST(SceneKeysRule, EveryKeyOfAGeneratedSceneIsReadOrRefusedSayingWhy) {
  std::vector<testing::KeyAnswer> answers = testing::answers_beyond_the_mesh("right");
  const std::string geo = std::string(PIEZOCONTACT_TEST_DATA) + "/rectangle.geo";
  const std::string generated = "applies to gmsh meshes; this scene generates a rectangle";
  const std::string box = "applies to a box; this scene generates a rectangle";
  answers.insert(answers.end(), {{"mesh.generator", "rectangle", ""},
                                 {"mesh.gmsh", geo, "gives both generator and gmsh"},
                                 {"mesh.x", "[0, 0.03]", ""},
                                 {"mesh.y", "[0, 0.01]", ""},
                                 {"mesh.z", "[0, 0.01]", box},
                                 {"mesh.nx", "30", ""},
                                 {"mesh.ny", "10", ""},
                                 {"mesh.nz", "4", box},
                                 {"mesh.cell", "quadrilateral", ""},
                                 {"mesh.order", "2", ""},
                                 {"mesh.size_factor", "0.5", generated},
                                 {"mesh.max_seconds", "60", generated},
                                 {"target_error", "0.1", ""}});
  testing::walk_every_key(testing::scene_with_every_object({}, "right"), answers);
}

}  // namespace
}  // namespace pc

#pragma once
// The key rule (docs/scenes.md): every key a scene gives is used by it or refused saying why. A walk over
// every key the reader knows, read off the reader's own refusal of an unknown key in each object, so that
// a key added to the reader without an entry here fails the walk. Each key is set on its own in a scene
// and must load, or be refused with a message naming the key and why. Shared by the walk of a generated
// scene (scene_keys_rule_test.cpp) and of a gmsh one (scene_keys_rule_gmsh_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "models/scene/json.hpp"
#include "models/scene/scene.hpp"
#include "support/shipped_scenes.hpp"
#include "support/test_helpers.hpp"

namespace pc::testing {

// The paper scene with an electrode and a brick on the face region `side` and adaptive steps, so that every
// object of the schema is in it; `overrides` then (a gmsh scene's mesh and regions).
inline Json scene_with_every_object(const std::vector<std::string>& overrides, const std::string& side) {
  Json json = read_json_file(kPaperScene);
  apply_overrides(json, {R"(electrodes=[{"name": "e", "region": ")" + side + R"(", "voltage": 1}])",
                         R"(bricks=[{"type": "boundary_dashpot", "region": ")" + side + R"(", "c_b": 1e6}])",
                         R"(time.adaptive={"tolerance": 1e-3})"});
  apply_overrides(json, overrides);
  return json;
}

// The objects of the schema, by path ("" is the top level).
inline const std::vector<std::string>& schema_objects() {
  static const std::vector<std::string> objects = {"",
                                                   "mesh",
                                                   "material",
                                                   "regions",
                                                   "loads",
                                                   "loads.traction[0]",
                                                   "contact",
                                                   "foundation.conductive",
                                                   "electrodes[0]",
                                                   "bricks[0]",
                                                   "time",
                                                   "time.adaptive",
                                                   "solver",
                                                   "output",
                                                   "output.probes",
                                                   "output.grid"};
  return objects;
}

// The keys the reader allows in the object at `path`, from its refusal of an unknown one: "(known: a, b)".
inline std::vector<std::string> known_keys(const Json& scene, const std::string& path) {
  Json json = scene;
  const std::string probe = (path.empty() ? "" : path + ".") + "zz_not_a_key";
  apply_overrides(json, {probe + "=0"});
  const std::string what = error_of([&] { load_scene(json, PIEZOCONTACT_SCENES); });
  const std::string opening = "unknown key '" + probe + "' (known: ";
  const auto at = what.find(opening);
  if (at == std::string::npos) {
    ADD_FAILURE() << "the reader does not refuse '" << probe << "' as unknown: " << what;
    return {};
  }
  const auto from = at + opening.size();
  const std::string list = what.substr(from, what.find(')', from) - from);
  std::vector<std::string> keys;
  for (size_t start = 0; start <= list.size();) {
    const size_t comma = std::min(list.find(", ", start), list.size());
    keys.push_back((path.empty() ? "" : path + ".") + list.substr(start, comma - start));
    start = comma + 2;
  }
  return keys;
}

// A key set on its own: what the scene answers. `refusal` empty: it loads; else its message names the key
// and holds `refusal` (why). An empty value: an object the scene gives, whose keys are walked.
struct KeyAnswer {
  std::string key;    // "mesh.size_factor"
  std::string value;  // the --set value
  std::string refusal;
};

// Every key of every object of `scene` has an answer, and each answer holds: loaded, or refused saying why.
inline void walk_every_key(const Json& scene, const std::vector<KeyAnswer>& answers) {
  std::vector<std::string> walked;
  for (const std::string& object : schema_objects())
    for (const std::string& key : known_keys(scene, object)) {
      walked.push_back(key);
      const bool answered =
          std::any_of(answers.begin(), answers.end(), [&](const KeyAnswer& a) { return a.key == key; });
      EXPECT_TRUE(answered) << "'" << key << "': the reader knows it, the walk has no answer for it";
    }
  for (const KeyAnswer& a : answers) {
    EXPECT_NE(std::find(walked.begin(), walked.end(), a.key), walked.end()) << "'" << a.key << "' is not a key";
    if (a.value.empty()) continue;  // an object of the scene, walked key by key
    Json json = scene;
    apply_overrides(json, {a.key + "=" + a.value});
    const std::string what = error_of([&] { load_scene(json, PIEZOCONTACT_SCENES); });
    if (a.refusal.empty()) {
      EXPECT_EQ(what, "(no error)") << a.key << "=" << a.value;
    } else {
      // Named by its path, or by its own name where the message is about its object ("a floating electrode").
      const std::string leaf = a.key.substr(a.key.find_last_of('.') + 1);
      EXPECT_TRUE(what.find("'" + a.key + "'") != std::string::npos || what.find(leaf) != std::string::npos)
          << a.key << "=" << a.value << ": " << what;
      EXPECT_NE(what.find(a.refusal), std::string::npos) << a.key << "=" << a.value << ": " << what;
    }
  }
}

// The answers both scenes give, the mesh aside: each key with a value the scene reads.
inline std::vector<KeyAnswer> answers_beyond_the_mesh(const std::string& side) {
  return {
      {"name", "\"walk\"", ""},
      {"about", "\"a description, documentation only\"", ""},
      {"plugins", "[]", ""},
      {"mesh", "", ""},  // the objects themselves: their keys are walked one by one
      {"regions", "", ""},
      {"material", "", ""},
      {"contact", "", ""},
      {"foundation", "", ""},
      {"loads", "", ""},
      {"time", "", ""},
      {"solver", "", ""},
      {"output", "", ""},
      {"electrodes", "[]", ""},
      {"bricks", "[]", ""},
      {"material.name", "\"documentation only\"", ""},
      {"material.voigt_order", "[\"documentation only\"]", ""},
      {"material.rho", "7000", ""},
      {"material.elasticity_B", "[[1.27205e11, 8.46702e10, 0], [8.46702e10, 1.17436e11, 0], [0, 0, 2.29885e10]]", ""},
      {"material.viscosity_A", "[[1.27205e9, 8.46702e8, 0], [8.46702e8, 1.17436e9, 0], [0, 0, 2.29885e8]]", ""},
      {"material.viscosity_tau_v", "0.02", "disagree (A != tau_v B): give one of them"},
      {"material.piezo_E", "[[0, 0, 17], [-6.6, 23.2, 0]]", ""},
      {"material.permittivity_beta", "[[1.5e-8, 0], [0, 1.3e-8]]", ""},
      {"material.preset", "PZT-5H", "'material.poling' is required with 'material.preset'"},
      {"material.poling", "y", "goes with 'material.preset'"},
      {"regions.clamped", "[\"" + side + "\"]", ""},
      {"regions.traction", "[\"documentation only\"]", ""},
      {"regions.contact", "\"\"", "is empty: name the contact region, or leave the key out"},
      {"regions.grounded", "[\"top\"]", ""},
      {"regions.charge", "[\"" + side + "\"]", ""},
      {"loads.f0", "[0, -1]", ""},
      {"loads.traction", "[]", ""},
      {"loads.q0", "1e-3", ""},
      {"loads.q_b", "1e-4", ""},
      {"loads.traction[0].region", "\"" + side + "\"", ""},
      {"loads.traction[0].value", "[1, 0]", ""},
      {"loads.traction[0].time", "constant", ""},
      // Another law's or foundation type's parameters are refused by the registries' rule (registry_test.cpp).
      {"contact.law_normal", "linear_damped", ""},
      {"contact.law_tangential", "viscous", ""},
      {"contact.foundation_velocity", "[0, 1e-3]", ""},
      {"contact.c_nu", "1e13", ""},
      {"contact.c_tau", "0.5", ""},
      {"foundation.conductive.type", "conductive", ""},
      {"foundation.conductive.k_e", "2", ""},
      {"foundation.conductive.phi_f", "-24", ""},
      {"electrodes[0].name", "f", ""},
      {"electrodes[0].region", "\"" + side + "\"", ""},
      {"electrodes[0].voltage", "2", ""},
      {"electrodes[0].floating", "true", "a floating electrode's voltage is computed"},
      {"electrodes[0].charge", "0", "a driven electrode's charge is measured"},
      {"bricks[0].type", "boundary_dashpot", ""},
      {"bricks[0].region", "\"" + side + "\"", ""},
      {"bricks[0].c_b", "2e6", ""},
      {"time.T", "0.1", ""},
      {"time.steps", "100", ""},
      {"time.u0", "[1e-9, 0]", ""},
      {"time.v0", "[0, 1e-6]", ""},
      {"time.prediction", "zero", ""},
      {"time.scheme", "bdf2", ""},
      {"time.max_attempts", "1000", ""},
      {"time.max_wall_seconds", "3600", ""},
      {"time.adaptive", "1e-4", ""},
      {"time.error_estimate", "summed", ""},
      {"time.adaptive.tolerance", "1e-4", ""},
      {"time.adaptive.max_step", "0.01", ""},
      {"time.adaptive.factorization_cost", "3", ""},
      {"solver.linear", "umfpack", ""},
      {"solver.max_iterations", "30", ""},
      {"solver.relative_tolerance", "1e-9", ""},
      {"solver.line_search", "false", ""},
      {"solver.watchdog", "4", ""},
      {"solver.cutback_factor", "0.25", ""},
      {"solver.condensed", "false", ""},
      {"solver.condensation", "schur", ""},
      {"solver.condensed_max_dofs", "100", ""},
      {"solver.contact_newton", "false", ""},
      {"solver.max_memory_gib", "100", ""},
      {"solver.threads", "1", ""},
      {"output.vtu_every", "5", ""},
      {"output.vtu_format", "zlib", ""},
      {"output.vtu_fields", "[\"u\", \"phi\"]", ""},
      {"output.progress_every", "5", ""},
      {"output.space_error_every", "1", ""},
      {"output.checkpoint_every", "0", ""},
      {"output.probes", R"({"corner": [0.03, 0.01], "center": [0.01, 0.005]})", ""},
      {"output.probes.corner", "[0.02, 0.01]", ""},
      {"output.probes.center", "[0.01, 0.004]", ""},
      {"output.grid", R"({"x": [0, 0.03, 4], "y": [0, 0.01, 3]})", ""},
      {"output.grid.x", "[0, 0.03, 7]", ""},
      {"output.grid.y", "[0, 0.01, 2]", ""},
      {"output.slip_threshold", "1e-12", ""},
      {"output.phi_f_sweep", "[1, 2]", ""},
      {"output.sweep_steps", "5", ""},
      {"output.contact_history", "true", ""},
      {"output.energy_books", "true", ""},
  };
}

}  // namespace pc::testing

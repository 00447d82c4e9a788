// Plugins as a scene meets them: a law of a user's shared library is named in a scene and read, checked,
// listed and run like a built-in one; a missing file, a library that is no plugin, a plugin built against
// another version and a plugin whose name clashes with a registered one are refused, naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "assembly/version.hpp"
#include "bricks/law_registry.hpp"
#include "models/scene/plugins.hpp"
#include "models/scene/registry_catalog.hpp"
#include "models/scene/scene_runner.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

using testing::error_of;

const std::string kPlugins = PIEZOCONTACT_TEST_PLUGINS;
const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";

std::string plugin(const std::string& name) { return kPlugins + "/lib" + name + ".so"; }

// The paper's scene on a coarse mesh with the plugin's normal law and a plugins list.
Scene scene_with_plugins(const std::string& plugins_json, const std::vector<std::string>& more = {}) {
  std::vector<std::string> overrides = {"mesh.nx=15", "mesh.ny=5", "time.steps=10", "plugins=" + plugins_json};
  overrides.insert(overrides.end(), more.begin(), more.end());
  return load_scene_file(kScene, overrides);
}

TEST(Plugins, ALawOfAPluginIsNamedCheckedListedAndRunLikeABuiltInOne) {
  const std::string path = plugin("quadratic_damping_plugin");
  // Before loading, the scene may not name it; the message lists what is registered.
  EXPECT_CONTAINS(error_of([] { load_scene_file(kScene, {"contact.law_normal=quadratic_damped"}); }),
                  "unknown normal law 'quadratic_damped'");

  const Scene scene =
      scene_with_plugins("[\"" + path + "\"]", {"contact.law_normal=quadratic_damped", "contact.c_nu=1e20"});
  EXPECT_EQ(scene.spec.normal.name, "quadratic_damped");
  EXPECT_EQ(scene.spec.normal.parameters, (ParameterValues{{"c_nu", 1e20}}));
  ASSERT_NE(normal_law_registry().find("quadratic_damped"), nullptr);
  EXPECT_CONTAINS(catalog_list(registry_catalog()), "power_damped quadratic_damped");
  EXPECT_CONTAINS(catalog_describe(registry_catalog(), "quadratic_damped"), "contact.c_nu [Pa s^2/m^2] required, >= 0");

  // Its parameters are checked like a built-in law's: range, keys it does not read.
  EXPECT_CONTAINS(
      error_of([&] {
        scene_with_plugins("[\"" + path + "\"]", {"contact.law_normal=quadratic_damped", "contact.c_nu=-1"});
      }),
      "'contact.c_nu' (Pa s^2/m^2) must be >= 0, got -1");
  EXPECT_CONTAINS(error_of([&] {
                    scene_with_plugins("[\"" + path + "\"]", {"contact.law_normal=quadratic_damped", "contact.m=2"});
                  }),
                  "'contact.m' is read by law_normal normal_compliance, law_normal power_damped, not by the chosen "
                  "law_normal 'quadratic_damped'");

  // And it runs: the body is pressed on a foundation whose response the plugin's law gives.
  const FoundationRunResult r = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
  ASSERT_TRUE(r.completed) << r.message;
  EXPECT_GT(r.max_abs_ux, 0.0);

  // A plugin's brick too: the scene adds it over a region, its parameter a model constant.
  const Scene with_brick = scene_with_plugins(
      "[\"" + path + "\"]", {"bricks=[{\"type\": \"plugin_dashpot\", \"region\": \"right\", \"c_plugin\": 1e3}]"});
  PiezoContactSpec spec = with_brick.spec;
  const PiezoContactModel built = build_piezo_contact_model(spec);
  bool found = false;
  for (const auto& b : built.model->bricks()) found = found || b->name() == "boundary dashpot (c_plugin) on right";
  EXPECT_TRUE(found);
  EXPECT_EQ(built.model->scalar("c_plugin"), 1e3);
  EXPECT_CONTAINS(error_of([&] {
                    scene_with_plugins("[\"" + path + "\"]",
                                       {"bricks=[{\"type\": \"plugin_dashpot\", \"region\": \"right\"}]"});
                  }),
                  "'bricks[0].c_plugin' is required by brick type 'plugin_dashpot'");

  // Loading the same file again (another scene naming it) is a no-op.
  EXPECT_NO_THROW(load_plugin(path));
  EXPECT_EQ(std::count(loaded_plugins().begin(), loaded_plugins().end(), std::filesystem::canonical(path).string()), 1);
}

TEST(Plugins, BadPluginsAreRefusedNamingTheFile) {
  const auto problem = [](const std::string& path) { return error_of([&] { load_plugin(path); }); };
  EXPECT_CONTAINS(problem(kPlugins + "/libmissing.so"), "plugin '" + kPlugins + "/libmissing.so': no such file");
  EXPECT_CONTAINS(problem(plugin("not_a_plugin")), "not a piezocontact plugin");
  EXPECT_CONTAINS(problem(plugin("other_version_plugin")),
                  "was built against piezocontact 9.9.9, but this is piezocontact " PIEZOCONTACT_VERSION);
  EXPECT_CONTAINS(problem(plugin("clashing_plugin")), "normal law registry: 'linear_damped' is registered twice");
  const std::string text = (std::filesystem::temp_directory_path() / "piezocontact_text_plugin.so").string();
  std::ofstream(text) << "not a shared library\n";
  EXPECT_CONTAINS(problem(text), "cannot be loaded");
  // In a scene, the message carries the key's path.
  EXPECT_CONTAINS(error_of([] { scene_with_plugins("[\"libmissing.so\"]"); }),
                  "'plugins[0]': plugin '" + std::string(PIEZOCONTACT_SCENES) + "/libmissing.so': no such file");
}

}  // namespace
}  // namespace pc

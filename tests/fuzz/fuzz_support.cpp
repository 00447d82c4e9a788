#include "fuzz_support.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "models/scene/scene.hpp"
#include "models/scene/scene_runner.hpp"

namespace pc::fuzz {
namespace {

// The cap on a fuzzed scene's estimated memory: the paper's 60 x 20 P1 mesh (3843 dofs, ~30 MiB) fits,
// 100 x 100 does not. Small enough that no input makes the target build a mesh that takes long.
constexpr double kMaxMemoryGib = 0.05;

}  // namespace

Outcome& last_outcome() {
  static Outcome outcome;
  return outcome;
}

void finding(const char* target, const std::string& what) {
  std::fprintf(stderr, "fuzz finding in %s: %s\n", target, what.c_str());
  std::fflush(stderr);
  std::abort();
}

Json bounded_for_fuzzing(Json scene) {
  if (!scene.is_object()) return scene;
  if (const auto plugins = scene.find("plugins"); plugins && plugins->is_array()) scene.set("plugins", Json::array());
  if (auto mesh = scene.find("mesh"); mesh && mesh->is_object() && mesh->contains("gmsh")) {
    mesh->set("gmsh", Json("no-such-file-when-fuzzing.msh"));
    scene.set("mesh", std::move(*mesh));
  }
  auto solver = scene.find("solver");
  if (!solver) solver = Json::object();
  if (!solver->is_object()) return scene;  // refused by load_scene, naming 'solver'
  const auto cap = solver->find("max_memory_gib");
  if (cap && !cap->is_number()) return scene;  // refused, naming 'solver.max_memory_gib'
  solver->set("max_memory_gib", Json(cap ? std::min(cap->as_number(), kMaxMemoryGib) : kMaxMemoryGib));
  scene.set("solver", std::move(*solver));
  return scene;
}

void check_scene(const Json& json) {
  // Relative paths (plugins, gmsh files) resolve against a folder that does not exist.
  const Scene scene = load_scene(bounded_for_fuzzing(json), "/nonexistent/piezocontact-fuzz");
  for (const SceneFoundation& f : scene.foundations) FoundationRun run(scene, f);
}

}  // namespace pc::fuzz

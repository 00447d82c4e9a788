#pragma once
// Private to load_scene (models/scene/scene.cpp): a scene read section by section, each section one function
// with its own keys and checks, every problem collected. A section reads what earlier ones left in the
// SceneReading (the mesh's dimension, whether the body is piezoelectric), so load_scene calls them in order.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "assembly/error.hpp"
#include "bricks/piezo_materials.hpp"
#include "models/scene/json.hpp"
#include "models/scene/scene.hpp"

namespace pc::scene_detail {

// Collects every problem instead of stopping at the first, so that one run of `check` lists them all.
class Problems {
 public:
  // Runs the check; a pc::Error it throws becomes one problem and the result is empty.
  template <class F> auto check(F&& f) -> std::optional<decltype(f())> {
    try {
      return f();
    } catch (const Error& e) {
      add(e.what());
      return std::nullopt;
    }
  }
  void check_void(const std::function<void()>& f) {
    try {
      f();
    } catch (const Error& e) {
      add(e.what());
    }
  }
  void add(std::string problem) {
    if (problem.rfind("scene: ", 0) == 0) problem = problem.substr(7);
    list_.push_back(std::move(problem));
  }
  void throw_if_any(const std::string& scene) const {
    if (list_.empty()) return;
    std::string text = message("scene '", scene, "' has ", list_.size(), " problem", list_.size() > 1 ? "s" : "", ":");
    for (const std::string& p : list_) text += "\n  - " + p;
    throw Error(text);
  }

 private:
  std::vector<std::string> list_;
};

// A scene being read: its JSON, the scene read so far, the problems found so far, and what the sections
// read for the later ones.
struct SceneReading {
  const Json& json;
  const std::string& directory;  // what relative paths in the scene resolve against
  Scene& scene;
  PiezoContactSpec& spec;  // scene.spec
  Problems problems{};
  int dim = 2;  // the mesh's (read_mesh); 2 without a mesh
  // The material's preset (read_material): its tensors when found, and whether one was named, found or not
  // (if not, its tensors are not missing).
  std::optional<PiezoTensors> preset{};
  bool preset_named = false;
  bool electric = false;  // a piezoelectric body (read_material_tensors)
};

// One section of the scene: its keys read into the SceneReading and checked, each problem added.
using SceneSection = void (*)(SceneReading&);

// name: a plain file name; "unnamed" when it is missing or not one.
void read_name(SceneReading& r);
// The top level: only the known sections.
void check_top_level_keys(SceneReading& r);
// plugins: loaded first, since the laws they register are names the rest of the scene may use.
void load_plugins(SceneReading& r);
// mesh: generated or read from a gmsh file, its order, and the dimension the later sections read in.
void read_mesh(SceneReading& r);
// material: its keys, the preset and the density.
void read_material(SceneReading& r);
// material: the elasticity, viscosity and piezoelectric tensors; then whether the body is piezoelectric.
void read_material_tensors(SceneReading& r);
// regions: the face regions clamped, grounded, in contact and charged.
void read_regions(SceneReading& r);
// loads: the body force, tractions and charges.
void read_loads(SceneReading& r);
// contact: the normal and tangential laws and the foundation's motion (with a contact region only).
void read_contact(SceneReading& r);
// electrodes: driven or floating, each on a face region.
void read_electrodes(SceneReading& r);
// foundation: the foundations to run, each a registered foundation law.
void read_foundations(SceneReading& r);
// bricks: registered bricks beyond the recipe's, each over a region of the mesh.
void read_bricks(SceneReading& r);
// time: the scheme, span, steps, time error estimate, adaptive steps and initial state; and target_error.
void read_time(SceneReading& r);
// solver: Newton's options, the linear solver, the condensation, threads and memory.
void read_solver(SceneReading& r);
// output: what is written and how often.
void read_output(SceneReading& r);
// output: every probe and grid point inside the mesh.
void check_output_points(SceneReading& r);

}  // namespace pc::scene_detail

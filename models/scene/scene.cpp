#include "models/scene/scene.hpp"

#include <algorithm>
#include <filesystem>
#include <new>

#include "assembly/error.hpp"
#include "models/scene/scene_sections.hpp"

namespace pc {

const std::vector<SceneVtuField>& scene_vtu_fields() {
  static const std::vector<SceneVtuField> fields = {{"v", false},
                                                    {"u", false},
                                                    {"phi", true},
                                                    {"contact_pressure", false},
                                                    {"contact_state", false},
                                                    {"strain", false},
                                                    {"stress", false},
                                                    {"von_mises", false},
                                                    {"electric_field", true},
                                                    {"electric_displacement", true},
                                                    {"space_error", false}};
  return fields;
}

bool SceneOutput::writes_vtu_field(const std::string& name) const {
  return vtu_fields.empty() || std::find(vtu_fields.begin(), vtu_fields.end(), name) != vtu_fields.end();
}

Scene load_scene(const Json& json, const std::string& directory) {
  Scene scene;
  scene.json = json;
  scene.directory = directory;
  using namespace scene_detail;
  SceneReading reading{json, directory, scene, scene.spec};
  // The sections in the order they are read: a later one uses what an earlier one read (the plugins' laws,
  // the mesh's dimension and regions, whether the body is piezoelectric, the contact region).
  static constexpr SceneSection sections[] = {
      read_name,    check_top_level_keys, load_plugins, read_mesh,          read_material,    read_material_tensors,
      read_regions, read_loads,           read_contact, read_electrodes,    read_foundations, read_bricks,
      read_time,    read_solver,          read_output,  check_output_points};
  for (const SceneSection section : sections) section(reading);
  reading.problems.throw_if_any(scene.name);
  return scene;
}

void apply_overrides(Json& json, const std::vector<std::string>& overrides) {
  for (const std::string& o : overrides) {
    const auto eq = o.find('=');
    require(eq != std::string::npos && eq > 0, "--set '", o, "': expected key=value, e.g. --set contact.c_nu=1e14");
    // A key the file omits may be set (e.g. time.scheme): load_scene checks every key against the ones
    // its object knows, so a misspelt one is still refused, with the known keys listed.
    const std::string key = o.substr(0, eq);
    json.set_path(key, parse_json_value_from_cli(o.substr(eq + 1), "--set " + key), Json::NewKeys::allow);
  }
}

Scene load_scene_file(const std::string& path, const std::vector<std::string>& overrides) {
  Json json = read_json_file(path);
  apply_overrides(json, overrides);
  Scene scene;
  try {
    scene = load_scene(json, std::filesystem::path(path).parent_path().string());
  } catch (const std::bad_alloc& e) {
    fail("out of memory while reading the scene '", path, "' and building its mesh: ", e.what(),
         "; coarsen the mesh, or free memory");
  }
  scene.file = path;
  scene.overrides = overrides;
  return scene;
}

std::vector<std::array<double, 3>> SceneGrid::points() const {
  auto along = [](double a, double b, int n, int i) { return n > 1 ? a + (b - a) * i / (n - 1) : a; };
  std::vector<std::array<double, 3>> out;
  for (int k = 0; k < std::max(nz, 1); ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) out.push_back({along(x0, x1, nx, i), along(y0, y1, ny, j), along(z0, z1, nz, k)});
  return out;
}

const SceneFoundation& find_foundation(const Scene& scene, const std::string& name) {
  std::string known;
  for (const SceneFoundation& f : scene.foundations) {
    if (f.name == name) return f;
    known += (known.empty() ? "" : ", ") + f.name;
  }
  fail("scene '", scene.name, "' has no foundation '", name, "' (it has: ", known, ")");
}

}  // namespace pc

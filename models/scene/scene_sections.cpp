// The sections of a scene (models/scene/scene_sections.hpp), each read and checked on its own; load_scene
// (scene.cpp) calls them in order.
#include "models/scene/scene_sections.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "assembly/error.hpp"
#include "assembly/gmsh_import.hpp"
#include "assembly/mesh_generators.hpp"
#include "assembly/point_locator.hpp"
#include "assembly/suggestions.hpp"
#include "bricks/brick_registry.hpp"
#include "bricks/law_registry.hpp"
#include "bricks/piezo_materials.hpp"
#include "bricks/voigt.hpp"
#include "models/scene/memory_estimate.hpp"
#include "models/scene/plugins.hpp"
#include "models/scene/registered_keys.hpp"
#include "models/scene/scene_time_function.hpp"
#include "models/solvers/condensed_solve.hpp"

namespace pc {
namespace {

std::vector<std::string> names_of(const Json& j) {
  if (j.is_string()) return {j.as_string()};
  std::vector<std::string> names;
  for (const Json& item : j.as_array()) names.push_back(item.as_string());
  return names;
}

// Every key a scene gives is used or refused: a key that only another variant of its section reads (a gmsh
// mesh's size_factor in a generated one, a box's nz in a rectangle) is refused saying why, not ignored.
void refuse_keys(const Json& object, std::initializer_list<const char*> keys, const std::string& why) {
  for (const char* key : keys)
    if (const auto value = object.find(key)) fail("scene: '", value->path(), "' ", why);
}

// regions is read and names no contact region: the keys of contact only would then be ignored.
bool lacks_contact_region(const Json& scene_json) {
  const auto regions = scene_json.find("regions");
  return regions && regions->is_object() && !regions->contains("contact");
}

bool is_geo_script(const std::string& file) {
  std::string extension = std::filesystem::path(file).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension == ".geo";
}

// The mesh keys of the variants this mesh is not: a generator's in a gmsh mesh, a script's with a .msh
// file, a gmsh file's in a generated mesh, a box's in a rectangle.
void refuse_other_mesh_keys(const Json& m) {
  if (const auto file = m.find("gmsh")) {
    const std::string name = file->as_string();
    refuse_keys(m, {"cell", "x", "y", "z", "nx", "ny", "nz"},
                "applies to generated meshes (mesh.generator); this scene reads the gmsh file '" + name + "'");
    if (!is_geo_script(name))
      refuse_keys(m, {"size_factor"},
                  "scales the mesh sizes of a .geo script; this scene reads the mesh file '" + name + "'");
    return;
  }
  const auto generator = m.find("generator");
  if (!generator || !generator->is_string()) return;  // refused by build_mesh
  const std::string shape = generator->as_string();
  if (shape != "rectangle" && shape != "box") return;
  refuse_keys(m, {"size_factor", "max_seconds"}, "applies to gmsh meshes; this scene generates a " + shape);
  if (shape == "rectangle") refuse_keys(m, {"z", "nz"}, "applies to a box; this scene generates a rectangle");
}

// Refuses a generated mesh whose run would not fit in memory: the machine's available memory, or the
// user's solver.max_memory_gib.
struct MemoryLimit {
  double bytes = 0;  // 0: unknown
  std::string source;
};

// The machine's available memory, or the user's solver.max_memory_gib.
MemoryLimit memory_limit(const Json& scene_json) {
  MemoryLimit limit{available_memory_bytes(), "available to this run (the machine's free memory, or ulimit -v)"};
  if (const auto solver = scene_json.find("solver"))
    if (const auto cap = solver->find("max_memory_gib"))
      limit = {cap->as_positive() * 1073741824.0, "allowed by 'solver.max_memory_gib'"};
  return limit;
}

void require_fits(const Json& scene_json, const Json& m, int dim, const int* cells) {
  const auto order_key = m.find("order");
  const int order = order_key && order_key->is_number() && order_key->as_number() == 2 ? 2 : 1;
  const MemoryEstimate e = estimate_structured_run(dim, cells, order);
  const auto [limit, source] = memory_limit(scene_json);
  if (limit <= 0 || e.bytes <= limit) return;
  std::string shape = message(cells[0]);
  for (int d = 1; d < dim; ++d) shape += message(" x ", cells[d]);
  fail("scene: 'mesh' (", shape, " cells, P", order, ") has about ", e.dofs, " dofs, and a run would need about ",
       e.bytes / 1073741824.0, " GiB, more than the ", limit / 1073741824.0, " GiB ", source,
       ": coarsen mesh.nx/ny/nz (or set solver.max_memory_gib)");
}

std::shared_ptr<const Mesh> build_mesh(const Json& scene_json, const Json& m, const std::string& directory,
                                       Scene& scene) {
  require_known_keys(
      m, {"generator", "gmsh", "x", "y", "z", "nx", "ny", "nz", "cell", "order", "size_factor", "max_seconds"});
  require(!(m.contains("gmsh") && m.contains("generator")),
          "scene: 'mesh' gives both generator and gmsh: a mesh "
          "is generated or read, not both");
  refuse_other_mesh_keys(m);
  if (const auto file = m.find("gmsh")) {
    std::filesystem::path path = file->as_string();
    if (path.is_relative()) path = std::filesystem::path(directory) / path;
    GmshOptions options;
    if (const auto f = m.find("size_factor")) options.mesh_size_factor = f->as_positive();
    // Meshing a script is bounded in time and memory: a size far too small is stopped, not waited for.
    options.max_seconds = 600;
    if (const auto t = m.find("max_seconds")) options.max_seconds = t->as_positive();
    options.max_memory_bytes = memory_limit(scene_json).bytes;
    scene.mesh_file = file->as_string();
    scene.mesh_size_factor = options.mesh_size_factor;
    auto mesh = std::make_shared<const Mesh>(import_gmsh(path.string(), options));
    scene.mesh_description =
        message("gmsh '", file->as_string(), "': ", mesh->num_cells(), " ", to_string(mesh->cell_shape()), "s");
    return mesh;
  }
  const std::string generator = m.at("generator").as_string();
  const std::string cell = m.contains("cell") ? m.at("cell").as_string() : "triangle";
  const auto x = m.at("x").as_vector(2), y = m.at("y").as_vector(2);
  scene.nx = m.at("nx").as_int_at_least(1);
  scene.ny = m.at("ny").as_int_at_least(1);
  scene.mesh_generator = generator;
  scene.mesh_spacing = {(x[1] - x[0]) / scene.nx, (y[1] - y[0]) / scene.ny};
  if (generator == "rectangle") {
    const int cells[2] = {scene.nx, scene.ny};
    require_fits(scene_json, m, 2, cells);
    require(cell == "triangle" || cell == "quadrilateral",
            "scene: 'mesh.cell' must be triangle or quadrilateral for "
            "a rectangle, got '",
            cell, "'");
    scene.mesh_description = message(scene.nx, " x ", scene.ny, " ", cell, "s");
    return std::make_shared<const Mesh>(rectangle_mesh({x[0], y[0]}, {x[1], y[1]}, scene.nx, scene.ny,
                                                       cell == "triangle" ? Shape::Triangle : Shape::Quadrilateral));
  }
  if (generator == "box") {
    const auto z = m.at("z").as_vector(2);
    const int nz = scene.nz = m.at("nz").as_int_at_least(1);
    scene.mesh_spacing.push_back((z[1] - z[0]) / nz);
    const int cells[3] = {scene.nx, scene.ny, nz};
    require_fits(scene_json, m, 3, cells);
    require(cell == "tetrahedron" || cell == "hexahedron",
            "scene: 'mesh.cell' must be tetrahedron or hexahedron "
            "for a box, got '",
            cell, "'");
    scene.mesh_description = message(scene.nx, " x ", scene.ny, " x ", nz, " ", cell, "s");
    return std::make_shared<const Mesh>(box_mesh({x[0], y[0], z[0]}, {x[1], y[1], z[1]}, scene.nx, scene.ny, nz,
                                                 cell == "tetrahedron" ? Shape::Tetrahedron : Shape::Hexahedron));
  }
  fail("scene: 'mesh.generator' must be rectangle or box (or give mesh.gmsh), got '", generator, "'");
}

// A constant or linearly growing load: value, or value * t.
Load make_load(std::vector<double> value, const std::string& time) {
  if (time == "constant")
    return [value](const double*, double, double* out) {
      for (size_t i = 0; i < value.size(); ++i) out[i] = value[i];
    };
  return [value](const double*, double t, double* out) {
    for (size_t i = 0; i < value.size(); ++i) out[i] = value[i] * t;
  };
}

bool all_zero(const std::vector<double>& v) {
  for (double x : v)
    if (x != 0) return false;
  return true;
}

void require_region(const Mesh& mesh, const Json& at, const std::string& name, RegionKind kind) {
  std::string known;
  for (const std::string& n : mesh.region_names()) known += (known.empty() ? "" : ", ") + n;
  require(mesh.has_region(name), "scene: '", at.path(), "' names region '", name,
          "', which the mesh lacks (it has: ", known, ")");
  require(mesh.region_kind(name) == kind, "scene: '", at.path(), "': region '", name, "' must be a ",
          kind == RegionKind::Faces ? "face (boundary)" : "cell", " region");
}

Choice read_foundation(const Json& f) {
  const auto& entry = chosen_entry(f, "type", foundation_law_registry());
  const ChosenEntry chosen{"foundation type '" + entry.name + "'", &entry.parameters};
  require_read_keys(f, {"type"}, {chosen}, {registered_parameters("foundation type", foundation_law_registry())});
  return {entry.name, read_parameters(f, chosen)};
}

// A name that is a plain file name: the runner writes <name>.pvd and <name>_<step>.vtu into OUT/<foundation>/.
void require_file_name(const Json& at, const std::string& name) {
  require(!name.empty(), "scene: '", at.path(), "' is empty");
  const bool plain = std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
  require(plain && name.front() != '.', "scene: '", at.path(), "' = '", name,
          "' must be a plain file name "
          "(letters, digits, _ - ., not starting with a dot): it names output files");
}

// The most points an output grid may have, in all (1e7: a grid.csv of about 1 GB).
constexpr double kMaxGridPoints = 1e7;

// Every point must lie in the mesh (within round-off of its boundary): a probe outside it has no value.
void require_points_in_mesh(const PointLocator& locator, const Json& at,
                            const std::vector<std::array<double, 3>>& points) {
  for (const auto& x : points)
    require(locator.locate(x.data()).has_value(), "scene: '", at.path(), "': the point (", x[0], ", ", x[1], ", ", x[2],
            ") is outside the mesh");
}

// time.adaptive: the tolerance alone, or an object with it and the controller's bounds.
AdaptiveSteps read_adaptive_steps(const Json& a, double end_time) {
  AdaptiveSteps steps;
  if (a.is_number()) {
    steps.tolerance = a.as_number_in(1e-12, 0.5);
    return steps;
  }
  require(a.is_object(), "scene: '", a.path(), "' must be a tolerance (e.g. 1e-3) or an object with \"tolerance\"");
  require_known_keys(a, {"tolerance", "max_step", "factorization_cost"});
  steps.tolerance = a.at("tolerance").as_number_in(1e-12, 0.5);
  if (const auto x = a.find("max_step")) steps.max_step = x->as_number_in(1e-300, end_time);
  if (const auto x = a.find("factorization_cost")) steps.factorization_cost = x->as_number_in(0, 1e6);
  return steps;
}

// output.vtu_fields: a non-empty list of the arrays the files can hold, each once, the electric ones only
// for a piezoelectric body.
std::vector<std::string> read_vtu_fields(const Json& list, bool electric) {
  std::string known;
  std::vector<std::string> known_names;
  for (const SceneVtuField& f : scene_vtu_fields()) {
    known += (known.empty() ? "" : ", ") + f.name;
    known_names.push_back(f.name);
  }
  std::vector<std::string> names;
  for (const Json& item : list.as_array()) {
    const std::string name = item.as_string();
    const auto field = std::find_if(scene_vtu_fields().begin(), scene_vtu_fields().end(),
                                    [&](const SceneVtuField& f) { return f.name == name; });
    require(field != scene_vtu_fields().end(), "scene: '", item.path(), "' = '", name,
            "' is not a field of the VTU files (known: ", known, ")", did_you_mean(name, known_names));
    require(electric || !field->electric, "scene: '", item.path(), "' = '", name,
            "': the body is not piezoelectric "
            "(no material.piezo_E), so its VTU files have no ",
            name);
    require(std::find(names.begin(), names.end(), name) == names.end(), "scene: '", item.path(), "' = '", name,
            "' is listed twice");
    names.push_back(name);
  }
  require(!names.empty(), "scene: '", list.path(), "' is empty: name the fields to write (known: ", known,
          "), or leave it out to write them all");
  return names;
}

// output.grid: the sample points along each axis, [min, max, points], z in a 3D scene only.
void read_output_grid(const Json& g, int dim, SceneGrid& grid) {
  // A 3D scene samples a volume or the planes it names (z: [c, c, 1]), never a default plane; a 2D
  // scene has no z to sample.
  require(dim == 3 || !g.contains("z"), "scene: '", g.path(),
          ".z' is given, but the scene is 2D (its mesh "
          "has no z): remove it");
  require(dim == 2 || g.contains("z"), "scene: '", g.path(),
          ".z' is required in a 3D scene: [min, max, "
          "points] (a plane z = c is [c, c, 1])");
  require_known_keys(g, dim == 3 ? std::vector<std::string>{"x", "y", "z"} : std::vector<std::string>{"x", "y"});
  std::vector<std::pair<const char*, std::vector<double>>> axes = {{"x", g.at("x").as_vector(3)},
                                                                   {"y", g.at("y").as_vector(3)}};
  if (dim == 3) axes.push_back({"z", g.at("z").as_vector(3)});
  // A count that cannot be (not an integer, < 1, or more points than a table can sensibly hold) is
  // refused here, naming the key and the value, not turned into an int that overflows to no grid.
  double total = 1;
  std::string product;
  for (const auto& [axis, v] : axes) {
    require(std::isfinite(v[2]) && v[2] >= 1 && v[2] <= kMaxGridPoints && v[2] == std::floor(v[2]), "scene: '",
            g.path(), ".", axis, "[2]' = ", v[2], ": the third entry is a number of points, an integer in [1, ",
            kMaxGridPoints, "]");
    total *= v[2];
    product += message(product.empty() ? "" : " x ", v[2]);
  }
  require(total <= kMaxGridPoints, "scene: '", g.path(), "': ", product, " = ", total,
          " points, more than the limit of ", kMaxGridPoints);
  const auto& x = axes[0].second;
  const auto& y = axes[1].second;
  grid.x0 = x[0], grid.x1 = x[1], grid.nx = int(x[2]);
  grid.y0 = y[0], grid.y1 = y[1], grid.ny = int(y[2]);
  if (dim == 3) {
    const auto& z = axes[2].second;
    grid.z0 = z[0], grid.z1 = z[1], grid.nz = int(z[2]);
  }
}

// The solver keys that the chosen path does not read: those of the condensed solves without them, the
// contact-dof Newton off the schur path, the watchdog without a line search.
void refuse_unread_solver_keys(const Json& s, const NewtonOptions& newton) {
  if (newton.condensed_max_fraction <= 0)
    refuse_keys(s, {"condensed_max_dofs", "contact_newton"},
                "applies to condensed solves; solver.condensed = false factorises the whole system at every "
                "iteration");
  else if (newton.condensation != "schur" && newton.condensation != "auto")
    refuse_keys(s, {"contact_newton"},
                "applies to the schur path (solver.condensation schur, or auto); this scene's is '" +
                    newton.condensation + "'");
  if (!newton.line_search)
    refuse_keys(s, {"watchdog"}, "applies to the line search; solver.line_search = false takes full steps");
}

// The output keys that nothing of this scene reads: the sweep's steps without a sweep, the contact
// nodes' outputs without a contact region, energy books where no run keeps them.
void refuse_unread_output_keys(const scene_detail::SceneReading& r, const Json& o) {
  if (r.scene.output.phi_f_sweep.empty())
    refuse_keys(o, {"sweep_steps"}, "is the steps of each run of the output.phi_f_sweep sweep, which this scene lacks");
  if (lacks_contact_region(r.json))
    refuse_keys(o, {"contact_history", "slip_threshold"},
                "applies to a contact region (regions.contact); this scene has none");
  const auto books = o.find("energy_books");
  if (!books || !books->as_bool()) return;
  // With target_error the mode chooses the scheme, and the books are kept if it is backward Euler.
  const std::string& scheme = r.spec.scheme.name;
  require(scheme == "backward_euler" || r.json.contains("target_error"), "scene: '", books->path(),
          "' = true: the energy books are backward Euler's identities, and time.scheme is '", scheme, "'");
  const bool at_rest = std::all_of(r.scene.u0.begin(), r.scene.u0.end(), [](double c) { return c == 0; });
  require(r.electric || at_rest, "scene: '", books->path(),
          "' = true: a purely mechanical body's books start at rest, and time.u0 is not 0");
}

}  // namespace

namespace scene_detail {

void read_name(SceneReading& r) {
  r.scene.name = r.problems
                     .check([&] {
                       const std::string name = r.json.at("name").as_string();
                       require_file_name(r.json.at("name"), name);
                       return name;
                     })
                     .value_or("unnamed");
}

void check_top_level_keys(SceneReading& r) {
  r.problems.check_void([&] {
    require_known_keys(r.json, {"name", "about", "plugins", "mesh", "regions", "material", "contact", "foundation",
                                "loads", "electrodes", "bricks", "time", "solver", "output", "target_error"});
  });
}

void load_plugins(SceneReading& r) {
  const auto plugins = r.json.find("plugins");
  if (!plugins) return;
  r.problems.check_void([&] {
    for (const Json& item : plugins->as_array()) {
      std::filesystem::path path = item.as_string();
      if (path.is_relative()) path = std::filesystem::path(r.directory) / path;
      r.problems.check_void([&] {
        try {
          load_plugin(path.string());
        } catch (const Error& e) {
          fail("scene: '", item.path(), "': ", e.what());
        }
      });
    }
  });
}

void read_mesh(SceneReading& r) {
  PiezoContactSpec& spec = r.spec;
  r.problems.check_void([&] { spec.mesh = build_mesh(r.json, r.json.at("mesh"), r.directory, r.scene); });
  r.problems.check_void([&] {
    if (!r.json.contains("mesh")) return;  // reported once, by the mesh's own check above
    spec.order = r.json.at("mesh").at("order").as_int();
    require(spec.order == 1 || spec.order == 2, "scene: 'mesh.order' must be 1 or 2, got ", spec.order);
  });
  r.dim = spec.mesh ? spec.mesh->dim() : 2;
}

// Validated here so that messages carry the scene paths. A preset (material.preset, poled along
// material.poling) gives rho, elasticity_B, piezo_E and permittivity_beta; each of those keys given next to
// it overrides the preset's value (e.g. another density).
void read_material(SceneReading& r) {
  r.problems.check_void([&] {
    const Json& m = r.json.at("material");
    require_known_keys(m, {"name", "rho", "voigt_order", "elasticity_B", "viscosity_tau_v", "viscosity_A", "piezo_E",
                           "permittivity_beta", "preset", "poling"});
    r.problems.check_void([&] {
      const auto p = m.find("preset");
      const auto poling = m.find("poling");
      r.preset_named = p.has_value();
      if (!p) {
        require(!poling,
                "scene: 'material.poling' goes with 'material.preset' (the axis the preset is poled "
                "along); explicit tensors are written for their own axes");
        return;
      }
      const PiezoMaterialPreset& material = piezo_material(p->as_string(), "scene: '" + p->path() + "'");
      require(poling.has_value(),
              "scene: 'material.poling' is required with 'material.preset': the poling axis, x, "
              "y or z (the preset's tables are poled along z)");
      const Axis axis = axis_from_name(poling->as_string(), "scene: '" + poling->path() + "'");
      require(r.dim == 3 || axis != Axis::z, "scene: '", poling->path(),
              "' is z, but a 2D model (plane strain in "
              "x-y) is poled in its plane: x or y");
      r.preset = material.tensors(r.dim, axis);
    });
    if (r.preset && !m.contains("rho"))
      r.spec.rho = r.preset->rho;
    else if (m.contains("rho") || !r.preset_named)
      r.spec.rho = m.at("rho").as_number_at_least(0);
  });
}

void read_material_tensors(SceneReading& r) {
  PiezoContactSpec& spec = r.spec;
  const int dim = r.dim;
  const std::optional<PiezoTensors>& preset = r.preset;
  const bool preset_named = r.preset_named;
  const auto material = r.json.find("material");
  if (material && material->is_object()) {
    // elasticity_B as given, else the preset's; empty when a named preset was not found (already reported).
    const auto elasticity = [&]() -> Eigen::MatrixXd {
      if (material->contains("elasticity_B") || !preset_named) return material->at("elasticity_B").as_matrix();
      return preset ? preset->B : Eigen::MatrixXd();
    };
    r.problems.check_void([&] {
      spec.B = elasticity();
      if (preset_named && !preset && !material->contains("elasticity_B")) return;
      check_stiffness("material.elasticity_B", spec.B, dim);
    });
    r.problems.check_void([&] {
      // A directly, or A = tau_v B (a Kelvin-Voigt relaxation time); both only when they agree.
      const auto a = material->find("viscosity_A");
      const auto tau = material->find("viscosity_tau_v");
      if (a) {
        spec.A = a->as_matrix();
        check_stiffness("material.viscosity_A", spec.A, dim, /*allow_zero=*/true);
      }
      if (!tau) return;
      const double tau_v = tau->as_number_at_least(0);
      const Eigen::MatrixXd B = elasticity();
      if (!a) {
        spec.A = tau_v * B;
        return;
      }
      require(spec.A.rows() == B.rows() && spec.A.cols() == B.cols() &&
                  (spec.A - tau_v * B).norm() <= 1e-12 * spec.A.norm(),
              "scene: 'material.viscosity_A' and 'material.viscosity_tau_v' disagree (A != tau_v B): give one of them");
    });
    r.problems.check_void([&] {
      const auto e = material->find("piezo_E");
      const auto beta = material->find("permittivity_beta");
      if (preset_named) {
        // The preset's, each unless given; nothing to add when the preset was not found.
        if (!preset && !(e && beta)) return;
        spec.E = e ? e->as_matrix() : preset->E;
        spec.beta = beta ? beta->as_matrix() : preset->beta;
      } else {
        require(e.has_value() == beta.has_value(),
                "scene: material.piezo_E and material.permittivity_beta go "
                "together (both for a piezoelectric body, neither for a purely mechanical one)");
        if (!e) return;
        spec.E = e->as_matrix();
        spec.beta = beta->as_matrix();
      }
      check_piezoelectric("material.piezo_E", spec.E, dim);
      check_permittivity("material.permittivity_beta", spec.beta, dim);
    });
  }
  // Every preset is piezoelectric: one that was named but not found is not a mechanical body either.
  r.electric = spec.E.size() > 0 || (preset_named && !preset);
}

void read_regions(SceneReading& r) {
  PiezoContactSpec& spec = r.spec;
  r.problems.check_void([&] {
    const Json& regions = r.json.at("regions");
    require_known_keys(regions, {"clamped", "traction", "contact", "grounded", "charge"});
    if (const auto c = regions.find("clamped")) spec.clamped = names_of(*c);
    if (const auto g = regions.find("grounded")) spec.grounded = names_of(*g);
    if (const auto c = regions.find("contact")) {
      spec.contact = c->as_string();
      require(!spec.contact.empty(),
              "scene: 'regions.contact' is empty: name the contact region, or leave the key out "
              "for a body without contact");
    }
    if (!spec.mesh) return;
    for (const std::string& n : spec.clamped) require_region(*spec.mesh, regions.at("clamped"), n, RegionKind::Faces);
    for (const std::string& n : spec.grounded) require_region(*spec.mesh, regions.at("grounded"), n, RegionKind::Faces);
    if (!spec.contact.empty()) require_region(*spec.mesh, regions.at("contact"), spec.contact, RegionKind::Faces);
    if (const auto c = regions.find("charge"))
      for (const std::string& n : names_of(*c)) require_region(*spec.mesh, *c, n, RegionKind::Faces);
    require(!spec.clamped.empty(),
            "scene: 'regions.clamped' is empty: the body needs a clamped side (meas Gamma_D > 0)");
    require(!r.electric || !spec.grounded.empty(),
            "scene: 'regions.grounded' is empty: the potential needs a grounded "
            "side (meas Gamma_a > 0)");
  });
}

void read_loads(SceneReading& r) {
  PiezoContactSpec& spec = r.spec;
  const int dim = r.dim;
  const bool electric = r.electric;
  r.problems.check_void([&] {
    const Json& loads = r.json.at("loads");
    require_known_keys(loads, {"f0", "traction", "q0", "q_b"});
    if (const auto f0 = loads.find("f0")) {
      const auto value = f0->as_vector(size_t(dim));
      if (!all_zero(value)) spec.body_force = make_load(value, "constant");
    }
    if (const auto t = loads.find("traction")) {
      for (const Json& item : t->as_array()) {
        require_known_keys(item, {"region", "value", "time"});
        const std::string region = item.at("region").as_string();
        if (spec.mesh) require_region(*spec.mesh, item.at("region"), region, RegionKind::Faces);
        const std::string time = item.contains("time") ? item.at("time").as_string() : "constant";
        require(time == "constant" || time == "linear", "scene: '", item.path(),
                ".time' must be constant or linear "
                "(value * t), got '",
                time, "'");
        spec.tractions.push_back({region, make_load(item.at("value").as_vector(size_t(dim)), time),
                                  time == "constant" ? LoadTime::Constant : LoadTime::Varying});
      }
    }
    // A charge is a load on the potential, which a purely mechanical body has not.
    for (const char* key : {"q0", "q_b"})
      if (const auto q = loads.find(key))
        require(electric || q->as_number() == 0, "scene: '", q->path(), "' = ", q->as_number(),
                ": a purely mechanical body (no material.piezo_E) has no charge to load");
    if (const auto q0 = loads.find("q0"); q0 && q0->as_number() != 0 && electric)
      spec.volume_charge = make_load({q0->as_number()}, "constant");
    if (const auto qb = loads.find("q_b"); qb && qb->as_number() != 0 && electric)
      for (const std::string& region : names_of(r.json.at("regions").at("charge")))
        spec.surface_charges.push_back({region, make_load({qb->as_number()}, "constant"), LoadTime::Constant});
  });
}

void read_contact(SceneReading& r) {
  PiezoContactSpec& spec = r.spec;
  const int dim = r.dim;
  r.problems.check_void([&] {
    if (spec.contact.empty()) {
      require(!(r.json.contains("contact") && lacks_contact_region(r.json)),
              "scene: 'contact' applies to a contact region (regions.contact); this scene has none");
      return;
    }
    const Json& c = r.json.at("contact");
    const auto& normal = chosen_entry(c, "law_normal", normal_law_registry());
    const auto& friction = chosen_entry(c, "law_tangential", friction_law_registry(), "none");
    const ChosenEntry chosen_normal{"law_normal '" + normal.name + "'", &normal.parameters};
    const ChosenEntry chosen_friction{"law_tangential '" + friction.name + "'", &friction.parameters};
    for (const ParameterDeclaration& d : friction.parameters)
      require(!find_parameter(normal.parameters, d.name), "scene: 'contact.", d.name, "' would be read by both ",
              chosen_normal.label, " and ", chosen_friction.label,
              ": laws paired in one contact object need "
              "distinct parameter names");
    require_read_keys(c, {"law_normal", "law_tangential", "foundation_velocity"}, {chosen_normal, chosen_friction},
                      {registered_parameters("law_normal", normal_law_registry()),
                       registered_parameters("law_tangential", friction_law_registry())});
    spec.normal = {normal.name, read_parameters(c, chosen_normal)};
    spec.friction = {friction.name, read_parameters(c, chosen_friction)};
    if (const auto velocity = c.find("foundation_velocity")) {
      const std::vector<Json> components = velocity->as_array();
      require(int(components.size()) == dim, "scene: 'contact.foundation_velocity' must list ", dim,
              " time functions (one per component), got ", components.size());
      auto motion = std::make_shared<FoundationMotion>();
      for (int d = 0; d < dim; ++d) motion->velocity[d] = time_function_from_json(components[d]);
      spec.foundation_motion = motion;
    }
  });
}

// Driven (phi = V(t)), reporting their charge and current, or floating (one unknown potential, a given
// charge), reporting their voltage.
void read_electrodes(SceneReading& r) {
  PiezoContactSpec& spec = r.spec;
  const auto electrodes = r.json.find("electrodes");
  if (!electrodes) return;
  r.problems.check_void([&] {
    require(r.electric,
            "scene: 'electrodes': a purely mechanical body (no material.piezo_E) has no potential to drive");
    std::vector<std::string> names;
    for (const Json& item : electrodes->as_array()) {
      r.problems.check_void([&] {
        require_known_keys(item, {"name", "region", "voltage", "floating", "charge"});
        const bool floating = item.find("floating") && item.at("floating").as_bool();
        Electrode electrode;
        if (floating) {
          require(!item.find("voltage"), "scene: '", item.path(),
                  "': a floating electrode's voltage is computed; "
                  "give its 'charge' (default 0, an open circuit) instead of a 'voltage'");
          electrode = floating_electrode(
              item.at("name").as_string(), item.at("region").as_string(),
              item.find("charge") ? time_function_from_json(item.at("charge")) : TimeFunction::constant(0));
        } else {
          require(!item.find("charge"), "scene: '", item.path(),
                  "': a driven electrode's charge is measured; "
                  "'charge' is for a floating one (\"floating\": true)");
          electrode = Electrode{item.at("name").as_string(), item.at("region").as_string(),
                                time_function_from_json(item.at("voltage"))};
        }
        require_file_name(item.at("name"), electrode.name);
        require(std::find(names.begin(), names.end(), electrode.name) == names.end(), "scene: '", item.path(),
                ".name': electrode '", electrode.name, "' is named twice");
        names.push_back(electrode.name);
        if (spec.mesh) require_region(*spec.mesh, item.at("region"), electrode.region, RegionKind::Faces);
        for (const std::string& g : spec.grounded)
          require(g != electrode.region, "scene: '", item.path(), ".region': '", g,
                  "' is grounded (regions.grounded) and cannot be an electrode too");
        spec.electrodes.push_back(std::move(electrode));
      });
    }
  });
}

void read_foundations(SceneReading& r) {
  r.problems.check_void([&] {
    const Json& f = r.json.at("foundation");
    for (const Json::Member& member : f.members()) {
      // Not a structured binding: clang before 16 cannot capture one in a lambda.
      const std::string& name = member.first;
      const Json& value = member.second;
      if (const auto foundation = r.problems.check([&] { return read_foundation(value); })) {
        require(r.electric || foundation->name == "insulated", "scene: '", value.path(), "': a ", foundation->name,
                " foundation needs a piezoelectric body (material.piezo_E)");
        require(!r.spec.contact.empty() || foundation->name == "insulated", "scene: '", value.path(), "': a ",
                foundation->name, " foundation needs a contact region (regions.contact)");
        r.scene.foundations.push_back({name, *foundation});
      }
    }
    require(f.size() > 0, "scene: 'foundation' lists no foundation to run");
  });
}

void read_bricks(SceneReading& r) {
  PiezoContactSpec& spec = r.spec;
  const auto bricks = r.json.find("bricks");
  if (!bricks) return;
  r.problems.check_void([&] {
    for (const Json& item : bricks->as_array()) {
      r.problems.check_void([&] {
        const auto& entry = chosen_entry(item, "type", brick_registry());
        const ChosenEntry chosen{"brick type '" + entry.name + "'", &entry.parameters};
        require_read_keys(item, {"type", "region"}, {chosen}, {registered_parameters("brick type", brick_registry())});
        const std::string region = item.at("region").as_string();
        if (spec.mesh)
          require(spec.mesh->has_region(region), "scene: '", item.path(), ".region' names region '", region,
                  "', which the mesh lacks");
        spec.bricks.push_back({{entry.name, read_parameters(item, chosen)}, region});
      });
    }
  });
}

void read_time(SceneReading& r) {
  Scene& scene = r.scene;
  const int dim = r.dim;
  r.problems.check_void([&] {
    const Json& t = r.json.at("time");
    const auto& scheme = chosen_entry(t, "scheme", time_scheme_registry(), "backward_euler");
    const ChosenEntry chosen{"time.scheme '" + scheme.name + "'", &scheme.parameters};
    require_read_keys(t,
                      {"T", "steps", "u0", "v0", "prediction", "scheme", "max_attempts", "max_wall_seconds", "adaptive",
                       "error_estimate"},
                      {chosen}, {registered_parameters("time.scheme", time_scheme_registry())});
    r.spec.scheme = {scheme.name, read_parameters(t, chosen)};
    scene.end_time = t.at("T").as_positive();
    scene.steps = t.at("steps").as_int_at_least(1);
    if (const auto x = t.find("max_attempts")) scene.max_attempts = x->as_int_at_least(0);
    if (const auto x = t.find("max_wall_seconds")) scene.max_wall_seconds = x->as_number_in(0, 1e12);
    if (const auto x = t.find("error_estimate")) {
      const std::string e = x->as_string();
      require(e == "linearised" || e == "summed" || e == "none", "scene: '", x->path(),
              "' must be linearised (the default), summed or none, got '", e, "'");
      scene.estimate_time_error = e != "none";
      if (e == "summed") scene.time_error_propagation = TimeErrorPropagation::Summed;
    }
    if (const auto x = t.find("adaptive")) {
      scene.adaptive = read_adaptive_steps(*x, scene.end_time);
      require(scene.estimate_time_error, "scene: '", x->path(),
              "' needs the time error estimate, which "
              "time.error_estimate = none turns off");
    }
    if (const auto x = r.json.find("target_error")) {
      scene.target_error = x->as_number_in(1e-6, 0.5);
      require(!scene.mesh_generator.empty(),
              "scene: 'target_error' chooses the mesh size of a generated mesh "
              "(mesh.generator); this scene's mesh is the gmsh file '",
              scene.mesh_file, "'");
      require(scene.estimate_time_error,
              "scene: 'target_error' needs the time error estimate, which "
              "time.error_estimate = none turns off");
    }
    scene.u0 = t.contains("u0") ? t.at("u0").as_vector(size_t(dim)) : std::vector<double>(dim, 0.0);
    scene.v0 = t.contains("v0") ? t.at("v0").as_vector(size_t(dim)) : std::vector<double>(dim, 0.0);
    const std::string p = t.contains("prediction") ? t.at("prediction").as_string() : "previous";
    require(p == "zero" || p == "previous", "scene: 'time.prediction' must be zero (the paper's) or previous, got '", p,
            "'");
    scene.prediction = p == "zero" ? Prediction::Zero : Prediction::Previous;
  });
}

void read_solver(SceneReading& r) {
  Scene& scene = r.scene;
  r.problems.check_void([&] {
    // "auto" gives the dense matrices of a Schur condensation at most a quarter of the memory, whether or
    // not the scene has a solver section.
    scene.newton.dense_memory_budget_bytes = 0.25 * memory_limit(r.json).bytes;
    const auto s = r.json.find("solver");
    if (!s) return;
    require_known_keys(
        *s, {"linear", "max_iterations", "relative_tolerance", "line_search", "watchdog", "cutback_factor", "condensed",
             "condensation", "condensed_max_dofs", "contact_newton", "max_memory_gib", "threads"});
    if (const auto x = s->find("threads")) scene.threads = x->as_int_at_least(1);
    if (const auto x = s->find("condensed"))
      scene.newton.condensed_max_fraction = x->as_bool() ? NewtonOptions{}.condensed_max_fraction : 0.0;
    if (const auto x = s->find("condensed_max_dofs")) scene.newton.condensed_max_dofs = x->as_int_at_least(0);
    if (const auto x = s->find("contact_newton")) scene.newton.contact_newton = x->as_bool();
    scene.newton.condensation =
        chosen_entry(*s, "condensation", condensation_registry(), NewtonOptions{}.condensation).name;
    scene.newton.linear_solver =
        chosen_entry(*s, "linear", linear_solver_registry(), NewtonOptions{}.linear_solver).name;
    if (const auto x = s->find("max_iterations")) scene.newton.max_iterations = x->as_int_at_least(1);
    if (const auto x = s->find("relative_tolerance")) {
      // A tolerance below the residual's round-off floor could never be met (Newton would stop the run,
      // NewtonOutcome::RoundOffFloor): refused here, before anything is built.
      scene.newton.relative_tolerance = x->as_number_in(0, 1);
      require(scene.newton.relative_tolerance >= min_relative_tolerance(), "scene: '", x->path(),
              "' = ", scene.newton.relative_tolerance,
              " is below the residual's round-off floor: the smallest relative ", "tolerance Newton can meet is ",
              min_relative_tolerance(), " (", kRoundOffFloorFactor, " machine epsilons)");
    }
    if (const auto x = s->find("line_search")) scene.newton.line_search = x->as_bool();
    if (const auto x = s->find("watchdog")) scene.newton.watchdog = x->as_int_at_least(0);
    if (const auto x = s->find("cutback_factor")) {
      scene.cutback_factor = x->as_number_in(0, 1);
      require(scene.cutback_factor > 0 && scene.cutback_factor < 1, "scene: 'solver.cutback_factor' must be in (0, 1)");
    }
    refuse_unread_solver_keys(*s, scene.newton);
  });
}

void read_output(SceneReading& r) {
  const int dim = r.dim;
  SceneOutput& out = r.scene.output;
  r.problems.check_void([&] {
    const auto o = r.json.find("output");
    if (!o) return;
    require_known_keys(
        *o, {"vtu_every", "vtu_format", "vtu_fields", "progress_every", "space_error_every", "probes", "grid",
             "slip_threshold", "phi_f_sweep", "sweep_steps", "checkpoint_every", "contact_history", "energy_books"});
    if (const auto x = o->find("vtu_every")) out.vtu_every = x->as_int_at_least(1);
    if (const auto x = o->find("vtu_format"))
      out.vtu_format = vtu_format_from_name(x->as_string(), "scene: '" + x->path() + "'");
    if (const auto x = o->find("vtu_fields")) out.vtu_fields = read_vtu_fields(*x, r.electric);
    if (const auto x = o->find("checkpoint_every")) out.checkpoint_every = x->as_int_at_least(0);
    if (const auto x = o->find("progress_every")) out.progress_every = x->as_int_at_least(1);
    if (const auto x = o->find("space_error_every")) out.space_error_every = x->as_int_at_least(0);
    if (const auto p = o->find("probes")) {
      require_known_keys(*p, {"corner", "center"});
      const auto corner = p->at("corner").as_vector(size_t(dim)), center = p->at("center").as_vector(size_t(dim));
      for (int d = 0; d < dim; ++d) out.corner[d] = corner[d], out.center[d] = center[d];
    }
    if (const auto g = o->find("grid")) read_output_grid(*g, dim, out.grid);
    if (const auto x = o->find("slip_threshold")) out.slip_threshold = x->as_number_at_least(0);
    if (const auto x = o->find("contact_history")) out.contact_history = x->as_bool();
    if (const auto x = o->find("energy_books")) out.energy_books = x->as_bool();
    if (const auto x = o->find("phi_f_sweep")) out.phi_f_sweep = x->as_vector();
    if (const auto x = o->find("sweep_steps")) out.sweep_steps = x->as_int_at_least(1);
    refuse_unread_output_keys(r, *o);
  });
  r.spec.slip_threshold = out.slip_threshold;
}

void check_output_points(SceneReading& r) {
  r.problems.check_void([&] {
    const auto o = r.json.find("output");
    if (!r.spec.mesh || !o) return;
    const PointLocator locator(*r.spec.mesh);
    if (const auto p = o->find("probes")) {
      require_points_in_mesh(locator, p->at("corner"), {r.scene.output.corner});
      require_points_in_mesh(locator, p->at("center"), {r.scene.output.center});
    }
    if (const auto g = o->find("grid")) require_points_in_mesh(locator, *g, r.scene.output.grid.points());
  });
}

}  // namespace scene_detail
}  // namespace pc

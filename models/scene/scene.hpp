#pragma once
// A scene file (JSON) read into everything a run needs: the mesh, the physics it contains (which decides
// the bricks, see piezo_contact_recipe.hpp), the foundations to run, time span, solver and outputs.
// Loading validates the whole scene before anything is computed and reports every problem at once, each
// with the dotted path of the offending value ("contact.c_nu must be a number, got the string \"1e12\"").
// The format is documented in docs/scenes.md; scenes/paper2d.json is the paper's test.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "assembly/vtu_format.hpp"
#include "models/piezo/piezo_contact_recipe.hpp"
#include "models/scene/json.hpp"
#include "models/scene/target_error_choice.hpp"
#include "models/solvers/newton.hpp"
#include "models/stepper.hpp"

namespace pc {

struct SceneFoundation {
  std::string name;  // the key in "foundation": a run writes into OUT/<name>/
  Choice law;        // a registered foundation law ("insulated", "conductive", ...) with its parameters
};

struct SceneGrid {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0, z0 = 0, z1 = 0;
  int nx = 0, ny = 0;  // sample points along each axis
  int nz = 0;          // 3D scenes (output.grid.z, required there): points along z; 0 in 2D
  // The sample points, x fastest, then y, then z (z = 0 in 2D).
  std::vector<std::array<double, 3>> points() const;
};

// An array a scene's VTU files can hold (output.vtu_fields names some of them).
struct SceneVtuField {
  std::string name;
  bool electric;  // only a piezoelectric body has it
};
// Every such array, in the order a file holds them: the point data v, u, phi, contact_pressure, then the
// cell data strain, stress, von_mises, electric_field, electric_displacement.
const std::vector<SceneVtuField>& scene_vtu_fields();

struct SceneOutput {
  int vtu_every = 10;
  VtuFormat vtu_format = kDefaultVtuFormat;  // output.vtu_format
  std::vector<std::string> vtu_fields;       // output.vtu_fields: the arrays the VTU files hold; empty: all
  // Whether the VTU files hold that array.
  bool writes_vtu_field(const std::string& name) const;
  int progress_every = 20;
  // The spatial error estimate every N accepted steps (0: at the VTU output steps only), for its largest
  // value over the run (space_error_peak in summary.json): a transient's peak between output steps is
  // otherwise missed. The target-error mode sets 1.
  int space_error_every = 0;
  int checkpoint_every = 10;  // a checkpoint (for --resume) every N steps and at a stop; 0: only at a stop
  std::array<double, 3> corner{}, center{};  // probes of history.csv and summary.json
  SceneGrid grid;
  double slip_threshold = 0;  // m/s: a contact node with |v_tau| above it slides
  // output.contact_history: contact_state.csv, each contact node's state at every step (contact_nodes.csv
  // says where the nodes are)
  bool contact_history = false;
  // output.energy_books: the energy books' columns in history.csv (backward Euler; each kept brick's
  // residual costs a copy per assembly)
  bool energy_books = true;
  std::vector<double> phi_f_sweep;  // foundation voltages for Figure 5 (conductive runs)
  int sweep_steps = 0;              // time steps of each sweep run (0: the scene's)
};

struct Scene {
  Json json;                           // the scene as read, after --set overrides
  std::string file;                    // the scene file (load_scene_file), and ...
  std::vector<std::string> overrides;  // ... the --set overrides applied to it
  std::string directory;               // what relative paths in the scene (gmsh file, plugins) resolve against
  std::string name;
  std::string mesh_description;      // e.g. "60 x 20 triangles"
  int nx = 0, ny = 0, nz = 0;        // generated meshes only (nz: box)
  std::string mesh_generator;        // mesh.generator ("rectangle", "box"); empty for a gmsh mesh
  std::vector<double> mesh_spacing;  // generated meshes: the cell size along each axis
  std::string mesh_file;             // mesh.gmsh as the scene gives it; empty for a generated mesh
  double mesh_size_factor = 1;       // mesh.size_factor (gmsh)
  PiezoContactSpec spec;             // everything but the foundation; spec.scheme from time.scheme and its parameters
  std::vector<double> u0, v0;        // constant initial displacement and velocity
  std::vector<SceneFoundation> foundations;
  double end_time = 0;
  int steps = 0;
  Prediction prediction = Prediction::Previous;
  NewtonOptions newton;
  double cutback_factor = 0.5;
  int max_attempts = 0;         // time.max_attempts: step attempts, accepted or cut back (0: no limit)
  double max_wall_seconds = 0;  // time.max_wall_seconds (0: no limit)
  // time.adaptive: a tolerance, or {"tolerance", "max_step", "factorization_cost"}; time.steps then sets
  // the first step (StepperOptions::adaptive).
  std::optional<AdaptiveSteps> adaptive;
  // time.error_estimate: "linearised" (the default), "summed" or "none" (models/time_error_estimate.hpp).
  bool estimate_time_error = true;
  TimeErrorPropagation time_error_propagation = TimeErrorPropagation::Linearised;
  // target_error: the estimated error the run must reach (models/scene/target_error.hpp), and once
  // scene_for_target_error has chosen, what it chose.
  std::optional<double> target_error;
  std::optional<TargetErrorChoice> target_choice;
  int threads = 0;  // solver.threads: of the element loops and products (0: assembly/threads.hpp's default)
  SceneOutput output;
};

// Validates and builds (meshes included); throws one pc::Error listing every problem found.
// `directory` resolves relative paths in the scene (a gmsh file).
Scene load_scene(const Json& json, const std::string& directory);
// Applies command-line overrides "a.b=value" (--set) in order: the value parsed as JSON when it parses
// (parse_json_value_from_cli), the path by Json::set_path, which may add a last key the object lacks.
void apply_overrides(Json& json, const std::vector<std::string>& overrides);
// Reads the file, applies the overrides (apply_overrides), loads.
Scene load_scene_file(const std::string& path, const std::vector<std::string>& overrides = {});
// The scene's foundation of that name; throws naming the known ones.
const SceneFoundation& find_foundation(const Scene& scene, const std::string& name);

}  // namespace pc

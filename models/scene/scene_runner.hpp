#pragma once
// Runs a scene: one time-dependent run per foundation of the scene, each writing into OUT/<foundation>/
//   summary.json   key numbers of the run and what its mesh is (see README, "Reading the results")
//   history.csv    t, uy_corner, (uz_corner in 3D,) phi_center, newton_iterations: one row per step, written as it goes
//   gamma_c.csv    x, (z,) ux, uy, (uz,) vx, vy, (vz,) phi, contact_pressure at the contact nodes' own dof values,
//                  final time, sorted by x
//   grid.csv       x, y, (z,) ux, uy, (uz,) vx, vy, (vz,) phi sampled on the scene's output grid (x fastest,
//                  then y, then z), final time
//   final_nodes.csv, final_cells.csv   the final state on the mesh (for the figures, 2D)
//   <name>.pvd + <name>_<step>.vtu     ParaView time series, every output.vtu_every steps and step 0, in the
//                  format output.vtu_format, holding the arrays output.vtu_fields names (all by default)
//   checkpoint.bin  the state to continue from (run --resume), every output.checkpoint_every steps
// and, when the scene asks for it, OUT/sweep_phi_f.csv: the final displacement against the foundation
// voltage (conductive foundation), for Figure 5, and OUT/manifest.json (models/scene/run_manifest.hpp).
#include <functional>
#include <map>
#include <string>

#include "assembly/linear_solver.hpp"
#include "models/scene/output_directory_lock.hpp"
#include "models/scene/scene.hpp"

namespace pc {

struct SceneRunOptions {
  std::string output_directory;
  bool progress = true;           // progress lines on stdout
  std::vector<std::string> only;  // run only these foundations (empty: all)
  bool sweep = true;              // run the phi_f sweep if the scene has one
  // Continue the run recorded in the directory's manifest.json (same scene): completed parts are kept,
  // a stopped or killed one continues from its last checkpoint (or starts again if it has none).
  bool resume = false;
};

// How one run of a foundation writes and where it starts.
struct FoundationRunOptions {
  std::string directory;  // empty: nothing is written (studies, tests)
  bool progress = true;
  int steps_override = 0;  // > 0 replaces the scene's number of steps
  // Continue from directory/checkpoint.bin (written every output.checkpoint_every steps and at a stop):
  // history.csv keeps its rows up to the checkpoint, the VTU series its steps, and the run goes on as the
  // uninterrupted one would have, to the last digit. Without a checkpoint the run starts from t = 0.
  bool resume = false;
  std::function<void()> after_checkpoint;  // e.g. the manifest's update
  // Called after each accepted step once its history row is written (studies: the time of each step).
  std::function<void(const StepRecord&)> after_step;
};

struct FoundationRunResult {
  std::string foundation;
  bool completed = false;
  int steps = 0, ndof = 0, newton_iterations_total = 0, newton_iterations_max_per_step = 0;
  int cutbacks = 0;                        // failed step attempts that were retried with a smaller step
  int rejections = 0;                      // time.adaptive: attempts rejected on their estimated time error
  std::vector<FieldTimeError> time_error;  // the estimated time error at the end, per field (global)
  // The estimated spatial error of the final state, relative to the largest norm the field had at an
  // output step or the end (space_error_scale), as the time error is relative to its largest RMS; and the
  // largest estimate of each field at those times (space_error_largest, absolute).
  std::map<std::string, double> space_error, space_error_scale, space_error_largest;
  // The largest estimates over the run: of the time error (any field, any step), and of the spatial error
  // (any field, any output step or the end, relative to the field's scale). What --target-error aims at.
  double time_error_peak = 0;
  double space_error_peak() const;
  double wall_seconds = 0;
  double max_abs_ux = 0, max_abs_uy = 0, phi_min = 0, phi_max = 0, uy_corner = 0, ux_corner = 0, phi_center = 0;
  int dim = 2;  // of the mesh: max_abs_uz and uz_corner are results in 3D only
  double max_abs_uz = 0, uz_corner = 0;
  double max_abs_vtau_contact = 0;
  int n_slip_nodes = 0, n_contact_nodes = 0;
  // Time per phase, summed over the Newton solves of the steps and of the initial potential, and the
  // sparse factorisations done. jacobian_seconds is the Jacobian's part of assembly_seconds (the rest is
  // the residual's); factorize_seconds includes the symbolic analyses.
  double assembly_seconds = 0, jacobian_seconds = 0, factorize_seconds = 0, solve_seconds = 0, condensation_seconds = 0;
  int factorizations = 0;
  std::string linear_strategy;  // solver.condensation = "auto": what the cost model chose and why
  FactorEstimate full_factors;  // the full factorisations' solver's prediction (summary.json: factorization)
  // Writing the results: history rows (probes included), the VTU series, checkpoints and the final tables
  // (summary.json, written after the wall time is taken, is not in it).
  double output_seconds = 0;
  double vtu_seconds = 0;  // the part of output_seconds spent on the VTU series: its derived fields and files
  std::string message;
};

// One foundation of a scene: its model built once, then run as often as asked, each run from the scene's
// initial state. A parameter study changes model constants between runs (the phi_f sweep sets "phi_f"):
// only the bricks that read a changed constant are rebuilt, and the pattern, the symbolic analysis and
// the cached linear bricks are kept.
class FoundationRun {
 public:
  FoundationRun(const Scene& scene, const SceneFoundation& foundation);
  FoundationRunResult run(const FoundationRunOptions& options);
  // With an empty directory nothing is written (studies, tests); steps_override > 0 replaces the scene's.
  FoundationRunResult run(const std::string& directory, bool progress, int steps_override = 0);
  Model& model() { return *built_.model; }
  const NewtonSolver& newton() const { return newton_; }

 private:
  const Scene& scene_;
  SceneFoundation foundation_;
  PiezoContactModel built_;
  NewtonSolver newton_;
};

// Builds and runs one foundation of the scene once (FoundationRun for several runs of one model).
FoundationRunResult run_foundation(const Scene& scene, const SceneFoundation& foundation, const std::string& directory,
                                   bool progress, int steps_override = 0);

// Runs the scene as SceneRunOptions say; returns false if a run did not complete. A scene with a
// target_error is first given its discretisation (models/scene/target_error.hpp: pilots, then the choice). A non-empty
// output directory is locked (OutputDirectoryLock) before the first step. A run whose state or results become
// non-finite stops there: nothing non-finite is written, and its summary.json says completed = false
// with the message. The reason a run stopped is printed on stderr whatever options.progress says.
bool run_scene(const Scene& scene, const SceneRunOptions& options);

}  // namespace pc

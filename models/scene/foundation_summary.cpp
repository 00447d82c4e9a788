#include "models/scene/foundation_summary.hpp"

#include <algorithm>
#include <cmath>

#include "assembly/atomic_file.hpp"
#include "assembly/blas_info.hpp"
#include "assembly/processes.hpp"
#include "assembly/threads.hpp"
#include "models/scene/json.hpp"
#include "models/scene/mesh_summary.hpp"
#include "models/scene/run_timing.hpp"
#include "models/scene/target_error_outcome.hpp"

namespace pc {

std::vector<std::pair<const char*, double>> result_numbers(const FoundationRunResult& r) {
  std::vector<std::pair<const char*, double>> numbers = {{"max_abs_ux", r.max_abs_ux}, {"max_abs_uy", r.max_abs_uy}};
  if (r.dim == 3) numbers.push_back({"max_abs_uz", r.max_abs_uz});
  numbers.insert(
      numbers.end(),
      {{"phi_min", r.phi_min}, {"phi_max", r.phi_max}, {"ux_corner", r.ux_corner}, {"uy_corner", r.uy_corner}});
  if (r.dim == 3) numbers.push_back({"uz_corner", r.uz_corner});
  numbers.insert(numbers.end(), {{"phi_center", r.phi_center}, {"max_abs_vtau_contact", r.max_abs_vtau_contact}});
  return numbers;
}

namespace {

// A number of the summary, or null when it is not finite (JSON has no NaN; the run is then not completed).
Json finite_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

// What the run is: the scene, the foundation, the mesh and the order, and its counts.
void set_run(Json& s, const Scene& scene, const FoundationRunResult& r, int steps) {
  s.set("scene", Json(scene.name));
  s.set("foundation", Json(r.foundation));
  s.set("mesh", mesh_summary(scene));
  // A generated mesh's cell counts at the top level too, as 2D readers know them; a gmsh mesh has none.
  if (!scene.mesh_generator.empty()) {
    s.set("nx", Json(double(scene.nx)));
    s.set("ny", Json(double(scene.ny)));
    if (scene.nz > 0) s.set("nz", Json(double(scene.nz)));
  }
  s.set("order", Json(double(scene.spec.order)));
  s.set("steps", Json(double(steps)));
  s.set("completed", Json(r.completed));
  s.set("ndof", Json(double(r.ndof)));
  s.set("newton_iterations_total", Json(double(r.newton_iterations_total)));
  s.set("newton_iterations_max_per_step", Json(double(r.newton_iterations_max_per_step)));
}

// The estimated errors: in time and space at the end and their peaks, the target-error mode's choice and
// what it achieved, and what the adaptive steps did.
void set_errors(Json& s, const Scene& scene, const FoundationRunResult& r) {
  // The estimated time error at the end (relative RMS per field), and what the adaptive steps did.
  Json time_error = Json::object();
  double time_error_max = 0;
  for (const FieldTimeError& f : r.time_error) {
    time_error.set(f.field, finite_or_null(f.global));
    time_error_max = std::max(time_error_max, f.global);
  }
  s.set("time_error", std::move(time_error));
  s.set("time_error_max", finite_or_null(time_error_max));
  // The estimated spatial error of the final state (relative, in each field's energy norm).
  Json space_error = Json::object();
  double space_error_max = 0;
  for (const auto& [field, relative] : r.space_error) {
    space_error.set(field, finite_or_null(relative));
    space_error_max = std::max(space_error_max, relative);
  }
  s.set("space_error", std::move(space_error));
  s.set("space_error_max", finite_or_null(space_error_max));
  s.set("time_error_peak", finite_or_null(r.time_error_peak));
  s.set("space_error_peak", finite_or_null(r.space_error_peak()));
  // The target-error mode: what it chose, what it predicted, what the run's estimates say it achieved,
  // and what its pilots cost (counted in wall_s_total too).
  if (const auto& c = scene.target_choice) {
    Json t = Json::object();
    t.set("target", Json(c->target));
    t.set("chosen", Json(c->description()));
    t.set("predicted_space", Json(c->predicted_space));
    t.set("predicted_time", Json(c->predicted_time));
    t.set("predicted_seconds", Json(c->predicted_seconds));
    t.set("achieved_space", finite_or_null(r.space_error_peak()));
    t.set("achieved_time", finite_or_null(r.time_error_peak));
    t.set("achieved", finite_or_null(target_estimate(r)));
    t.set("target_met", Json(target_met(*c, r)));
    t.set("safety_margin", Json(c->margin));
    t.set("pilots_wall_s", Json(c->pilots_seconds_of(r.foundation)));
    t.set("rates", Json(c->rates));
    Json warnings = Json::array();
    for (const std::string& w : c->warnings) warnings.push_back(Json(w));
    t.set("warnings", std::move(warnings));
    t.set("why", Json(c->explanation));
    s.set("target_error", std::move(t));
  }
  if (scene.adaptive) {
    Json adaptive = Json::object();
    adaptive.set("tolerance", Json(scene.adaptive->tolerance));
    adaptive.set("rejections", Json(double(r.rejections)));
    s.set("adaptive", std::move(adaptive));
  }
}

// What the run cost: its wall time by phase (the target-error mode's pilots in the total, not in the
// phases), the threads and processes, the linear strategy, the BLAS kernels and the full factorisations.
void set_costs(Json& s, const Scene& scene, const FoundationRunResult& r) {
  const double pilots = scene.target_choice ? scene.target_choice->pilots_seconds_of(r.foundation) : 0;
  s.set("wall_s_total", Json(r.wall_seconds + pilots));
  s.set("threads", Json(double(assembly_threads())));
  if (!r.linear_strategy.empty()) s.set("linear_strategy", Json(r.linear_strategy));
  // Where the wall time went (models/scene/run_timing.hpp), and the factorisations it paid for.
  Json timing = Json::object();
  for (const RunPhase& phase : run_phases(r)) timing.set(phase.name + "_s", Json(phase.seconds));
  timing.set("factorizations", Json(double(r.factorizations)));
  s.set("timing", std::move(timing));
  s.set("processes", Json(double(processes::count())));
  // The BLAS kernels that ran: another CPU's kernels give results equal to round-off, not to the bit.
  const BlasInfo& blas = blas_info();
  s.set("blas", Json::object({{"vendor", Json(blas.vendor)},
                              {"core", Json(blas.core)},
                              {"config", Json(blas.config)},
                              {"library", Json(blas.library)}}));
  // What the solver of the full factorisations predicted of them (MUMPS's INFOG), when they were made.
  if (r.full_factors.entries > 0) {
    Json f = Json::object();
    f.set("symmetric", Json(r.full_factors.symmetric));
    f.set("factor_entries", Json(r.full_factors.entries));
    f.set("gflop", Json(r.full_factors.flops / 1e9));
    f.set("memory_mb_all_processes", Json(r.full_factors.memory_bytes / 1e6));
    f.set("memory_mb_largest_process", Json(r.full_factors.largest_process_memory_bytes / 1e6));
    s.set("factorization", std::move(f));
  }
}

}  // namespace

void write_summary(const Scene& scene, const std::string& dir, const FoundationRunResult& r, int steps) {
  Json s = Json::object();
  set_run(s, scene, r, steps);
  set_errors(s, scene, r);
  set_costs(s, scene, r);
  for (const auto& [name, value] : result_numbers(r)) s.set(name, finite_or_null(value));
  s.set("n_contact_nodes", Json(double(r.n_contact_nodes)));
  s.set("n_slip_nodes", Json(double(r.n_slip_nodes)));
  s.set("slip_threshold", Json(scene.output.slip_threshold));
  if (!r.message.empty()) s.set("message", Json(r.message));
  write_atomically(dir + "/summary.json", "summary", [&](std::ostream& out) { out << s.dump(2) << "\n"; });
}

}  // namespace pc

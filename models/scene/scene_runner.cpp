#include "models/scene/scene_runner.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>


#include "assembly/blas_info.hpp"
#include "assembly/atomic_file.hpp"
#include "assembly/blas_workspace.hpp"
#include "assembly/error.hpp"
#include "assembly/point_locator.hpp"
#include "assembly/processes.hpp"
#include "assembly/threads.hpp"
#include "bricks/law_registry.hpp"
#include "models/model_state.hpp"
#include "models/output/boundary_table.hpp"
#include "models/output/checkpoint.hpp"
#include "models/output/contact_output_fields.hpp"
#include "models/output/csv_log.hpp"
#include "models/output/piezo_fields.hpp"
#include "models/scene/interrupts.hpp"
#include "models/scene/mesh_summary.hpp"
#include "models/scene/run_manifest.hpp"
#include "models/scene/run_timing.hpp"
#include "models/scene/target_error.hpp"
#include "models/scene/time_estimate.hpp"
#include "models/output/result_series.hpp"
#include "models/piezo/contact_resultant.hpp"
#include "models/piezo/electrodes.hpp"
#include "models/piezo/energy_books.hpp"
#include "models/piezo/initial_potential.hpp"
#include "models/piezo/piezo_space_error.hpp"

namespace pc {
namespace {

// Value of one component of a field at a point (0 if the model has no such field).
double probe(const Model& m, const PointLocator& locator, const std::string& field, int component,
             const std::array<double, 3>& x) {
  if (!m.has_field(field)) return 0;
  return evaluate_at(m.space(field), m.values(field), locator, x.data())[component];
}

// The model's own normal brick's contact fields at the contact nodes, at the model's time (built.normal set).
ContactOutputFields contact_fields_of(const PiezoContactModel& built, double slip_threshold) {
  const Model& m = *built.model;
  return contact_output_fields(*built.normal, m.space("v"), built.contact_nodes, m.values(built.contact_argument),
                               m.values("v"), slip_threshold, m.time());
}

std::string describe_duration(double seconds) {
  if (seconds < 90) return message(int(seconds + 0.5), " s");
  if (seconds < 5400) return message(int(seconds / 60 + 0.5), " min");
  return message(int(seconds / 3600 + 0.5), " h");
}

std::string eta(double elapsed, double done_fraction) {
  if (done_fraction <= 0) return "?";
  return describe_duration(elapsed * (1 - done_fraction) / done_fraction);
}

// Block residual norms as "1.00e-10 / 2.00e-17".
std::string residual_text(const std::vector<double>& norms) {
  std::string text;
  for (double norm : norms) {
    char part[32];
    std::snprintf(part, sizeof part, "%s%.2e", text.empty() ? "" : " / ", norm);
    text += part;
  }
  return text;
}

// No non-finite number is ever written as a result: a table with one is refused, naming the file, the
// column and the row, and the run stops there (the caller turns the error into its stop message).
void require_finite_rows(const std::string& what, const std::vector<std::string>& columns,
                         const std::vector<std::vector<double>>& rows) {
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t c = 0; c < rows[i].size(); ++c)
      require(std::isfinite(rows[i][c]), what, ": ", columns[c], " in row ", i + 1, " is not finite (",
              std::isnan(rows[i][c]) ? "not a number" : "it overflowed", "); nothing non-finite is written");
}

void write_finite_csv(const std::string& path, const std::vector<std::string>& columns,
                      const std::vector<std::vector<double>>& rows) {
  require_finite_rows(std::filesystem::path(path).filename().string(), columns, rows);
  write_csv(path, columns, rows);
}

// The model's unknowns must all be finite (the first non-finite one is named).
void require_finite_state(const Model& m, const std::string& when) {
  for (const std::string& u : m.unknowns())
    require(m.values(u).allFinite(), when, ": the unknown '", u, "' is not finite");
}

void write_final_tables(const Scene& scene, const PiezoContactModel& built, const PointLocator& locator,
                        const std::string& dir, FoundationRunResult& r) {
  const Model& m = *built.model;
  const Mesh& mesh = m.mesh();
  const int dim = mesh.dim();
  const bool electric = m.has_field("phi");
  auto at = [&](const std::string& field, int c, const std::array<double, 3>& x) {
    return probe(m, locator, field, c, x);
  };

  // Contact boundary, sorted by x: the nodal dof values (a clamped node reads exact zeros), the model's own
  // normal brick for the pressure, each node's own normal for the slip.
  if (built.normal) {
    const FESpace& vspace = m.space("v");
    const BoundaryNodes nodes = boundary_nodes(vspace, scene.spec.contact, 0);
    const ContactNodes& contact = built.contact_nodes;
    const ContactOutputFields fields = contact_fields_of(built, scene.output.slip_threshold);
    const std::vector<double>& pressure = fields.pressure;
    const std::vector<double>& slip = fields.slip;
    std::vector<double> phi;
    if (electric) phi = values_at_nodes(nodes, m.space("phi"), m.values("phi"), 0);
    std::vector<std::vector<double>> rows;
    for (size_t i = 0; i < nodes.points.size(); ++i) {
      const int dof = nodes.scalar_dofs[i];
      const size_t k = std::lower_bound(contact.scalar_dofs.begin(), contact.scalar_dofs.end(), dof) -
                       contact.scalar_dofs.begin();
      std::vector<double> row = {nodes.points[i][0]};
      if (dim == 3) row.push_back(nodes.points[i][2]);
      for (const char* field : {"u", "v"})
        for (int d = 0; d < dim; ++d) row.push_back(m.values(field)[vspace.dof(dof, d)]);
      row.push_back(electric ? phi[i] : 0.0);
      row.push_back(pressure[k]);
      rows.push_back(row);
      r.max_abs_vtau_contact = std::max(r.max_abs_vtau_contact, slip[k]);
    }
    std::vector<std::string> columns = dim == 2 ? std::vector<std::string>{"x", "ux", "uy", "vx", "vy", "phi", "contact_pressure"}
                                                : std::vector<std::string>{"x", "z", "ux", "uy", "uz", "vx", "vy", "vz", "phi",
                                                                           "contact_pressure"};
    if (!dir.empty()) write_finite_csv(dir + "/gamma_c.csv", columns, rows);
  }
  if (dir.empty()) return;

  // The output grid (x fastest, then y, then z): every coordinate and every component of u and v.
  if (scene.output.grid.nx > 0 && scene.output.grid.ny > 0) {
    std::vector<std::string> columns = {"x", "y", "z"};
    columns.resize(size_t(dim));
    for (const char* field : {"u", "v"})
      for (int d = 0; d < dim; ++d) columns.push_back(message(field, "xyz"[d]));
    columns.push_back("phi");
    std::vector<std::vector<double>> rows;
    for (const std::array<double, 3>& x : scene.output.grid.points()) {
      std::vector<double> row(x.begin(), x.begin() + dim);
      for (const char* field : {"u", "v"})
        for (int d = 0; d < dim; ++d) row.push_back(at(field, d, x));
      row.push_back(electric ? at("phi", 0, x) : 0.0);
      rows.push_back(row);
    }
    write_finite_csv(dir + "/grid.csv", columns, rows);
  }

  // The final state on the mesh, for the figures (2D).
  if (dim != 2) return;
  std::vector<std::vector<double>> node_rows;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const std::array<double, 3> x = {mesh.node(n)[0], mesh.node(n)[1], 0};
    node_rows.push_back({double(n), x[0], x[1], at("u", 0, x), at("u", 1, x), at("v", 0, x), at("v", 1, x),
                         electric ? at("phi", 0, x) : 0.0});
  }
  write_finite_csv(dir + "/final_nodes.csv", {"node", "x", "y", "ux", "uy", "vx", "vy", "phi"}, node_rows);
  const std::vector<double> stress = cell_stress(m);
  const int voigt = 3;
  std::vector<std::vector<double>> cell_rows;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell(c);
    const double vm = von_mises(std::span<const double>(stress.data() + c * voigt, voigt), dim);
    double phi_mean = 0;
    for (int n : nodes) phi_mean += node_rows[n][7] / double(nodes.size());
    // Quadrilaterals are written as two triangles, so the table is always a triangulation.
    cell_rows.push_back({double(nodes[0]), double(nodes[1]), double(nodes[2]), vm, phi_mean});
    if (nodes.size() == 4) cell_rows.push_back({double(nodes[0]), double(nodes[2]), double(nodes[3]), vm, phi_mean});
  }
  write_finite_csv(dir + "/final_cells.csv", {"n0", "n1", "n2", "von_mises", "phi_mean"}, cell_rows);
}

// The stepper's counts without the time error estimate's history (vectors of the mesh's size), which a
// copy per step would not afford.
StepperState counts_of(const StepperState& s) {
  return {.time = s.time, .step_size = s.step_size, .steps = s.steps, .successes = s.successes,
          .attempts = s.attempts, .cutbacks = s.cutbacks, .newton_iterations_total = s.newton_iterations_total,
          .newton_iterations_max_per_step = s.newton_iterations_max_per_step, .rejections = s.rejections,
          .last_error = s.last_error, .time_error = {}};
}

// history.csv, a row per step: the corner's u_y (and u_z in 3D), the centre's potential, Newton's iterations.
std::vector<std::string> history_columns(int dim) {
  if (dim == 3) return {"t", "uy_corner", "uz_corner", "phi_center", "newton_iterations"};
  return {"t", "uy_corner", "phi_center", "newton_iterations"};
}

std::vector<double> history_row(const Model& m, const PointLocator& locator, const SceneOutput& output, double t,
                                int newton_iterations) {
  std::vector<double> row = {t, probe(m, locator, "u", 1, output.corner)};
  if (m.mesh().dim() == 3) row.push_back(probe(m, locator, "u", 2, output.corner));
  row.push_back(probe(m, locator, "phi", 0, output.center));
  row.push_back(double(newton_iterations));
  return row;
}

}  // namespace

double FoundationRunResult::space_error_peak() const {
  double peak = 0;
  for (const auto& [field, largest] : space_error_largest) {
    const auto scale = space_error_scale.find(field);
    if (scale != space_error_scale.end() && scale->second > 0) peak = std::max(peak, largest / scale->second);
  }
  return peak;
}

namespace {

// The result's numbers by name, as summary.json holds them.
std::vector<std::pair<const char*, double>> result_numbers(const FoundationRunResult& r) {
  std::vector<std::pair<const char*, double>> numbers = {{"max_abs_ux", r.max_abs_ux}, {"max_abs_uy", r.max_abs_uy}};
  if (r.dim == 3) numbers.push_back({"max_abs_uz", r.max_abs_uz});
  numbers.insert(numbers.end(), {{"phi_min", r.phi_min}, {"phi_max", r.phi_max}, {"ux_corner", r.ux_corner},
                                 {"uy_corner", r.uy_corner}});
  if (r.dim == 3) numbers.push_back({"uz_corner", r.uz_corner});
  numbers.insert(numbers.end(), {{"phi_center", r.phi_center}, {"max_abs_vtau_contact", r.max_abs_vtau_contact}});
  return numbers;
}

// A number of the summary, or null when it is not finite (JSON has no NaN; the run is then not completed).
Json finite_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

void write_summary(const Scene& scene, const std::string& dir, const FoundationRunResult& r, int steps) {
  Json s = Json::object();
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
  // The target-error mode: what it chose, what it predicted, and what the run's estimates say it achieved.
  if (const auto& c = scene.target_choice) {
    Json t = Json::object();
    t.set("target", Json(c->target));
    t.set("chosen", Json(c->description()));
    t.set("predicted_space", Json(c->predicted_space));
    t.set("predicted_time", Json(c->predicted_time));
    t.set("predicted_seconds", Json(c->predicted_seconds));
    t.set("achieved_space", finite_or_null(r.space_error_peak()));
    t.set("achieved_time", finite_or_null(r.time_error_peak));
    t.set("achieved", finite_or_null(r.space_error_peak() + r.time_error_peak));
    t.set("why", Json(c->explanation));
    s.set("target_error", std::move(t));
  }
  if (scene.adaptive) {
    Json adaptive = Json::object();
    adaptive.set("tolerance", Json(scene.adaptive->tolerance));
    adaptive.set("rejections", Json(double(r.rejections)));
    s.set("adaptive", std::move(adaptive));
  }
  s.set("wall_s_total", Json(r.wall_seconds));
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
  s.set("blas", Json::object({{"vendor", Json(blas.vendor)}, {"core", Json(blas.core)},
                              {"config", Json(blas.config)}, {"library", Json(blas.library)}}));
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
  for (const auto& [name, value] : result_numbers(r)) s.set(name, finite_or_null(value));
  s.set("n_contact_nodes", Json(double(r.n_contact_nodes)));
  s.set("n_slip_nodes", Json(double(r.n_slip_nodes)));
  s.set("slip_threshold", Json(scene.output.slip_threshold));
  if (!r.message.empty()) s.set("message", Json(r.message));
  write_atomically(dir + "/summary.json", "summary", [&](std::ostream& out) { out << s.dump(2) << "\n"; });
}

}  // namespace

namespace {

PiezoContactModel build_foundation_model(const Scene& scene, const SceneFoundation& foundation) {
  PiezoContactSpec spec = scene.spec;
  spec.foundation = foundation.law;
  try {
    return build_piezo_contact_model(spec);
  } catch (const std::bad_alloc& e) {
    fail("out of memory while building the model of the ", foundation.name, " foundation (",
         spec.mesh->num_cells(), " cells, P", spec.order, "): ", e.what(), "; coarsen the mesh, or free memory");
  }
}

}  // namespace

FoundationRun::FoundationRun(const Scene& scene, const SceneFoundation& foundation)
    : scene_(scene), foundation_(foundation), built_(build_foundation_model(scene, foundation)), newton_(scene.newton) {}

FoundationRunResult run_foundation(const Scene& scene, const SceneFoundation& foundation, const std::string& dir,
                                   bool progress, int steps_override) {
  return FoundationRun(scene, foundation).run(dir, progress, steps_override);
}

FoundationRunResult FoundationRun::run(const std::string& dir, bool progress, int steps_override) {
  FoundationRunOptions options;
  options.directory = dir;
  options.progress = progress;
  options.steps_override = steps_override;
  return run(options);
}

namespace {

// The runner's own totals, kept in a checkpoint so that a resumed run's summary counts the whole run.
void save_totals(const FoundationRunResult& r, double wall_seconds, Checkpoint& c) {
  c.numbers["run:assembly_seconds"] = r.assembly_seconds;
  c.numbers["run:jacobian_seconds"] = r.jacobian_seconds;
  c.numbers["run:output_seconds"] = r.output_seconds;
  c.numbers["run:factorize_seconds"] = r.factorize_seconds;
  c.numbers["run:solve_seconds"] = r.solve_seconds;
  c.numbers["run:condensation_seconds"] = r.condensation_seconds;
  c.numbers["run:vtu_seconds"] = r.vtu_seconds;
  c.numbers["run:factorizations"] = r.factorizations;
  c.numbers["run:wall_seconds"] = wall_seconds;
  for (const auto& [field, scale] : r.space_error_scale) c.numbers["run:space_error_scale:" + field] = scale;
  for (const auto& [field, largest] : r.space_error_largest) c.numbers["run:space_error_largest:" + field] = largest;
  c.numbers["run:time_error_peak"] = r.time_error_peak;
}

void restore_totals(const Checkpoint& c, FoundationRunResult& r, double& wall_seconds) {
  r.assembly_seconds = c.number("run:assembly_seconds");
  // A checkpoint of an earlier version has no Jacobian and output times: its part counts as residual and other.
  for (auto [name, value] : {std::pair{"run:jacobian_seconds", &r.jacobian_seconds},
                             std::pair{"run:output_seconds", &r.output_seconds}})
    *value = c.numbers.count(name) ? c.numbers.at(name) : 0.0;
  r.factorize_seconds = c.number("run:factorize_seconds");
  r.solve_seconds = c.number("run:solve_seconds");
  r.condensation_seconds = c.number("run:condensation_seconds");
  // A checkpoint of a build that did not time its VTU output has none.
  r.vtu_seconds = c.numbers.count("run:vtu_seconds") ? c.number("run:vtu_seconds") : 0.0;
  r.factorizations = int(c.number("run:factorizations"));
  wall_seconds = c.number("run:wall_seconds");
  for (const auto& [prefix, values] : {std::pair{std::string("run:space_error_scale:"), &r.space_error_scale},
                                      std::pair{std::string("run:space_error_largest:"), &r.space_error_largest}})
    for (const auto& [key, value] : c.numbers)
      if (key.starts_with(prefix)) (*values)[key.substr(prefix.size())] = value;
  if (c.numbers.count("run:time_error_peak")) r.time_error_peak = c.number("run:time_error_peak");
}

// The series' written steps as two vectors of the checkpoint.
void save_series(const ResultSeries& series, Checkpoint& c) {
  const auto written = series.written();
  Eigen::VectorXd steps(Eigen::Index(written.size())), times(Eigen::Index(written.size()));
  for (size_t i = 0; i < written.size(); ++i) {
    steps[Eigen::Index(i)] = written[i].first;
    times[Eigen::Index(i)] = written[i].second;
  }
  c.vectors["series:steps"] = steps;
  c.vectors["series:times"] = times;
}

std::vector<std::pair<int, double>> restore_series(const Checkpoint& c) {
  const Eigen::VectorXd& steps = c.vector("series:steps");
  const Eigen::VectorXd& times = c.vector("series:times");
  require(steps.size() == times.size(), "checkpoint: the VTU series' steps and times differ in number");
  std::vector<std::pair<int, double>> written;
  for (Eigen::Index i = 0; i < steps.size(); ++i) written.emplace_back(int(steps[i]), times[i]);
  return written;
}

}  // namespace

FoundationRunResult FoundationRun::run(const FoundationRunOptions& run_options) {
  const auto start = std::chrono::steady_clock::now();
  const std::string& dir = run_options.directory;
  // Distributed, every process computes the same replicated results; one writes them and prints.
  const bool writer = processes::is_writer();
  const bool progress = run_options.progress && writer;
  const int steps_override = run_options.steps_override;
  const Scene& scene = scene_;
  const SceneFoundation& foundation = foundation_;
  PiezoContactModel& built = built_;
  NewtonSolver& newton = newton_;
  FoundationRunResult result;
  result.foundation = foundation.name;
  Model& m = *built.model;
  const Mesh& mesh = m.mesh();
  const int dim = result.dim = mesh.dim();
  for (const std::string& u : m.unknowns()) result.ndof += m.space(u).num_dofs();

  // Every run starts from the scene's initial state, whatever an earlier run of this model left.
  for (const std::string& u : m.unknowns()) m.set_values(u, Eigen::VectorXd::Zero(m.space(u).num_dofs()));
  const FESpace& vspace = m.space("v");
  auto constant = [&](const std::vector<double>& value) {
    return vspace.interpolate([&](const double*, double* out) {
      for (int d = 0; d < dim; ++d) out[d] = value[d];
    });
  };
  built.scheme->set_initial_state(m, constant(scene.u0), constant(scene.v0));

  const int steps = steps_override > 0 ? steps_override : scene.steps;
  StepperOptions options;
  options.start = 0;
  options.end = scene.end_time;
  options.step = scene.end_time / steps;
  options.cutback_factor = scene.cutback_factor;
  options.prediction = scene.prediction;
  options.output_every = scene.output.vtu_every;
  options.max_attempts = scene.max_attempts;
  options.max_wall_seconds = scene.max_wall_seconds;
  options.adaptive = scene.adaptive;
  options.estimate_time_error = scene.estimate_time_error;
  options.time_error_propagation = scene.time_error_propagation;
  options.checkpoint_every = dir.empty() ? 0 : scene.output.checkpoint_every;  // the writer's callback writes
  options.stop_requested = [] { return std::string(interrupt_reason() ? interrupt_reason() : ""); };
  const PointLocator locator(mesh);
  const bool electric = m.has_field("phi");
  // Each electrode's V, Q and I join the history's columns.
  ElectrodeMeter electrodes(scene.spec.electrodes);
  std::vector<std::string> history_header = history_columns(dim);
  // The step size and the time error estimate (models/time_error_estimate.hpp): the step's local error and
  // each field's estimated global error, relative.
  const std::vector<std::string> error_fields =
      scene.estimate_time_error ? TimeErrorEstimator::default_fields(m, *built.scheme, scene.time_error_propagation)
                                : std::vector<std::string>{};
  history_header.insert(history_header.end(), {"dt", "err_time_step"});
  for (const std::string& f : error_fields) history_header.push_back("err_time_" + f);
  for (const std::string& column : electrodes.columns()) history_header.push_back(column);
  // With contact, the foundation's resultant force on the body and its power.
  const bool contact = built.normal != nullptr;
  if (contact) {
    for (int d = 0; d < dim; ++d) history_header.push_back(std::string("contact_f") + "xyz"[d]);
    history_header.push_back("contact_power");
  }
  // Backward Euler's energy books (energy_books.hpp), whose identities are that scheme's; a mechanical
  // model starts them at rest (u0 = 0), as it has no initial solve to assemble its stored energy at.
  std::unique_ptr<EnergyBooks> books;
  const bool starts_at_rest = std::all_of(scene.u0.begin(), scene.u0.end(), [](double c) { return c == 0; });
  if (scene.output.energy_books && scene.spec.scheme.name == "backward_euler" && (built.electric || starts_at_rest)) {
    double v0_squared = 0;
    for (double c : scene.v0) v0_squared += c * c;
    double volume = 0;
    for (int c = 0; c < mesh.num_cells(); ++c) volume += mesh.cell_measure(c);
    books = std::make_unique<EnergyBooks>(built, 0.5 * scene.spec.rho * v0_squared * volume);
    for (const std::string& column : EnergyBooks::columns()) history_header.push_back(column);
  }
  const std::string checkpoint_path = dir + "/checkpoint.bin";
  double earlier_wall_seconds = 0;  // of the run's part before a resume

  std::unique_ptr<CsvLog> history;
  // output.contact_history: the contact nodes sorted along the surface, and their state at every step.
  const bool contact_history = contact && scene.output.contact_history;
  BoundaryNodes history_nodes;
  std::vector<size_t> history_order;  // index into built.contact_nodes of each sorted node
  std::vector<std::string> contact_header = {"t"};
  std::unique_ptr<CsvLog> contact_log;
  if (contact_history) {
    history_nodes = boundary_nodes(m.space("v"), scene.spec.contact, 0);
    const std::vector<int>& dofs = built.contact_nodes.scalar_dofs;
    for (size_t i = 0; i < history_nodes.scalar_dofs.size(); ++i) {
      history_order.push_back(size_t(std::lower_bound(dofs.begin(), dofs.end(), history_nodes.scalar_dofs[i]) - dofs.begin()));
      contact_header.push_back("node_" + std::to_string(i));
    }
  }
  auto contact_row = [&](double t) {  // after a step: the model's time is t
    const std::vector<ContactState> states = contact_fields_of(built, scene.output.slip_threshold).state;
    std::vector<double> row = {t};
    for (size_t k : history_order) row.push_back(double(states[k]));
    return row;
  };
  std::unique_ptr<ResultSeries> series;
  if (!dir.empty()) {
    std::error_code error;
    if (writer) {
      std::filesystem::create_directories(dir, error);
      require(!error && std::filesystem::is_directory(dir), "cannot create the output directory '", dir, "' (--out): ",
              error ? error.message() : "a file of that name is in the way");
    }
    processes::any(false);  // the folder exists before the other processes write their pieces into it
    // Distributed, every process writes the piece of its cells of each VTU step, the writer the .pvtu.
    series = std::make_unique<ResultSeries>(dir, scene.name, scene.output.vtu_format);
    series->write_pieces(m.owned_cells());
    // Every process resumes from the writer's checkpoint (the folder is shared), or none does.
    if (processes::broadcast(run_options.resume && std::filesystem::exists(checkpoint_path))) {
      const Checkpoint checkpoint = read_checkpoint(checkpoint_path);
      require(checkpoint.text("foundation") == foundation.name, "--resume: '", checkpoint_path,
              "' is the checkpoint of the foundation '", checkpoint.text("foundation"), "'");
      restore_model_state(m, *built.scheme, checkpoint);
      options.resume = restore_stepper_state(checkpoint);
      restore_totals(checkpoint, result, earlier_wall_seconds);
      std::map<std::string, double> meter_state;
      for (const auto& [key, value] : checkpoint.numbers)
        if (key.starts_with("electrodes.")) meter_state[key] = value;
      electrodes.restore(meter_state);
      if (books) books->restore(checkpoint.vectors);
      if (writer)
        history = std::make_unique<CsvLog>(CsvLog::continue_after(dir + "/history.csv", history_header, options.resume->steps));
      if (writer && contact_history)
        contact_log = std::make_unique<CsvLog>(
            CsvLog::continue_after(dir + "/contact_state.csv", contact_header, options.resume->steps));
      series->continue_from(restore_series(checkpoint));
      if (progress)
        std::printf("  [%s] resumed at step %d, t = %.6g s, from %s\n", foundation.name.c_str(), options.resume->steps,
                    options.resume->time, checkpoint_path.c_str());
    } else {
      series->continue_from({});  // a series of an earlier run in this folder is not mixed in
      if (writer) {
        history = std::make_unique<CsvLog>(dir + "/history.csv", history_header);
        if (contact_history) {
          contact_log = std::make_unique<CsvLog>(dir + "/contact_state.csv", contact_header);
          std::vector<std::vector<double>> where;
          for (const auto& p : history_nodes.points) where.push_back(dim == 3 ? std::vector<double>{p[0], p[1], p[2]}
                                                                             : std::vector<double>{p[0], p[1]});
          write_csv(dir + "/contact_nodes.csv", dim == 3 ? std::vector<std::string>{"x", "y", "z"}
                                                          : std::vector<std::string>{"x", "y"}, where);
        }
        std::filesystem::remove(checkpoint_path, error);
      }
    }
    processes::any(false);  // the writer has cleared the folder's stale steps before any piece is written
  }
  // Writing results, timed as the run's output phase.
  auto timed_output = [&](auto&& write) {
    const auto t = std::chrono::steady_clock::now();
    write();
    result.output_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  StepperCallbacks callbacks;
  callbacks.on_start = [&](Model& model) { return solve_initial_potential(model, *built.scheme, newton); };
  auto add_phases = [&](const NewtonReport& newton) {
    result.assembly_seconds += newton.assembly_seconds;
    result.jacobian_seconds += newton.jacobian_seconds;
    result.factorize_seconds += newton.factorize_seconds + newton.analyze_seconds;
    result.solve_seconds += newton.solve_seconds;
    result.condensation_seconds += newton.condensation_seconds;
    result.factorizations += newton.factorizations;
  };
  // Where the run stands after its last accepted step, for its summary if a callback stops it (a
  // non-finite result, memory running out): the stepper's own state, as each step record carries it.
  StepperState done = options.resume.value_or(StepperState{});
  auto when = [](const StepRecord& r) {
    return r.step == 0 ? message("the initial state (t = ", r.time, ")") : message("step ", r.step, " (t = ", r.time, ")");
  };
  const double first_time = options.resume ? options.resume->time : 0.0;  // of this process's part of the run
  constexpr double progress_seconds = 10;
  auto last_line = std::chrono::steady_clock::now();
  auto since_last_line = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - last_line).count(); };
  // What solver.condensation = "auto" chose and why, kept for the summary and printed once per choice.
  auto note_linear_strategy = [&] {
    if (result.linear_strategy == newton.strategy_explanation()) return;
    result.linear_strategy = newton.strategy_explanation();
    if (progress) std::printf("  [%s] %s\n", foundation.name.c_str(), result.linear_strategy.c_str());
  };
  if (progress) {
    const TimeEstimate predicted = estimate_run_seconds(dim, result.ndof, steps);
    std::printf("  [%s] %d dofs, %d steps: predicted %s (%s)\n", foundation.name.c_str(), result.ndof, steps,
                describe_duration(predicted.seconds).c_str(), predicted.basis);
    // Inside a long step, a line per Newton iteration once progress_seconds have passed without one.
    newton.set_iteration_callback([&](const NewtonReport& report) {
      note_linear_strategy();  // as soon as auto has chosen, not after a long first step
      if (since_last_line() < progress_seconds) return;
      last_line = std::chrono::steady_clock::now();
      std::printf("  [%s] step %d: Newton iteration %d, |R| = %s\n", foundation.name.c_str(), done.steps + 1,
                  int(report.history.size()) - 1, residual_text(report.history.back().residual_norms).c_str());
      std::fflush(stdout);
    });
  }
  // The callback reads this run's locals: the solver, which outlives the run, must not keep it.
  struct ForgetCallback {
    NewtonSolver& newton;
    ~ForgetCallback() { newton.set_iteration_callback(nullptr); }
  } forget_callback{newton};
  // The spatial estimate's largest norm and value per field so far (FoundationRunResult::space_error_peak);
  // the estimator keeps its patch fits from one call to the next.
  PiezoSpaceErrorEstimator space_error_of;
  const auto note_space_error = [&](const SpaceErrorEstimate& estimate) {
    for (const SpaceErrorField& f : estimate.fields) {
      result.space_error_scale[f.field] = std::max(result.space_error_scale[f.field], f.norm);
      result.space_error_largest[f.field] = std::max(result.space_error_largest[f.field], f.estimate);
    }
  };
  callbacks.on_step = [&](const Model& model, const StepRecord& r) {
    add_phases(r.newton);
    NewtonReport cut_back;  // the failed attempts before this step
    static_cast<LinearSolveCost&>(cut_back) = r.cut_back_cost;
    cut_back.assembly_seconds = r.cut_back_assembly_seconds;
    add_phases(cut_back);
    note_linear_strategy();
    done = counts_of(r.state);
    require_finite_state(model, when(r));
    for (const FieldTimeError& e : r.time_error.fields) result.time_error_peak = std::max(result.time_error_peak, e.global);
    if (scene.output.space_error_every > 0 && r.step % scene.output.space_error_every == 0)
      note_space_error(space_error_of(model));
    timed_output([&] {
      std::vector<double> row = history_row(model, locator, scene.output, r.time, r.newton.iterations);
      row.insert(row.end(), {r.dt, r.time_error.max_local()});
      for (const std::string& f : error_fields) {
        const FieldTimeError* e = r.time_error.field(f);
        row.push_back(e ? e->global : 0.0);
      }
      for (const ElectrodeReading& e : electrodes.read(model)) row.insert(row.end(), {e.voltage, e.charge, e.current});
      if (contact) {
        const ContactResultant resultant = contact_resultant(built);
        row.insert(row.end(), resultant.force.begin(), resultant.force.begin() + dim);
        row.push_back(resultant.power);
      }
      if (books) {
        books->record(model);
        for (double value : books->row()) row.push_back(value);
      }
      require_finite_rows(when(r) + ": history.csv", history_header, {row});
      if (history) history->row(row);
      if (contact_log) contact_log->row(contact_row(r.time));
    });
    if (run_options.after_step) run_options.after_step(r);
    // A line every progress_every steps, and at least every progress_seconds: no long silence.
    if (progress && (r.step % scene.output.progress_every == 0 || r.step == 1 || since_last_line() >= progress_seconds)) {
      last_line = std::chrono::steady_clock::now();
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const std::string residuals = residual_text(r.newton.history.back().residual_norms);
      std::printf("  [%s] step %d/%d  t = %.4g s  Newton %d (%s)  |R| = %s  in contact %g, sliding %g  left ~%s\n",
                  foundation.name.c_str(), r.step, steps, r.time, r.newton.iterations, to_string(r.newton.outcome).c_str(),
                  residuals.c_str(),
                  r.newton.diagnostics.count("contact_nodes_in_compression") ? r.newton.diagnostics.at("contact_nodes_in_compression") : 0.0,
                  r.newton.diagnostics.count("contact_nodes_in_slip") ? r.newton.diagnostics.at("contact_nodes_in_slip") : 0.0,
                  eta(elapsed, (r.time - first_time) / (scene.end_time - first_time)).c_str());
      std::fflush(stdout);
    }
  };
  callbacks.on_output = [&](const Model& model, const StepRecord& r) {
    if (r.step == 0) {
      add_phases(r.newton);  // the initial potential's solve (empty without a potential)
      electrodes.read(model);  // the charges the first step's currents start from
      if (books) books->start(model);
    }
    require_finite_state(model, when(r));
    SpaceErrorEstimate space_estimate = space_error_of(model);
    note_space_error(space_estimate);
    if (!series) return;
    timed_output([&] {
      const auto began = std::chrono::steady_clock::now();
      const SceneOutput& out = scene.output;
      VtuWriter writer(mesh);
      add_piezo_output(writer, model, {}, [&](const std::string& name) { return out.writes_vtu_field(name); });
      if (out.writes_vtu_field("contact_pressure") || out.writes_vtu_field("contact_state")) {
        const FESpace& vspace = model.space("v");
        const ContactOutputFields fields =
            built.normal ? contact_fields_of(built, out.slip_threshold) : ContactOutputFields{};
        if (out.writes_vtu_field("contact_pressure"))
          writer.add_point_data("contact_pressure", 1, on_mesh_nodes(vspace, built.contact_nodes, fields.pressure));
        if (out.writes_vtu_field("contact_state"))
          writer.add_point_data("contact_state", 1, on_mesh_nodes(vspace, built.contact_nodes, fields.state));
      }
      if (out.writes_vtu_field("space_error"))
        for (SpaceErrorField& f : space_estimate.fields)
          writer.add_cell_data("space_error_" + f.field, 1, std::move(f.cells));
      const std::string bad = writer.non_finite_array();
      require(bad.empty(), when(r), ": the output field '", bad, "' is not finite; nothing non-finite is written");
      series->write(r.step, r.time, writer);
      result.vtu_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    });
  };
  if (!dir.empty() && writer)
    callbacks.on_checkpoint = [&](const Model& model, const StepperState& state) {
      timed_output([&] {
        Checkpoint checkpoint;
        checkpoint.texts["foundation"] = foundation.name;
        save_model_state(model, *built.scheme, checkpoint);
        save_stepper_state(state, checkpoint);
        const double wall =
            earlier_wall_seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        save_totals(result, wall, checkpoint);  // a resumed run counts this checkpoint's own writing as other
        for (const auto& [key, value] : electrodes.state()) checkpoint.numbers[key] = value;
        if (books)
          checkpoint.vectors.merge(books->state());  // moves the nodes of the books' fresh map, no copy
        save_series(*series, checkpoint);
        write_checkpoint(checkpoint_path, checkpoint);
        if (run_options.after_checkpoint) run_options.after_checkpoint();
      });
    };

  // A non-finite state or result stops the run where it first appears, with a message saying where.
  bool stopped_in_callback = false;
  try {
    const RunSummary run = Stepper(options).run(m, *built.scheme, newton, callbacks);
    result.completed = run.completed;
    result.steps = run.steps;
    result.newton_iterations_total = run.newton_iterations_total;
    result.newton_iterations_max_per_step = run.newton_iterations_max_per_step;
    result.cutbacks = run.cutbacks;
    result.rejections = run.rejections;
    result.time_error = run.time_error.fields;
    result.message = run.message;
    // A completed run has nothing to resume: its checkpoint would only be mistaken for a stopped run's.
    if (run.completed && !dir.empty() && writer) std::filesystem::remove(checkpoint_path);
  } catch (const Error& e) {
    stopped_in_callback = true;
    result.message = e.what();
  } catch (const std::bad_alloc& e) {
    // Out of memory inside a step (a factorisation's fill, most likely): the step is named, and what has
    // been written stays; the state is mid-step, so no final tables are written from it.
    stopped_in_callback = true;
    result.message = message("out of memory in step ", done.steps + 1, " (from t = ", done.time, "): ", e.what(),
                             "; coarsen the mesh, or free memory");
  }
  if (stopped_in_callback) {
    result.completed = false;
    result.steps = done.steps;
    result.newton_iterations_total = done.newton_iterations_total;
    result.newton_iterations_max_per_step = done.newton_iterations_max_per_step;
    result.cutbacks = done.cutbacks;
  }

  const Eigen::VectorXd& u = m.values("u");
  for (int s = 0; s < vspace.num_scalar_dofs(); ++s) {
    result.max_abs_ux = std::max(result.max_abs_ux, std::abs(u[vspace.dof(s, 0)]));
    result.max_abs_uy = std::max(result.max_abs_uy, std::abs(u[vspace.dof(s, 1)]));
    if (dim == 3) result.max_abs_uz = std::max(result.max_abs_uz, std::abs(u[vspace.dof(s, 2)]));
  }
  if (electric) {
    result.phi_min = m.values("phi").minCoeff();
    result.phi_max = m.values("phi").maxCoeff();
    result.phi_center = probe(m, locator, "phi", 0, scene.output.center);
  }
  result.ux_corner = probe(m, locator, "u", 0, scene.output.corner);
  result.uy_corner = probe(m, locator, "u", 1, scene.output.corner);
  if (dim == 3) result.uz_corner = probe(m, locator, "u", 2, scene.output.corner);
  result.full_factors = newton.full_factor_estimate();
  const auto diagnostics = m.diagnostics();
  if (diagnostics.count("contact_nodes_in_slip")) {
    result.n_slip_nodes = int(diagnostics.at("contact_nodes_in_slip"));
    result.n_contact_nodes = int(diagnostics.at("contact_nodes_in_compression"));
  }
  // The final state's spatial error; a state stopped mid-step has none.
  if (!stopped_in_callback) {
    const SpaceErrorEstimate final_estimate = space_error_of(m);
    note_space_error(final_estimate);
    for (const SpaceErrorField& f : final_estimate.fields) {
      const double scale = result.space_error_scale[f.field];
      result.space_error[f.field] = scale > 0 ? f.estimate / scale : 0.0;
    }
  }
  // The final tables hold the final state, unless that is where a non-finite value appeared.
  if (!stopped_in_callback) {
    try {
      timed_output([&] { write_final_tables(scene, built, locator, writer ? dir : "", result); });
    } catch (const Error& e) {
      if (std::string(e.what()).find("not finite") == std::string::npos) throw;
      result.completed = false;
      result.message += (result.message.empty() ? "" : "; ") + message("stopped at the final tables: ", e.what());
    }
  }
  for (const auto& [name, value] : result_numbers(result))
    if (!std::isfinite(value) && result.completed) {
      result.completed = false;
      result.message += (result.message.empty() ? "" : "; ") + message("the result ", name, " is not finite");
    }
  result.wall_seconds =
      earlier_wall_seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!dir.empty() && writer) write_summary(scene, dir, result, steps);
  return result;
}

namespace {

void report_folder_cleaning(const RunManifest& manifest, bool progress) {
  if (progress && !manifest.removed().empty())
    std::printf("removed %zu files of an earlier run from '%s'\n", manifest.removed().size(), manifest.directory().c_str());
  // Files that are not the run's are reported whatever --quiet says: they must not pass for results.
  if (const auto& foreign = manifest.not_of_this_run(); !foreign.empty()) {
    std::fflush(stdout);
    std::fprintf(stderr,
                 "warning: '%s' holds %zu files that are not of this run (e.g. '%s'); they are left alone and listed in "
                 "manifest.json under not_of_this_run\n",
                 manifest.directory().c_str(), foreign.size(), foreign.front().c_str());
  }
}

const char* const sweep_part = "sweep_phi_f";

}  // namespace

bool run_scene(const Scene& scene, const SceneRunOptions& options) {
  set_assembly_threads(scene.threads);  // 0: PIEZOCONTACT_THREADS or the cores
  if (scene.target_error && !scene.target_choice) {  // the target-error mode: choose, then run the choice
    const bool talk = options.progress && processes::is_writer();
    if (talk) std::printf("target error %g: pilot runs\n", *scene.target_error);
    const Scene chosen = scene_for_target_error(scene, options.only, talk);
    if (processes::is_writer())
      std::printf("target error %g: %s\n", *scene.target_error, chosen.target_choice->explanation.c_str());
    return run_scene(chosen, options);
  }
  bool all_completed = true;
  std::string stop_reason;
  const std::string& out = options.output_directory;
  // Distributed, the writer process keeps the folder, its lock and its manifest; the others compute.
  const bool writer = processes::is_writer();
  const bool progress = options.progress && writer;
  // Before the first step: a directory that cannot be written or is in use costs no computing.
  std::unique_ptr<OutputDirectoryLock> lock;
  std::unique_ptr<RunManifest> manifest;
  if (!out.empty() && writer) {
    lock = std::make_unique<OutputDirectoryLock>(out);
    manifest = std::make_unique<RunManifest>(options.resume ? RunManifest::resume(out, scene)
                                                            : RunManifest::start(out, scene));
    report_folder_cleaning(*manifest, options.progress);
  } else if (out.empty()) {
    require(!options.resume, "--resume needs the output directory (--out) of the run to resume");
  }
  auto stopped = [&](const std::string& part, const std::string& reason) {
    all_completed = false;
    if (stop_reason.empty()) stop_reason = part + ": " + reason;
  };
  // Whatever stops the run, its manifest says so: an error (a full disk) is recorded before it goes on up.
  try {
    reserve_blas_workspace();  // now, while memory is plentiful (assembly/blas_workspace.hpp)
    for (const SceneFoundation& f : scene.foundations) {
      if (!options.only.empty() && std::find(options.only.begin(), options.only.end(), f.name) == options.only.end())
        continue;
      if (const std::string reason = agreed_interrupt_reason(); !reason.empty()) {  // nothing new starts
        stopped(f.name, message("not started: ", reason));
        break;
      }
      if (processes::broadcast(manifest && options.resume && manifest->part_state(f.name) == "completed")) {
        if (progress) std::printf("%s, %s foundation: completed before, kept\n", scene.name.c_str(), f.name.c_str());
        continue;
      }
      if (progress) std::printf("%s, %s foundation: %s\n", scene.name.c_str(), f.name.c_str(), scene.mesh_description.c_str());
      FoundationRunOptions run;
      if (!out.empty()) run.directory = out + "/" + f.name;
      if (manifest) {
        manifest->set_part(f.name, "running");
        run.after_checkpoint = [&] { manifest->save(); };
      }
      run.progress = options.progress;
      run.resume = options.resume;
      const FoundationRunResult r = FoundationRun(scene, f).run(run);
      if (manifest) manifest->set_part(f.name, r.completed ? "completed" : "stopped", r.message);
      // The stop reason goes to stderr whatever --quiet says: a failed run is never silent.
      if (!r.completed) {
        stopped(f.name, r.message.empty() ? "(no message)" : r.message);
        std::fflush(stdout);
        if (writer) std::fprintf(stderr, "%s, %s foundation: STOPPED after %d steps: %s\n", scene.name.c_str(), f.name.c_str(),
                     r.steps, r.message.empty() ? "(no message)" : r.message.c_str());
      }
      if (progress)
        std::printf("  %s: %s in %.2f s (VTU output %.2f s), %d Newton iterations (max %d per step); max|ux| = %.4g m, "
                    "max|uy| = %.4g m%s, phi in [%.4g, %.4g] V%s\n",
                    f.name.c_str(), r.completed ? "completed" : "STOPPED", r.wall_seconds, r.vtu_seconds,
                    r.newton_iterations_total,
                    r.newton_iterations_max_per_step, r.max_abs_ux, r.max_abs_uy,
                    r.dim == 3 ? message(", max|uz| = ", r.max_abs_uz, " m").c_str() : "", r.phi_min, r.phi_max,
                    r.message.empty() ? "" : ("; " + r.message).c_str());
      if (progress && scene.target_choice) {
        const double space = r.space_error_peak(), time = r.time_error_peak;
        std::printf("  %s: target error %.3g, estimated %.3g (space %.3g + time %.3g; predicted %.3g + %.3g)\n",
                    f.name.c_str(), scene.target_choice->target, space + time, space, time,
                    scene.target_choice->predicted_space, scene.target_choice->predicted_time);
      }
    }

    // Figure 5: final displacement against the foundation voltage, from one model of the first foundation
    // whose law has a phi_f: each run changes that constant only. A resumed run that stopped in the sweep
    // runs it again (its runs are short and write one table at the end).
    const auto swept = std::find_if(scene.foundations.begin(), scene.foundations.end(), [](const SceneFoundation& f) {
      return find_parameter(foundation_law_registry().at(f.law.name, "foundation").parameters, "phi_f") != nullptr;
    });
    const bool sweep_done_before =
        processes::broadcast(manifest && options.resume && manifest->part_state(sweep_part) == "completed");
    if (options.sweep && !scene.output.phi_f_sweep.empty() && swept != scene.foundations.end() && !out.empty() &&
        !sweep_done_before) {
      if (const std::string reason = agreed_interrupt_reason(); !reason.empty()) {
        stopped(sweep_part, message("not started: ", reason));
      } else {
        if (manifest) manifest->set_part(sweep_part, "running");
        FoundationRun sweep(scene, *swept);
        std::vector<std::vector<double>> rows;
        bool sweep_completed = true;
        std::string sweep_message;
        for (double phi_f : scene.output.phi_f_sweep) {
          sweep.model().set_constant("phi_f", phi_f);
          const FoundationRunResult r = sweep.run("", false, scene.output.sweep_steps);
          if (!r.completed) {
            sweep_completed = false;
            sweep_message = message("phi_f = ", phi_f, " V: ", r.message);
            stopped(sweep_part, sweep_message);
            if (writer)
              std::fprintf(stderr, "%s, sweep phi_f = %g V: STOPPED: %s\n", scene.name.c_str(), phi_f, r.message.c_str());
          }
          rows.push_back({phi_f, r.max_abs_ux, r.max_abs_uy, r.ux_corner, r.uy_corner});
          if (progress)
            std::printf("  sweep phi_f = %g V: max|ux| = %.4g m, max|uy| = %.4g m\n", phi_f, r.max_abs_ux, r.max_abs_uy);
          if (writer)
            write_finite_csv(out + "/sweep_phi_f.csv", {"phi_f", "max_abs_ux", "max_abs_uy", "ux_corner", "uy_corner"},
                             rows);
        }
        if (manifest) manifest->set_part(sweep_part, sweep_completed ? "completed" : "stopped", sweep_message);
      }
    }
  } catch (const std::exception& e) {
    if (manifest) {
      try {
        manifest->finish(false, e.what());
      } catch (const std::exception&) {
        // The error that stopped the run is the one to report.
      }
    }
    throw;
  }
  if (manifest) manifest->finish(all_completed, stop_reason);
  return all_completed;
}

}  // namespace pc

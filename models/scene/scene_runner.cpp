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
#include "models/output/duration_text.hpp"
#include "models/output/piezo_fields.hpp"
#include "models/output/result_series.hpp"
#include "models/piezo/contact_resultant.hpp"
#include "models/piezo/electrodes.hpp"
#include "models/piezo/energy_books.hpp"
#include "models/piezo/initial_potential.hpp"
#include "models/piezo/piezo_space_error.hpp"
#include "models/scene/foundation_summary.hpp"
#include "models/scene/interrupts.hpp"
#include "models/scene/run_checkpoint.hpp"
#include "models/scene/run_manifest.hpp"
#include "models/scene/run_progress.hpp"
#include "models/scene/target_error.hpp"
#include "models/scene/target_error_format.hpp"
#include "models/scene/target_error_outcome.hpp"

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

// Contact boundary, sorted by x: the nodal dof values (a clamped node reads exact zeros), the model's own
// normal brick for the pressure, each node's own normal for the slip. gamma_c.csv, if dir is not empty.
void write_contact_table(const Scene& scene, const PiezoContactModel& built, const std::string& dir,
                         FoundationRunResult& r) {
  const Model& m = *built.model;
  const int dim = m.mesh().dim();
  const bool electric = m.has_field("phi");
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
    const size_t k =
        std::lower_bound(contact.scalar_dofs.begin(), contact.scalar_dofs.end(), dof) - contact.scalar_dofs.begin();
    std::vector<double> row = {nodes.points[i][0]};
    if (dim == 3) row.push_back(nodes.points[i][2]);
    for (const char* field : {"u", "v"})
      for (int d = 0; d < dim; ++d) row.push_back(m.values(field)[vspace.dof(dof, d)]);
    row.push_back(electric ? phi[i] : 0.0);
    row.push_back(pressure[k]);
    rows.push_back(row);
    r.max_abs_vtau_contact = std::max(r.max_abs_vtau_contact, slip[k]);
  }
  std::vector<std::string> columns =
      dim == 2 ? std::vector<std::string>{"x", "ux", "uy", "vx", "vy", "phi", "contact_pressure"}
               : std::vector<std::string>{"x", "z", "ux", "uy", "uz", "vx", "vy", "vz", "phi", "contact_pressure"};
  if (!dir.empty()) write_finite_csv(dir + "/gamma_c.csv", columns, rows);
}

// The output grid (x fastest, then y, then z): every coordinate and every component of u and v. grid.csv.
void write_grid_table(const Scene& scene, const Model& m, const PointLocator& locator, const std::string& dir) {
  const int dim = m.mesh().dim();
  const bool electric = m.has_field("phi");
  auto at = [&](const std::string& field, int c, const std::array<double, 3>& x) {
    return probe(m, locator, field, c, x);
  };
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

// The final state on the mesh, for the figures (2D): final_nodes.csv and final_cells.csv.
void write_mesh_tables(const Model& m, const PointLocator& locator, const std::string& dir) {
  const Mesh& mesh = m.mesh();
  const int dim = mesh.dim();
  const bool electric = m.has_field("phi");
  auto at = [&](const std::string& field, int c, const std::array<double, 3>& x) {
    return probe(m, locator, field, c, x);
  };
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

// The final state's tables (an empty dir writes none, but the contact's largest slip is still taken).
void write_final_tables(const Scene& scene, const PiezoContactModel& built, const PointLocator& locator,
                        const std::string& dir, FoundationRunResult& r) {
  const Model& m = *built.model;
  if (built.normal) write_contact_table(scene, built, dir, r);
  if (dir.empty()) return;
  if (scene.output.grid.nx > 0 && scene.output.grid.ny > 0) write_grid_table(scene, m, locator, dir);
  if (m.mesh().dim() == 2) write_mesh_tables(m, locator, dir);
}

// The stepper's counts without the time error estimate's history (vectors of the mesh's size), which a
// copy per step would not afford.
StepperState counts_of(const StepperState& s) {
  return {.time = s.time,
          .step_size = s.step_size,
          .steps = s.steps,
          .successes = s.successes,
          .attempts = s.attempts,
          .cutbacks = s.cutbacks,
          .newton_iterations_total = s.newton_iterations_total,
          .newton_iterations_max_per_step = s.newton_iterations_max_per_step,
          .rejections = s.rejections,
          .last_error = s.last_error,
          .time_error = {}};
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

PiezoContactModel build_foundation_model(const Scene& scene, const SceneFoundation& foundation) {
  PiezoContactSpec spec = scene.spec;
  spec.foundation = foundation.law;
  try {
    return build_piezo_contact_model(spec);
  } catch (const std::bad_alloc& e) {
    fail("out of memory while building the model of the ", foundation.name, " foundation (", spec.mesh->num_cells(),
         " cells, P", spec.order, "): ", e.what(), "; coarsen the mesh, or free memory");
  }
}

}  // namespace

FoundationRun::FoundationRun(const Scene& scene, const SceneFoundation& foundation)
    : scene_(scene),
      foundation_(foundation),
      built_(build_foundation_model(scene, foundation)),
      newton_(scene.newton) {}

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

// A step as messages name it: "the initial state (t = 0)", "step 12 (t = 0.0012)".
std::string step_name(const StepRecord& r) {
  return r.step == 0 ? message("the initial state (t = ", r.time, ")")
                     : message("step ", r.step, " (t = ", r.time, ")");
}

// Every run starts from the scene's initial state, whatever an earlier run of this model left.
void start_from_initial_state(const Scene& scene, PiezoContactModel& built) {
  Model& m = *built.model;
  const int dim = m.mesh().dim();
  for (const std::string& u : m.unknowns()) m.set_values(u, Eigen::VectorXd::Zero(m.space(u).num_dofs()));
  const FESpace& vspace = m.space("v");
  auto constant = [&](const std::vector<double>& value) {
    return vspace.interpolate([&](const double*, double* out) {
      for (int d = 0; d < dim; ++d) out[d] = value[d];
    });
  };
  built.scheme->set_initial_state(m, constant(scene.u0), constant(scene.v0));
}

// The stepper's options of a run of `steps` steps (the resume, if any, is set from the checkpoint).
StepperOptions stepper_options(const Scene& scene, const std::string& dir, int steps) {
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
  return options;
}

// A run's history.csv, a row per step: the probes (history_columns), the step size and the time error
// estimate, each electrode's V, Q and I, with contact the foundation's resultant force on the body and its
// power, and the energy books; and, with output.contact_history, contact_state.csv (the contact nodes'
// state at every step) and contact_nodes.csv (where those nodes are, sorted along the surface).
class RunHistory {
 public:
  RunHistory(const Scene& scene, PiezoContactModel& built, const PointLocator& locator);
  // A fresh run's files (the writer's).
  void open(const std::string& dir);
  // A resumed run's files (the writer's): their rows up to the checkpoint's step are kept.
  void continue_after(const std::string& dir, int steps);
  // The meters' state in a checkpoint: the electrodes' charges, the energy books.
  void save(Checkpoint& c) const;
  void restore(const Checkpoint& c);
  // At the initial state: the charges the first step's currents start from, and the books' start.
  void start(const Model& model);
  // After an accepted step: its rows, refused if not finite, and written if the files are open.
  void record(const Model& model, const StepRecord& r);

 private:
  void add_energy_books();
  void find_contact_nodes();
  std::vector<double> contact_row(double t) const;

  const Scene& scene_;
  PiezoContactModel& built_;
  const PointLocator& locator_;
  const int dim_;
  ElectrodeMeter electrodes_;
  std::vector<std::string> header_;
  // The step size and the time error estimate (models/time_error_estimate.hpp): the step's local error and
  // each field's estimated global error, relative.
  const std::vector<std::string> error_fields_;
  const bool contact_;          // the model has contact
  const bool contact_history_;  // output.contact_history
  std::unique_ptr<EnergyBooks> books_;
  BoundaryNodes contact_nodes_;        // sorted along the surface
  std::vector<size_t> contact_order_;  // index into built.contact_nodes of each sorted node
  std::vector<std::string> contact_header_ = {"t"};
  std::unique_ptr<CsvLog> history_, contact_log_;
};

RunHistory::RunHistory(const Scene& scene, PiezoContactModel& built, const PointLocator& locator)
    : scene_(scene),
      built_(built),
      locator_(locator),
      dim_(built.model->mesh().dim()),
      electrodes_(scene.spec.electrodes),
      header_(history_columns(dim_)),
      error_fields_(scene.estimate_time_error
                        ? TimeErrorEstimator::default_fields(*built.model, *built.scheme, scene.time_error_propagation)
                        : std::vector<std::string>{}),
      contact_(built.normal != nullptr),
      contact_history_(contact_ && scene.output.contact_history) {
  header_.insert(header_.end(), {"dt", "err_time_step"});
  for (const std::string& f : error_fields_) header_.push_back("err_time_" + f);
  for (const std::string& column : electrodes_.columns()) header_.push_back(column);
  if (contact_) {
    for (int d = 0; d < dim_; ++d) header_.push_back(std::string("contact_f") + "xyz"[d]);
    header_.push_back("contact_power");
  }
  add_energy_books();
  if (contact_history_) find_contact_nodes();
}

// Backward Euler's energy books (energy_books.hpp), whose identities are that scheme's; a mechanical
// model starts them at rest (u0 = 0), as it has no initial solve to assemble its stored energy at.
void RunHistory::add_energy_books() {
  const Mesh& mesh = built_.model->mesh();
  const bool starts_at_rest = std::all_of(scene_.u0.begin(), scene_.u0.end(), [](double c) { return c == 0; });
  if (scene_.output.energy_books && scene_.spec.scheme.name == "backward_euler" &&
      (built_.electric || starts_at_rest)) {
    double v0_squared = 0;
    for (double c : scene_.v0) v0_squared += c * c;
    double volume = 0;
    for (int c = 0; c < mesh.num_cells(); ++c) volume += mesh.cell_measure(c);
    books_ = std::make_unique<EnergyBooks>(built_, 0.5 * scene_.spec.rho * v0_squared * volume);
    for (const std::string& column : EnergyBooks::columns()) header_.push_back(column);
  }
}

// output.contact_history: the contact nodes sorted along the surface, and their columns.
void RunHistory::find_contact_nodes() {
  contact_nodes_ = boundary_nodes(built_.model->space("v"), scene_.spec.contact, 0);
  const std::vector<int>& dofs = built_.contact_nodes.scalar_dofs;
  for (size_t i = 0; i < contact_nodes_.scalar_dofs.size(); ++i) {
    const int dof = contact_nodes_.scalar_dofs[i];
    contact_order_.push_back(size_t(std::lower_bound(dofs.begin(), dofs.end(), dof) - dofs.begin()));
    contact_header_.push_back("node_" + std::to_string(i));
  }
}

void RunHistory::open(const std::string& dir) {
  history_ = std::make_unique<CsvLog>(dir + "/history.csv", header_);
  if (contact_history_) {
    contact_log_ = std::make_unique<CsvLog>(dir + "/contact_state.csv", contact_header_);
    std::vector<std::vector<double>> where;
    for (const auto& p : contact_nodes_.points)
      where.push_back(dim_ == 3 ? std::vector<double>{p[0], p[1], p[2]} : std::vector<double>{p[0], p[1]});
    write_csv(dir + "/contact_nodes.csv",
              dim_ == 3 ? std::vector<std::string>{"x", "y", "z"} : std::vector<std::string>{"x", "y"}, where);
  }
}

void RunHistory::continue_after(const std::string& dir, int steps) {
  history_ = std::make_unique<CsvLog>(CsvLog::continue_after(dir + "/history.csv", header_, steps));
  if (contact_history_)
    contact_log_ = std::make_unique<CsvLog>(CsvLog::continue_after(dir + "/contact_state.csv", contact_header_, steps));
}

void RunHistory::save(Checkpoint& c) const {
  for (const auto& [key, value] : electrodes_.state()) c.numbers[key] = value;
  if (books_) c.vectors.merge(books_->state());  // moves the nodes of the books' fresh map, no copy
}

void RunHistory::restore(const Checkpoint& c) {
  std::map<std::string, double> meter_state;
  for (const auto& [key, value] : c.numbers)
    if (key.starts_with("electrodes.")) meter_state[key] = value;
  electrodes_.restore(meter_state);
  if (books_) books_->restore(c.vectors);
}

void RunHistory::start(const Model& model) {
  electrodes_.read(model);
  if (books_) books_->start(model);
}

void RunHistory::record(const Model& model, const StepRecord& r) {
  std::vector<double> row = history_row(model, locator_, scene_.output, r.time, r.newton.iterations);
  row.insert(row.end(), {r.dt, r.time_error.max_local()});
  for (const std::string& f : error_fields_) {
    const FieldTimeError* e = r.time_error.field(f);
    row.push_back(e ? e->global : 0.0);
  }
  for (const ElectrodeReading& e : electrodes_.read(model)) row.insert(row.end(), {e.voltage, e.charge, e.current});
  if (contact_) {
    const ContactResultant resultant = contact_resultant(built_);
    row.insert(row.end(), resultant.force.begin(), resultant.force.begin() + dim_);
    row.push_back(resultant.power);
  }
  if (books_) {
    books_->record(model);
    for (double value : books_->row()) row.push_back(value);
  }
  require_finite_rows(step_name(r) + ": history.csv", header_, {row});
  if (history_) history_->row(row);
  if (contact_log_) contact_log_->row(contact_row(r.time));
}

// After a step: the model's time is t.
std::vector<double> RunHistory::contact_row(double t) const {
  const std::vector<ContactState> states = contact_fields_of(built_, scene_.output.slip_threshold).state;
  std::vector<double> row = {t};
  for (size_t k : contact_order_) row.push_back(double(states[k]));
  return row;
}

// One run of a FoundationRun's model, from the state start_from_initial_state left: its output folder and
// files, its totals, and the stepper's callbacks that write and count (FoundationRun::run).
class FoundationPass {
 public:
  FoundationPass(std::chrono::steady_clock::time_point start, const Scene& scene, const SceneFoundation& foundation,
                 PiezoContactModel& built, NewtonSolver& newton, const FoundationRunOptions& options);
  FoundationPass(const FoundationPass&) = delete;
  FoundationPass& operator=(const FoundationPass&) = delete;
  // The iteration callback reads this run's members: the solver, which outlives the run, must not keep it.
  ~FoundationPass() { newton_.set_iteration_callback(nullptr); }
  FoundationRunResult run();

 private:
  void open_output();
  void resume_from(const Checkpoint& checkpoint);
  void start_afresh();
  void start_progress();
  StepperCallbacks callbacks();
  void on_step(const Model& model, const StepRecord& r);
  void on_output(const Model& model, const StepRecord& r);
  void write_vtu(const Model& model, const StepRecord& r, SpaceErrorEstimate& space_estimate);
  void on_checkpoint(const Model& model, const StepperState& state);
  bool take_steps();
  void take_final_results();
  void finish(bool stopped_in_callback);
  void add_phases(const NewtonReport& newton);
  void note_linear_strategy();
  void note_space_error(const SpaceErrorEstimate& estimate);
  template <class Write> void timed_output(Write&& write);
  double wall_seconds() const;

  const std::chrono::steady_clock::time_point start_;
  const Scene& scene_;
  const SceneFoundation& foundation_;
  PiezoContactModel& built_;
  Model& m_;
  NewtonSolver& newton_;
  const FoundationRunOptions& options_;
  const std::string& dir_;
  // Distributed, every process computes the same replicated results; one writes them and prints.
  const bool writer_, progress_;
  const int dim_, steps_;
  const std::string checkpoint_path_;
  FoundationRunResult result_;
  StepperOptions stepper_;
  const PointLocator locator_;
  RunHistory history_;
  std::unique_ptr<ResultSeries> series_;
  double earlier_wall_seconds_ = 0;  // of the run's part before a resume
  // Where the run stands after its last accepted step, for its summary if a callback stops it (a
  // non-finite result, memory running out): the stepper's own state, as each step record carries it.
  StepperState done_;
  RunProgress progress_lines_;
  // The spatial estimate's largest norm and value per field so far (FoundationRunResult::space_error_peak);
  // the estimator keeps its patch fits from one call to the next.
  PiezoSpaceErrorEstimator space_error_of_;
};

FoundationPass::FoundationPass(std::chrono::steady_clock::time_point start, const Scene& scene,
                               const SceneFoundation& foundation, PiezoContactModel& built, NewtonSolver& newton,
                               const FoundationRunOptions& options)
    : start_(start),
      scene_(scene),
      foundation_(foundation),
      built_(built),
      m_(*built.model),
      newton_(newton),
      options_(options),
      dir_(options.directory),
      writer_(processes::is_writer()),
      progress_(options.progress && writer_),
      dim_(m_.mesh().dim()),
      steps_(options.steps_override > 0 ? options.steps_override : scene.steps),
      checkpoint_path_(dir_ + "/checkpoint.bin"),
      stepper_(stepper_options(scene, dir_, steps_)),
      locator_(m_.mesh()),
      history_(scene, built, locator_),
      progress_lines_(scene, foundation.name, start, steps_) {
  result_.foundation = foundation.name;
  result_.dim = dim_;
  for (const std::string& u : m_.unknowns()) result_.ndof += m_.space(u).num_dofs();
}

FoundationRunResult FoundationPass::run() {
  open_output();
  done_ = stepper_.resume.value_or(StepperState{});
  progress_lines_.begin(stepper_.resume ? stepper_.resume->time : 0.0);  // of this process's part of the run
  if (progress_) start_progress();
  const bool stopped_in_callback = take_steps();
  take_final_results();
  finish(stopped_in_callback);
  return std::move(result_);
}

// The output directory (the writer creates it) and the VTU series, then either the checkpoint's state to
// continue from or fresh files.
void FoundationPass::open_output() {
  if (dir_.empty()) return;
  if (writer_) {
    std::error_code error;
    std::filesystem::create_directories(dir_, error);
    require(!error && std::filesystem::is_directory(dir_), "cannot create the output directory '", dir_,
            "' (--out): ", error ? error.message() : "a file of that name is in the way");
  }
  processes::any(false);  // the folder exists before the other processes write their pieces into it
  // Distributed, every process writes the piece of its cells of each VTU step, the writer the .pvtu.
  series_ = std::make_unique<ResultSeries>(dir_, scene_.name, scene_.output.vtu_format);
  series_->write_pieces(m_.owned_cells());
  // Every process resumes from the writer's checkpoint (the folder is shared), or none does.
  if (processes::broadcast(options_.resume && std::filesystem::exists(checkpoint_path_)))
    resume_from(read_checkpoint(checkpoint_path_));
  else
    start_afresh();
  processes::any(false);  // the writer has cleared the folder's stale steps before any piece is written
}

// The model, the stepper, the totals, the meters and the files as the checkpoint has them.
void FoundationPass::resume_from(const Checkpoint& checkpoint) {
  require(checkpoint.text("foundation") == foundation_.name, "--resume: '", checkpoint_path_,
          "' is the checkpoint of the foundation '", checkpoint.text("foundation"), "'");
  restore_model_state(m_, *built_.scheme, checkpoint);
  stepper_.resume = restore_stepper_state(checkpoint);
  restore_totals(checkpoint, result_, earlier_wall_seconds_);
  history_.restore(checkpoint);
  if (writer_) history_.continue_after(dir_, stepper_.resume->steps);
  series_->continue_from(restore_series(checkpoint));
  if (progress_)
    std::printf("  [%s] resumed at step %d, t = %.6g s, from %s\n", foundation_.name.c_str(), stepper_.resume->steps,
                stepper_.resume->time, checkpoint_path_.c_str());
}

// Fresh files, and no checkpoint of an earlier run left to be mistaken for this one's.
void FoundationPass::start_afresh() {
  series_->continue_from({});  // a series of an earlier run in this folder is not mixed in
  if (!writer_) return;
  history_.open(dir_);
  std::error_code error;
  std::filesystem::remove(checkpoint_path_, error);
}

// The predicted time, and Newton's iterations' lines inside a long step.
void FoundationPass::start_progress() {
  progress_lines_.predicted(m_);
  newton_.set_iteration_callback([this](const NewtonReport& report) {
    note_linear_strategy();  // as soon as auto has chosen, not after a long first step
    progress_lines_.iteration(report, done_.steps + 1);
  });
}

StepperCallbacks FoundationPass::callbacks() {
  StepperCallbacks callbacks;
  callbacks.on_start = [this](Model& model) { return solve_initial_potential(model, *built_.scheme, newton_); };
  callbacks.on_step = [this](const Model& model, const StepRecord& r) { on_step(model, r); };
  callbacks.on_output = [this](const Model& model, const StepRecord& r) { on_output(model, r); };
  if (!dir_.empty() && writer_)
    callbacks.on_checkpoint = [this](const Model& model, const StepperState& state) { on_checkpoint(model, state); };
  return callbacks;
}

// After each accepted step: its costs and estimates into the totals, its history rows, its progress line.
void FoundationPass::on_step(const Model& model, const StepRecord& r) {
  add_phases(r.newton);
  NewtonReport cut_back;  // the failed attempts before this step
  static_cast<LinearSolveCost&>(cut_back) = r.cut_back_cost;
  cut_back.assembly_seconds = r.cut_back_assembly_seconds;
  add_phases(cut_back);
  note_linear_strategy();
  done_ = counts_of(r.state);
  require_finite_state(model, step_name(r));
  for (const FieldTimeError& e : r.time_error.fields)
    result_.time_error_peak = std::max(result_.time_error_peak, e.global);
  if (scene_.output.space_error_every > 0 && r.step % scene_.output.space_error_every == 0)
    note_space_error(space_error_of_(model));
  timed_output([&] { history_.record(model, r); });
  if (options_.after_step) options_.after_step(r);
  if (progress_) progress_lines_.step(r);
}

// At each output step (step 0 first): the spatial estimate, and the VTU series' step.
void FoundationPass::on_output(const Model& model, const StepRecord& r) {
  if (r.step == 0) {
    add_phases(r.newton);  // the initial potential's solve (empty without a potential)
    history_.start(model);
  }
  require_finite_state(model, step_name(r));
  SpaceErrorEstimate space_estimate = space_error_of_(model);
  note_space_error(space_estimate);
  if (!series_) return;
  timed_output([&] { write_vtu(model, r, space_estimate); });
}

// The step's VTU file: the arrays output.vtu_fields names, refused if one is not finite.
void FoundationPass::write_vtu(const Model& model, const StepRecord& r, SpaceErrorEstimate& space_estimate) {
  const auto began = std::chrono::steady_clock::now();
  const SceneOutput& out = scene_.output;
  VtuWriter writer(m_.mesh());
  add_piezo_output(writer, model, {}, [&](const std::string& name) { return out.writes_vtu_field(name); });
  if (out.writes_vtu_field("contact_pressure") || out.writes_vtu_field("contact_state")) {
    const FESpace& vspace = model.space("v");
    const ContactOutputFields fields =
        built_.normal ? contact_fields_of(built_, out.slip_threshold) : ContactOutputFields{};
    if (out.writes_vtu_field("contact_pressure"))
      writer.add_point_data("contact_pressure", 1, on_mesh_nodes(vspace, built_.contact_nodes, fields.pressure));
    if (out.writes_vtu_field("contact_state"))
      writer.add_point_data("contact_state", 1, on_mesh_nodes(vspace, built_.contact_nodes, fields.state));
  }
  if (out.writes_vtu_field("space_error"))
    for (SpaceErrorField& f : space_estimate.fields)
      writer.add_cell_data("space_error_" + f.field, 1, std::move(f.cells));
  const std::string bad = writer.non_finite_array();
  require(bad.empty(), step_name(r), ": the output field '", bad, "' is not finite; nothing non-finite is written");
  series_->write(r.step, r.time, writer);
  result_.vtu_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
}

// checkpoint.bin (the writer's): the model, the stepper, the totals, the meters and the series' steps.
void FoundationPass::on_checkpoint(const Model& model, const StepperState& state) {
  timed_output([&] {
    Checkpoint checkpoint;
    checkpoint.texts["foundation"] = foundation_.name;
    save_model_state(model, *built_.scheme, checkpoint);
    save_stepper_state(state, checkpoint);
    save_totals(result_, wall_seconds(), checkpoint);  // a resumed run counts this checkpoint's own writing as other
    history_.save(checkpoint);
    save_series(*series_, checkpoint);
    write_checkpoint(checkpoint_path_, checkpoint);
    if (options_.after_checkpoint) options_.after_checkpoint();
  });
}

// The steps, and the stepper's counts into the result; true if a callback stopped them (a non-finite state
// or result stops the run where it first appears, with a message saying where), or memory ran out.
bool FoundationPass::take_steps() {
  bool stopped_in_callback = false;
  try {
    const RunSummary run = Stepper(stepper_).run(m_, *built_.scheme, newton_, callbacks());
    result_.completed = run.completed;
    result_.steps = run.steps;
    result_.newton_iterations_total = run.newton_iterations_total;
    result_.newton_iterations_max_per_step = run.newton_iterations_max_per_step;
    result_.cutbacks = run.cutbacks;
    result_.rejections = run.rejections;
    result_.time_error = run.time_error.fields;
    result_.message = run.message;
    // A completed run has nothing to resume: its checkpoint would only be mistaken for a stopped run's.
    if (run.completed && !dir_.empty() && writer_) std::filesystem::remove(checkpoint_path_);
  } catch (const Error& e) {
    stopped_in_callback = true;
    result_.message = e.what();
  } catch (const std::bad_alloc& e) {
    // Out of memory inside a step (a factorisation's fill, most likely): the step is named, and what has
    // been written stays; the state is mid-step, so no final tables are written from it.
    stopped_in_callback = true;
    result_.message = message("out of memory in step ", done_.steps + 1, " (from t = ", done_.time, "): ", e.what(),
                              "; coarsen the mesh, or free memory");
  }
  if (stopped_in_callback) {
    result_.completed = false;
    result_.steps = done_.steps;
    result_.newton_iterations_total = done_.newton_iterations_total;
    result_.newton_iterations_max_per_step = done_.newton_iterations_max_per_step;
    result_.cutbacks = done_.cutbacks;
  }
  return stopped_in_callback;
}

// The final state's numbers: the largest displacements, the potential's range, the probes, the contact.
void FoundationPass::take_final_results() {
  const FESpace& vspace = m_.space("v");
  const Eigen::VectorXd& u = m_.values("u");
  for (int s = 0; s < vspace.num_scalar_dofs(); ++s) {
    result_.max_abs_ux = std::max(result_.max_abs_ux, std::abs(u[vspace.dof(s, 0)]));
    result_.max_abs_uy = std::max(result_.max_abs_uy, std::abs(u[vspace.dof(s, 1)]));
    if (dim_ == 3) result_.max_abs_uz = std::max(result_.max_abs_uz, std::abs(u[vspace.dof(s, 2)]));
  }
  if (m_.has_field("phi")) {
    result_.phi_min = m_.values("phi").minCoeff();
    result_.phi_max = m_.values("phi").maxCoeff();
    result_.phi_center = probe(m_, locator_, "phi", 0, scene_.output.center);
  }
  result_.ux_corner = probe(m_, locator_, "u", 0, scene_.output.corner);
  result_.uy_corner = probe(m_, locator_, "u", 1, scene_.output.corner);
  if (dim_ == 3) result_.uz_corner = probe(m_, locator_, "u", 2, scene_.output.corner);
  result_.full_factors = newton_.full_factor_estimate();
  const auto diagnostics = m_.diagnostics();
  if (diagnostics.count("contact_nodes_in_slip")) {
    result_.n_slip_nodes = int(diagnostics.at("contact_nodes_in_slip"));
    result_.n_contact_nodes = int(diagnostics.at("contact_nodes_in_compression"));
  }
}

// The final state's spatial error and tables, the results' finiteness, the wall time, summary.json.
void FoundationPass::finish(bool stopped_in_callback) {
  // The final state's spatial error; a state stopped mid-step has none.
  if (!stopped_in_callback) {
    const SpaceErrorEstimate final_estimate = space_error_of_(m_);
    note_space_error(final_estimate);
    for (const SpaceErrorField& f : final_estimate.fields) {
      const double scale = result_.space_error_scale[f.field];
      result_.space_error[f.field] = scale > 0 ? f.estimate / scale : 0.0;
    }
  }
  // The final tables hold the final state, unless that is where a non-finite value appeared.
  if (!stopped_in_callback) {
    try {
      timed_output([&] { write_final_tables(scene_, built_, locator_, writer_ ? dir_ : "", result_); });
    } catch (const Error& e) {
      if (std::string(e.what()).find("not finite") == std::string::npos) throw;
      result_.completed = false;
      result_.message += (result_.message.empty() ? "" : "; ") + message("stopped at the final tables: ", e.what());
    }
  }
  for (const auto& [name, value] : result_numbers(result_))
    if (!std::isfinite(value) && result_.completed) {
      result_.completed = false;
      result_.message += (result_.message.empty() ? "" : "; ") + message("the result ", name, " is not finite");
    }
  result_.wall_seconds = wall_seconds();
  if (!dir_.empty() && writer_) write_summary(scene_, dir_, result_, steps_);
}

// A Newton solve's time per phase and factorisations into the totals.
void FoundationPass::add_phases(const NewtonReport& newton) {
  result_.assembly_seconds += newton.assembly_seconds;
  result_.jacobian_seconds += newton.jacobian_seconds;
  result_.factorize_seconds += newton.factorize_seconds + newton.analyze_seconds;
  result_.solve_seconds += newton.solve_seconds;
  result_.condensation_seconds += newton.condensation_seconds;
  result_.factorizations += newton.factorizations;
}

// What solver.condensation = "auto" chose and why, kept for the summary and printed once per choice.
void FoundationPass::note_linear_strategy() {
  if (result_.linear_strategy == newton_.strategy_explanation()) return;
  result_.linear_strategy = newton_.strategy_explanation();
  if (progress_) print_run_line(foundation_.name, "%s", result_.linear_strategy.c_str());
}

void FoundationPass::note_space_error(const SpaceErrorEstimate& estimate) {
  for (const SpaceErrorField& f : estimate.fields) {
    result_.space_error_scale[f.field] = std::max(result_.space_error_scale[f.field], f.norm);
    result_.space_error_largest[f.field] = std::max(result_.space_error_largest[f.field], f.estimate);
  }
}

// Writing results, timed as the run's output phase.
template <class Write> void FoundationPass::timed_output(Write&& write) {
  const auto t = std::chrono::steady_clock::now();
  write();
  result_.output_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The whole run's, a resumed run's earlier part included.
double FoundationPass::wall_seconds() const {
  return earlier_wall_seconds_ + std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

}  // namespace

FoundationRunResult FoundationRun::run(const FoundationRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  start_from_initial_state(scene_, built_);
  return FoundationPass(start, scene_, foundation_, built_, newton_, options).run();
}

namespace {

void report_folder_cleaning(const RunManifest& manifest, bool progress) {
  if (progress && !manifest.removed().empty())
    std::printf("removed %zu files of an earlier run from '%s'\n", manifest.removed().size(),
                manifest.directory().c_str());
  // Files that are not the run's are reported whatever --quiet says: they must not pass for results.
  if (const auto& foreign = manifest.not_of_this_run(); !foreign.empty()) {
    std::fflush(stdout);
    std::fprintf(
        stderr,
        "warning: '%s' holds %zu files that are not of this run (e.g. '%s'); they are left alone and listed in "
        "manifest.json under not_of_this_run\n",
        manifest.directory().c_str(), foreign.size(), foreign.front().c_str());
  }
}

const char* const sweep_part = "sweep_phi_f";

// A scene's runs once run_scene has its folder: each foundation's, then the phi_f sweep's, and the first
// reason one of them stopped (for the manifest).
class SceneRun {
 public:
  // manifest: the writer's, with an output directory (else null).
  SceneRun(const Scene& scene, const SceneRunOptions& options, RunManifest* manifest)
      : scene_(scene),
        options_(options),
        out_(options.output_directory),
        manifest_(manifest),
        writer_(processes::is_writer()),
        progress_(options.progress && writer_) {}
  void run_foundations();
  void note_what_the_sweep_keeps() const;
  void run_sweep();
  bool all_completed() const { return all_completed_; }
  bool target_met() const { return target_met_; }
  const std::string& stop_reason() const { return stop_reason_; }

 private:
  void run_foundation(const SceneFoundation& f);
  void print_result(const SceneFoundation& f, const FoundationRunResult& r);
  const SceneFoundation* swept_foundation() const;
  void sweep_phi_f(const SceneFoundation& swept);
  void stopped(const std::string& part, const std::string& reason);

  const Scene& scene_;
  const SceneRunOptions& options_;
  const std::string& out_;
  RunManifest* const manifest_;
  // Distributed, the writer process keeps the folder, its lock and its manifest; the others compute.
  const bool writer_, progress_;
  bool all_completed_ = true;
  bool target_met_ = true;  // every target-error run met its target
  std::string stop_reason_;
};

void SceneRun::stopped(const std::string& part, const std::string& reason) {
  all_completed_ = false;
  if (stop_reason_.empty()) stop_reason_ = part + ": " + reason;
}

// The foundations options.only names (all by default), each unless it completed before; none starts
// after an interrupt.
void SceneRun::run_foundations() {
  for (const SceneFoundation& f : scene_.foundations) {
    if (!options_.only.empty() && std::find(options_.only.begin(), options_.only.end(), f.name) == options_.only.end())
      continue;
    if (const std::string reason = agreed_interrupt_reason(); !reason.empty()) {  // nothing new starts
      stopped(f.name, message("not started: ", reason));
      break;
    }
    if (processes::broadcast(manifest_ && options_.resume && manifest_->part_state(f.name) == "completed")) {
      if (progress_) std::printf("%s, %s foundation: completed before, kept\n", scene_.name.c_str(), f.name.c_str());
      continue;
    }
    run_foundation(f);
  }
}

// One foundation's run into OUT/<foundation>/, recorded in the manifest.
void SceneRun::run_foundation(const SceneFoundation& f) {
  if (progress_)
    std::printf("%s, %s foundation: %s\n", scene_.name.c_str(), f.name.c_str(), scene_.mesh_description.c_str());
  FoundationRunOptions run;
  if (!out_.empty()) run.directory = out_ + "/" + f.name;
  if (manifest_) {
    manifest_->set_part(f.name, "running");
    run.after_checkpoint = [this] { manifest_->save(); };
  }
  run.progress = options_.progress;
  run.resume = options_.resume;
  const FoundationRunResult r = FoundationRun(scene_, f).run(run);
  if (manifest_) manifest_->set_part(f.name, r.completed ? "completed" : "stopped", r.message);
  // The stop reason goes to stderr whatever --quiet says: a failed run is never silent.
  if (!r.completed) {
    stopped(f.name, r.message.empty() ? "(no message)" : r.message);
    std::fflush(stdout);
    if (writer_)
      std::fprintf(stderr, "%s, %s foundation: STOPPED after %d steps: %s\n", scene_.name.c_str(), f.name.c_str(),
                   r.steps, r.message.empty() ? "(no message)" : r.message.c_str());
  }
  print_result(f, r);
}

// The run's line of results, and the target-error mode's estimate against its target.
void SceneRun::print_result(const SceneFoundation& f, const FoundationRunResult& r) {
  if (progress_)
    std::printf(
        "  %s: %s in %s (VTU output %s), %d Newton iterations (max %d per step); max|ux| = %.4g m, "
        "max|uy| = %.4g m%s, phi in [%.4g, %.4g] V%s\n",
        f.name.c_str(), r.completed ? "completed" : "STOPPED", describe_duration(r.wall_seconds).c_str(),
        describe_duration(r.vtu_seconds).c_str(), r.newton_iterations_total, r.newton_iterations_max_per_step,
        r.max_abs_ux, r.max_abs_uy, r.dim == 3 ? message(", max|uz| = ", r.max_abs_uz, " m").c_str() : "", r.phi_min,
        r.phi_max, r.message.empty() ? "" : ("; " + r.message).c_str());
  if (!scene_.target_choice) return;
  if (progress_) std::printf("  %s: %s\n", f.name.c_str(), target_result_line(*scene_.target_choice, r).c_str());
  if (!pc::target_met(*scene_.target_choice, r)) {
    target_met_ = false;
    std::fflush(stdout);  // a missed target is said whatever --quiet says
    if (writer_) std::fprintf(stderr, "%s\n", target_missed_warning(*scene_.target_choice, r).c_str());
  }
}

// Figure 5: final displacement against the foundation voltage, from one model of the first foundation
// whose law has a phi_f: each run changes that constant only. A resumed run that stopped in the sweep
// runs it again (its runs are short and write one table at the end).
void SceneRun::run_sweep() {
  const SceneFoundation* swept = swept_foundation();
  const bool sweep_done_before =
      processes::broadcast(manifest_ && options_.resume && manifest_->part_state(sweep_part) == "completed");
  if (swept && !sweep_done_before) {
    if (const std::string reason = agreed_interrupt_reason(); !reason.empty()) {
      stopped(sweep_part, message("not started: ", reason));
    } else {
      sweep_phi_f(*swept);
    }
  }
}

// The foundation the sweep runs (null when there is no sweep to run): the first whose law has a phi_f.
const SceneFoundation* SceneRun::swept_foundation() const {
  if (!options_.sweep || scene_.output.phi_f_sweep.empty() || out_.empty()) return nullptr;
  const auto swept = std::find_if(scene_.foundations.begin(), scene_.foundations.end(), [](const SceneFoundation& f) {
    return find_parameter(foundation_law_registry().at(f.law.name, "foundation").parameters, "phi_f") != nullptr;
  });
  return swept == scene_.foundations.end() ? nullptr : &*swept;
}

// Before the first run: a --set time.steps does not reach the sweep's runs when output.sweep_steps gives
// them their own, which the user, shortening a run, would not expect; said once (nothing when the same
// overrides set output.sweep_steps too).
void SceneRun::note_what_the_sweep_keeps() const {
  if (!progress_ || scene_.output.sweep_steps <= 0 || !swept_foundation()) return;
  std::string steps_override;
  for (const std::string& o : scene_.overrides) {
    const std::string key = o.substr(0, o.find('='));
    if (key == "output.sweep_steps") return;
    if (key == "time.steps") steps_override = o;
  }
  if (!steps_override.empty())
    std::printf("note: --set %s applies to the main runs; the phi_f sweep keeps its %d steps (output.sweep_steps)\n",
                steps_override.c_str(), scene_.output.sweep_steps);
}

// The sweep's runs, OUT/sweep_phi_f.csv rewritten after each.
void SceneRun::sweep_phi_f(const SceneFoundation& swept) {
  if (manifest_) manifest_->set_part(sweep_part, "running");
  FoundationRun sweep(scene_, swept);
  std::vector<std::vector<double>> rows;
  bool sweep_completed = true;
  std::string sweep_message, linear_strategy;
  for (double phi_f : scene_.output.phi_f_sweep) {
    sweep.model().set_constant("phi_f", phi_f);
    const FoundationRunResult r = sweep.run("", false, scene_.output.sweep_steps);
    // The sweep's runs print no progress; what condensation = "auto" chose, once per choice, as a run's.
    if (progress_ && r.linear_strategy != linear_strategy && !r.linear_strategy.empty())
      print_run_line(message("phi_f sweep ", phi_f, " V"), "%s", r.linear_strategy.c_str());
    linear_strategy = r.linear_strategy;
    if (!r.completed) {
      sweep_completed = false;
      sweep_message = message("phi_f = ", phi_f, " V: ", r.message);
      stopped(sweep_part, sweep_message);
      if (writer_)
        std::fprintf(stderr, "%s, sweep phi_f = %g V: STOPPED: %s\n", scene_.name.c_str(), phi_f, r.message.c_str());
    }
    rows.push_back({phi_f, r.max_abs_ux, r.max_abs_uy, r.ux_corner, r.uy_corner});
    if (progress_)
      std::printf("  sweep phi_f = %g V: max|ux| = %.4g m, max|uy| = %.4g m\n", phi_f, r.max_abs_ux, r.max_abs_uy);
    if (writer_)
      write_finite_csv(out_ + "/sweep_phi_f.csv", {"phi_f", "max_abs_ux", "max_abs_uy", "ux_corner", "uy_corner"},
                       rows);
  }
  if (manifest_) manifest_->set_part(sweep_part, sweep_completed ? "completed" : "stopped", sweep_message);
}

}  // namespace

bool run_scene(const Scene& scene, const SceneRunOptions& options) {
  return run_scene_outcome(scene, options).completed;
}

SceneRunOutcome run_scene_outcome(const Scene& scene, const SceneRunOptions& options) {
  set_assembly_threads(scene.threads);               // 0: PIEZOCONTACT_THREADS or the cores
  if (scene.target_error && !scene.target_choice) {  // the target-error mode: choose, then run the choice
    const bool talk = options.progress && processes::is_writer();
    const std::string target = percent(*scene.target_error);
    if (talk) std::printf("target error %s: pilot runs\n", target.c_str());
    const Scene chosen = scene_for_target_error(scene, options.only, talk);
    const TargetErrorChoice& choice = *chosen.target_choice;
    if (talk) std::printf("target error %s: %s\n", target.c_str(), choice.rates.c_str());
    std::fflush(stdout);  // the rates' warnings are said whatever --quiet says
    if (processes::is_writer())
      for (const std::string& warning : choice.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
    if (processes::is_writer()) std::printf("target error %s: %s\n", target.c_str(), choice.explanation.c_str());
    return run_scene_outcome(chosen, options);
  }
  const std::string& out = options.output_directory;
  // Before the first step: a directory that cannot be written or is in use costs no computing.
  std::unique_ptr<OutputDirectoryLock> lock;
  std::unique_ptr<RunManifest> manifest;
  if (!out.empty() && processes::is_writer()) {
    lock = std::make_unique<OutputDirectoryLock>(out);
    manifest = std::make_unique<RunManifest>(options.resume ? RunManifest::resume(out, scene)
                                                            : RunManifest::start(out, scene));
    report_folder_cleaning(*manifest, options.progress);
  } else if (out.empty()) {
    require(!options.resume, "--resume needs the output directory (--out) of the run to resume");
  }
  SceneRun run(scene, options, manifest.get());
  run.note_what_the_sweep_keeps();
  // Whatever stops the run, its manifest says so: an error (a full disk) is recorded before it goes on up.
  try {
    reserve_blas_workspace();  // now, while memory is plentiful (assembly/blas_workspace.hpp)
    run.run_foundations();
    run.run_sweep();
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
  if (manifest) manifest->finish(run.all_completed(), run.stop_reason());
  return {run.all_completed(), run.target_met()};
}

}  // namespace pc

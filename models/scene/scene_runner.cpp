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


#include "assembly/atomic_file.hpp"
#include "assembly/error.hpp"
#include "assembly/point_locator.hpp"
#include "bricks/law_registry.hpp"
#include "models/output/boundary_table.hpp"
#include "models/output/csv_log.hpp"
#include "models/output/piezo_fields.hpp"
#include "models/scene/interrupts.hpp"
#include "models/output/result_series.hpp"
#include "models/piezo/initial_potential.hpp"

namespace pc {
namespace {

// Value of one component of a field at a point (0 if the model has no such field).
double probe(const Model& m, const PointLocator& locator, const std::string& field, int component,
             const std::array<double, 3>& x) {
  if (!m.has_field(field)) return 0;
  return evaluate_at(m.space(field), m.values(field), locator, x.data())[component];
}

// Contact pressure at the mesh nodes (zero off the contact boundary), as VTU point data: the model's own
// normal brick at the contact nodes, each split against its own normal.
std::vector<double> nodal_contact_pressure(const PiezoContactModel& built) {
  const Model& m = *built.model;
  std::vector<double> pressure(m.mesh().num_nodes(), 0.0);
  if (!built.normal) return pressure;
  const FESpace& space = m.space("v");
  const std::vector<double> p =
      nodal_contact_pressure(*built.normal, space, built.contact_nodes, m.values(built.contact_argument));
  // Mesh vertices are the first dofs of each cell; a P2 space's other nodes are not mesh nodes.
  std::map<int, int> vertex_of_dof;
  for (int c = 0; c < m.mesh().num_cells(); ++c) {
    const auto dofs = space.cell_scalar_dofs(c);
    const auto vertices = m.mesh().cell(c);
    for (size_t k = 0; k < vertices.size(); ++k) vertex_of_dof[dofs[k]] = vertices[k];
  }
  for (size_t i = 0; i < p.size(); ++i)
    if (const auto it = vertex_of_dof.find(built.contact_nodes.scalar_dofs[i]); it != vertex_of_dof.end())
      pressure[it->second] = p[i];
  return pressure;
}

std::string eta(double elapsed, double done_fraction) {
  if (done_fraction <= 0) return "?";
  const double left = elapsed * (1 - done_fraction) / done_fraction;
  return left < 90 ? message(int(left + 0.5), " s") : message(int(left / 60 + 0.5), " min");
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
    const std::vector<double> pressure = nodal_contact_pressure(*built.normal, vspace, contact, m.values(built.contact_argument));
    const std::vector<double> slip = nodal_slip_speed(vspace, contact, m.values("v"));
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

  // The output grid (x fastest), in the plane z = 0 for 3D scenes.
  if (scene.output.grid.nx > 0 && scene.output.grid.ny > 0) {
    std::vector<std::vector<double>> rows;
    for (const std::array<double, 3>& x : scene.output.grid.points())
      rows.push_back({x[0], x[1], at("u", 0, x), at("u", 1, x), at("v", 0, x), at("v", 1, x),
                      electric ? at("phi", 0, x) : 0.0});
    write_finite_csv(dir + "/grid.csv", {"x", "y", "ux", "uy", "vx", "vy", "phi"}, rows);
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

// The result's numbers by name, as summary.json holds them.
std::vector<std::pair<const char*, double>> result_numbers(const FoundationRunResult& r) {
  return {{"max_abs_ux", r.max_abs_ux}, {"max_abs_uy", r.max_abs_uy}, {"phi_min", r.phi_min},
          {"phi_max", r.phi_max},       {"ux_corner", r.ux_corner},   {"uy_corner", r.uy_corner},
          {"phi_center", r.phi_center}, {"max_abs_vtau_contact", r.max_abs_vtau_contact}};
}

// A number of the summary, or null when it is not finite (JSON has no NaN; the run is then not completed).
Json finite_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

void write_summary(const Scene& scene, const std::string& dir, const FoundationRunResult& r, int steps) {
  Json s = Json::object();
  s.set("scene", Json(scene.name));
  s.set("foundation", Json(r.foundation));
  s.set("mesh", Json(scene.mesh_description));
  s.set("nx", Json(double(scene.nx)));
  s.set("ny", Json(double(scene.ny)));
  s.set("order", Json(double(scene.spec.order)));
  s.set("steps", Json(double(steps)));
  s.set("completed", Json(r.completed));
  s.set("ndof", Json(double(r.ndof)));
  s.set("newton_iterations_total", Json(double(r.newton_iterations_total)));
  s.set("newton_iterations_max_per_step", Json(double(r.newton_iterations_max_per_step)));
  s.set("wall_s_total", Json(r.wall_seconds));
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
  return build_piezo_contact_model(spec);
}

}  // namespace

FoundationRun::FoundationRun(const Scene& scene, const SceneFoundation& foundation)
    : scene_(scene), foundation_(foundation), built_(build_foundation_model(scene, foundation)), newton_(scene.newton) {}

FoundationRunResult run_foundation(const Scene& scene, const SceneFoundation& foundation, const std::string& dir,
                                   bool progress, int steps_override) {
  return FoundationRun(scene, foundation).run(dir, progress, steps_override);
}

FoundationRunResult FoundationRun::run(const std::string& dir, bool progress, int steps_override) {
  const auto start = std::chrono::steady_clock::now();
  const Scene& scene = scene_;
  const SceneFoundation& foundation = foundation_;
  PiezoContactModel& built = built_;
  NewtonSolver& newton = newton_;
  FoundationRunResult result;
  result.foundation = foundation.name;
  Model& m = *built.model;
  const Mesh& mesh = m.mesh();
  const int dim = mesh.dim();
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
  options.stop_requested = [] { return std::string(interrupt_reason() ? interrupt_reason() : ""); };
  const PointLocator locator(mesh);
  const bool electric = m.has_field("phi");

  std::unique_ptr<CsvLog> history;
  std::unique_ptr<ResultSeries> series;
  if (!dir.empty()) {
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    require(!error && std::filesystem::is_directory(dir), "cannot create the output directory '", dir, "' (--out): ",
            error ? error.message() : "a file of that name is in the way");
    history = std::make_unique<CsvLog>(dir + "/history.csv",
                                       std::vector<std::string>{"t", "uy_corner", "phi_center", "newton_iterations"});
    series = std::make_unique<ResultSeries>(dir, scene.name);
  }
  StepperCallbacks callbacks;
  callbacks.on_start = [&](Model& model) { return solve_initial_potential(model, *built.scheme, newton); };
  auto add_phases = [&](const NewtonReport& newton) {
    result.assembly_seconds += newton.assembly_seconds;
    result.factorize_seconds += newton.factorize_seconds + newton.analyze_seconds;
    result.solve_seconds += newton.solve_seconds;
    result.condensation_seconds += newton.condensation_seconds;
    result.factorizations += newton.factorizations;
  };
  // What the run has done, for its summary if a callback stops it (a non-finite result).
  RunSummary done;
  auto when = [](const StepRecord& r) {
    return r.step == 0 ? message("the initial state (t = ", r.time, ")") : message("step ", r.step, " (t = ", r.time, ")");
  };
  callbacks.on_step = [&](const Model& model, const StepRecord& r) {
    add_phases(r.newton);
    done.steps = r.step;
    done.newton_iterations_total += r.newton.iterations;
    done.cutbacks += r.cutbacks;
    done.newton_iterations_max_per_step = std::max(done.newton_iterations_max_per_step, r.newton.iterations);
    require_finite_state(model, when(r));
    const std::vector<double> row = {r.time, probe(model, locator, "u", 1, scene.output.corner),
                                     electric ? probe(model, locator, "phi", 0, scene.output.center) : 0.0,
                                     double(r.newton.iterations)};
    require_finite_rows(when(r) + ": history.csv", {"t", "uy_corner", "phi_center", "newton_iterations"}, {row});
    if (history) history->row(row);
    if (progress && (r.step % scene.output.progress_every == 0 || r.step == 1)) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::string residuals;
      for (double norm : r.newton.history.back().residual_norms) {
        char text[32];
        std::snprintf(text, sizeof text, "%s%.2e", residuals.empty() ? "" : " / ", norm);
        residuals += text;
      }
      std::printf("  [%s] step %d/%d  t = %.4g s  Newton %d (%s)  |R| = %s  in contact %g, sliding %g  left ~%s\n",
                  foundation.name.c_str(), r.step, steps, r.time, r.newton.iterations, to_string(r.newton.outcome).c_str(),
                  residuals.c_str(),
                  r.newton.diagnostics.count("contact_nodes_in_compression") ? r.newton.diagnostics.at("contact_nodes_in_compression") : 0.0,
                  r.newton.diagnostics.count("contact_nodes_in_slip") ? r.newton.diagnostics.at("contact_nodes_in_slip") : 0.0,
                  eta(elapsed, r.time / scene.end_time).c_str());
      std::fflush(stdout);
    }
  };
  callbacks.on_output = [&](const Model& model, const StepRecord& r) {
    if (r.step == 0) add_phases(r.newton);  // the initial potential's solve (empty without a potential)
    require_finite_state(model, when(r));
    if (!series) return;
    VtuWriter writer(mesh);
    add_piezo_output(writer, model);
    writer.add_point_data("contact_pressure", 1, nodal_contact_pressure(built));
    const std::string bad = writer.non_finite_array();
    require(bad.empty(), when(r), ": the output field '", bad, "' is not finite; nothing non-finite is written");
    series->write(r.step, r.time, writer);
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
    result.message = run.message;
  } catch (const Error& e) {
    stopped_in_callback = true;
    result.completed = false;
    result.steps = done.steps;
    result.newton_iterations_total = done.newton_iterations_total;
    result.newton_iterations_max_per_step = done.newton_iterations_max_per_step;
    result.cutbacks = done.cutbacks;
    result.message = e.what();
  }

  const Eigen::VectorXd& u = m.values("u");
  for (int s = 0; s < vspace.num_scalar_dofs(); ++s) {
    result.max_abs_ux = std::max(result.max_abs_ux, std::abs(u[vspace.dof(s, 0)]));
    result.max_abs_uy = std::max(result.max_abs_uy, std::abs(u[vspace.dof(s, 1)]));
  }
  if (electric) {
    result.phi_min = m.values("phi").minCoeff();
    result.phi_max = m.values("phi").maxCoeff();
    result.phi_center = probe(m, locator, "phi", 0, scene.output.center);
  }
  result.ux_corner = probe(m, locator, "u", 0, scene.output.corner);
  result.uy_corner = probe(m, locator, "u", 1, scene.output.corner);
  const auto diagnostics = m.diagnostics();
  if (diagnostics.count("contact_nodes_in_slip")) {
    result.n_slip_nodes = int(diagnostics.at("contact_nodes_in_slip"));
    result.n_contact_nodes = int(diagnostics.at("contact_nodes_in_compression"));
  }
  // The final tables hold the final state, unless that is where a non-finite value appeared.
  if (!stopped_in_callback) {
    try {
      write_final_tables(scene, built, locator, dir, result);
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
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!dir.empty()) write_summary(scene, dir, result, steps);
  return result;
}

bool run_scene(const Scene& scene, const SceneRunOptions& options) {
  bool all_completed = true;
  const std::string& out = options.output_directory;
  // Before the first step: a directory that cannot be written or is in use costs no computing.
  std::unique_ptr<OutputDirectoryLock> lock;
  if (!out.empty()) lock = std::make_unique<OutputDirectoryLock>(out);
  for (const SceneFoundation& f : scene.foundations) {
    if (!options.only.empty() && std::find(options.only.begin(), options.only.end(), f.name) == options.only.end())
      continue;
    if (interrupt_reason()) break;  // an interrupted run starts nothing new
    if (options.progress) std::printf("%s, %s foundation: %s\n", scene.name.c_str(), f.name.c_str(), scene.mesh_description.c_str());
    const FoundationRunResult r = run_foundation(scene, f, out.empty() ? "" : out + "/" + f.name, options.progress);
    all_completed = all_completed && r.completed;
    // The stop reason goes to stderr whatever --quiet says: a failed run is never silent.
    if (!r.completed) {
      std::fflush(stdout);
      std::fprintf(stderr, "%s, %s foundation: STOPPED after %d steps: %s\n", scene.name.c_str(), f.name.c_str(),
                   r.steps, r.message.empty() ? "(no message)" : r.message.c_str());
    }
    if (options.progress)
      std::printf("  %s: %s in %.2f s, %d Newton iterations (max %d per step); max|ux| = %.4g m, max|uy| = %.4g m, "
                  "phi in [%.4g, %.4g] V%s\n",
                  f.name.c_str(), r.completed ? "completed" : "STOPPED", r.wall_seconds, r.newton_iterations_total,
                  r.newton_iterations_max_per_step, r.max_abs_ux, r.max_abs_uy, r.phi_min, r.phi_max,
                  r.message.empty() ? "" : ("; " + r.message).c_str());
  }

  // Figure 5: final displacement against the foundation voltage, from one model of the first foundation
  // whose law has a phi_f: each run changes that constant only.
  const auto swept = std::find_if(scene.foundations.begin(), scene.foundations.end(), [](const SceneFoundation& f) {
    return find_parameter(foundation_law_registry().at(f.law.name, "foundation").parameters, "phi_f") != nullptr;
  });
  if (options.sweep && !scene.output.phi_f_sweep.empty() && swept != scene.foundations.end() && !out.empty() &&
      !interrupt_reason()) {
    FoundationRun sweep(scene, *swept);
    std::vector<std::vector<double>> rows;
    for (double phi_f : scene.output.phi_f_sweep) {
      sweep.model().set_constant("phi_f", phi_f);
      const FoundationRunResult r = sweep.run("", false, scene.output.sweep_steps);
      all_completed = all_completed && r.completed;
      if (!r.completed)
        std::fprintf(stderr, "%s, sweep phi_f = %g V: STOPPED: %s\n", scene.name.c_str(), phi_f, r.message.c_str());
      rows.push_back({phi_f, r.max_abs_ux, r.max_abs_uy, r.ux_corner, r.uy_corner});
      if (options.progress)
        std::printf("  sweep phi_f = %g V: max|ux| = %.4g m, max|uy| = %.4g m\n", phi_f, r.max_abs_ux, r.max_abs_uy);
      write_finite_csv(out + "/sweep_phi_f.csv", {"phi_f", "max_abs_ux", "max_abs_uy", "ux_corner", "uy_corner"}, rows);
    }
  }
  return all_completed;
}

}  // namespace pc

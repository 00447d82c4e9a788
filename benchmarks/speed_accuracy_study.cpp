// Speed against accuracy on the paper's scene (scenes/paper2d.json, conductive foundation, the richer
// case): which discretisation and solver settings buy how much accuracy, at what cost. From the baseline
// (the scene as shipped: 60 x 20 P1 triangles, 200 steps, backward Euler, c_nu = 1e12, Newton tolerance
// 1e-10, UMFPACK, Schur condensation) it sweeps one axis at a time,
//   mesh       nx = 15, 30, 60, 120, 240 (ny = nx / 3)
//   order      P1, P2
//   steps      25, 50, 100, 200, 400, 800 time steps over the scene's T = 0.2 s
//   scheme     backward_euler, bdf2, theta (0.5: Crank-Nicolson)
//   c_nu       1e9, 1e10, 1e12, 1e14, 1e16
//   tolerance  Newton relative tolerance 1e-4, 1e-6, 1e-8, 1e-10, 1e-12
//   condensation  the Newton step: schur (the default), columns (both solve through the contact dofs,
//              models/solvers/condensed_solve.hpp) or plain (a factorisation per iteration)
//   linear     umfpack, mumps, eigen-lu, with the columns condensation (the Schur one does its sparse
//              work in MUMPS whatever solver.linear says)
// and then jointly ("joint": nx 15, 30, 60, 120 x P1, P2 x 50, 200, 800 steps x backward Euler, BDF2;
// P2 up to 60 x 20) for the Pareto front, and "target": the settings the target-error mode chooses for
// 10 %, 1 % and 0.1 % (its pilots run in this process, the choice then as any other setting). Per run
// it records dofs, Newton iterations, wall time and its phases (assembly, factorisation, solve,
// condensation: summed over the Newton solves), peak resident memory, and the error against the
// reference:
//   err_u, err_v, err_phi          relative discrete L2 error at the final time over the 31 x 11 points
//                                  of grid.csv, ||a - ref|| / ||ref|| (both components for u and v)
//   err_uy_corner_t, err_phi_center_t
//                                  the histories uy_corner(t), phi_center(t) of history.csv: relative
//                                  max-norm over the reference's times, the run's history interpolated
//                                  linearly (times before the run's first step are skipped)
//   error                          max(err_u, err_v, err_phi): the number of the table and the plot.
// The reference is a much finer run of the same scene: P2 on 120 x 40 triangles (58563 dofs, the node
// spacing of P1 on 240 x 80), Newton tolerance 1e-12, backward Euler with 1600 steps, extrapolated in
// time (Richardson: 2 x the 1600-step run - the 800-step run, on the grid and on the histories). The time
// error dominates v, and backward Euler is cleanly first order on this scene, so the extrapolation is
// cheap accuracy: on the reference's mesh it agrees with BDF2 at 800 steps to 3e-4 in v (the 1600-step
// run alone: 4e-3). In space, P2 on 90 x 30 differs from it by 1.1e-4 in u and 1.6e-3 in v: errors below
// that are not resolved. The two runs take about 3 minutes on the 2-core machine when it is quiet (much
// longer when it is shared), so the reference is cached: OUT/reference/ is reused when its settings.txt
// names the same settings, and --reference DIR takes any directory with grid.csv and history.csv (e.g.
// one the runner wrote for the conductive foundation). The reference has the scene's c_nu = 1e12, so the
// c_nu axis measures the modelling error of the penalty as well as its cost, not a discretisation error.
//
// Every run is a fresh child process (this program re-executed with --child), so that peak RSS (VmHWM)
// is per run; it writes grid.csv and history.csv into OUT/runs/<settings>/. Each setting runs --repeat
// times (3 by default) and the fastest run counts, since load from other processes only slows runs down.
// A setting already run in this invocation (the baseline is on every axis) is not run again: its row is
// repeated under the new axis. Run (nice: the machine is shared):
//   nice build/release/benchmarks/speed_accuracy_study OUT [--reference DIR] [--repeat N] [axis ...]
//   /usr/bin/python3 scripts/plot_speed_accuracy.py OUT/speed_accuracy.csv docs/speed_accuracy.png
// Axes default to all of them, in the order above. Rows go to OUT/speed_accuracy.csv as the runs finish
// (an existing file with the same columns is appended to; the plot script keeps the last row of each
// axis and setting) and as a markdown table to stdout.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "models/output/csv_log.hpp"
#include "models/scene/scene_runner.hpp"
#include "models/scene/target_error.hpp"
#include "support/child_process.hpp"

namespace {

using namespace pc;
namespace fs = std::filesystem;

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";
const std::string kFoundation = "conductive";

// What a run may change, as scene overrides.
struct Settings {
  int nx = 0, ny = 0, order = 1, steps = 0;
  std::string scheme;  // backward_euler | bdf2 | theta (with theta = 0.5)
  double c_nu = 0, tolerance = 0;
  double adaptive = 0;  // time.adaptive's tolerance (0: uniform steps)
  std::string linear;
  std::string condensation;  // schur | columns | plain (solver.condensed = false)

  std::vector<std::string> overrides() const {
    std::vector<std::string> o = {"mesh.nx=" + std::to_string(nx),
                                  "mesh.ny=" + std::to_string(ny),
                                  "mesh.order=" + std::to_string(order),
                                  "time.steps=" + std::to_string(steps),
                                  "time.scheme=" + scheme,
                                  "contact.c_nu=" + number(c_nu),
                                  "solver.relative_tolerance=" + number(tolerance),
                                  "solver.linear=" + linear,
                                  "output.vtu_every=1000000"};  // the first and last VTU only
    if (scheme == "theta") o.push_back("time.theta=0.5");
    if (adaptive > 0) o.push_back("time.adaptive=" + number(adaptive));
    if (condensation == "plain")
      o.push_back("solver.condensed=false");
    else
      o.insert(o.end(), {"solver.condensed=true", "solver.condensation=" + condensation});
    return o;
  }
  // One word per setting, no commas (a CSV field and a directory name once spaces become '_').
  std::string label() const {
    return std::to_string(nx) + "x" + std::to_string(ny) + " P" + std::to_string(order) + " " +
           (adaptive > 0 ? "adaptive=" + number(adaptive) : std::to_string(steps) + "steps") + " " + scheme +
           " c_nu=" + number(c_nu) + " tol=" + number(tolerance) + " " + linear + " " + condensation;
  }
  static std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
  }
};

// The baseline: the scene as shipped.
Settings baseline() {
  const Scene scene = load_scene_file(kScene);
  Settings s;
  s.nx = scene.nx;
  s.ny = scene.ny;
  s.order = scene.spec.order;
  s.steps = scene.steps;
  s.scheme = scene.spec.scheme.name;
  s.c_nu = scene.spec.normal.parameters.at("c_nu");
  s.tolerance = scene.newton.relative_tolerance;
  s.linear = scene.newton.linear_solver;
  s.condensation = scene.newton.condensed_max_fraction > 0 ? scene.newton.condensation : "plain";
  return s;
}

// The reference's finer run (see the header): P2 on a 2x finer mesh (4x finer node spacing), 8x more
// steps, a tighter Newton tolerance.
Settings reference_settings() {
  Settings s = baseline();
  s.nx = 120;
  s.ny = 40;
  s.order = 2;
  s.steps = 1600;
  s.tolerance = 1e-12;
  return s;
}

std::vector<Settings> axis_settings(const std::string& axis, const Settings& base) {
  std::vector<Settings> runs;
  auto vary = [&](auto&& change) {
    Settings s = base;
    change(s);
    runs.push_back(s);
  };
  if (axis == "mesh")
    for (int nx : {15, 30, 60, 120, 240}) vary([&](Settings& s) { s.nx = nx, s.ny = nx / 3; });
  if (axis == "order")
    for (int order : {1, 2}) vary([&](Settings& s) { s.order = order; });
  if (axis == "steps")
    for (int steps : {25, 50, 100, 200, 400, 800}) vary([&](Settings& s) { s.steps = steps; });
  if (axis == "scheme")
    for (const char* scheme : {"backward_euler", "bdf2", "theta"}) vary([&](Settings& s) { s.scheme = scheme; });
  if (axis == "c_nu")
    for (double c_nu : {1e9, 1e10, 1e12, 1e14, 1e16}) vary([&](Settings& s) { s.c_nu = c_nu; });
  if (axis == "tolerance")
    for (double tolerance : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) vary([&](Settings& s) { s.tolerance = tolerance; });
  if (axis == "condensation")
    for (const char* c : {"schur", "columns", "plain"}) vary([&](Settings& s) { s.condensation = c; });
  if (axis == "linear")  // the Schur condensation does its sparse work in MUMPS whatever solver.linear says
    for (const char* linear : {"umfpack", "mumps", "eigen-lu"})
      vary([&](Settings& s) { s.linear = linear, s.condensation = "columns"; });
  if (axis == "joint")  // with BDF2, which the scheme axis shows to be the cheap way to a small error in v;
                        // P2 stops at 60 x 20, since 120 x 40 P2 is the reference's mesh
    for (int nx : {15, 30, 60, 120})
      for (int order : {1, 2})
        for (int steps : {50, 200, 800})
          for (const char* scheme : {"backward_euler", "bdf2"})
            if (order == 1 || nx <= 60)
              vary([&](Settings& s) { s.nx = nx, s.ny = nx / 3, s.order = order, s.steps = steps, s.scheme = scheme; });
  if (axis == "target")  // what --target-error chooses (models/scene/target_error.hpp), from its pilots
    for (double target : {0.1, 0.01, 0.001}) {
      const Scene scene = load_scene_file(kScene, {"target_error=" + Settings::number(target)});
      const auto began = std::chrono::steady_clock::now();
      try {
        const TargetErrorChoice c = choose_for_target_error(scene, {kFoundation}, false);
        std::printf("target %g: %s (pilots and choice %.2f s)\n", target, c.explanation.c_str(),
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count());
        vary([&](Settings& s) {
          s.nx = c.nx, s.ny = c.ny, s.order = c.order, s.adaptive = c.tolerance, s.scheme = c.scheme;
        });
      } catch (const Error& e) {
        std::printf("target %g: refused: %s\n", target, e.what());
      }
      std::fflush(stdout);
    }
  return runs;
}
const std::vector<std::string> kAxes = {"mesh",      "order",        "steps",  "scheme", "c_nu",
                                        "tolerance", "condensation", "linear", "joint",  "target"};

// ------------------------------------------------------------------------------------------- child
// One run into `dir`; prints its numbers on one line for the parent, the run's message last.
int child_main(const std::string& dir, const std::vector<std::string>& overrides) {
  FoundationRunResult r;
  try {
    const Scene scene = load_scene_file(kScene, overrides);
    r = run_foundation(scene, find_foundation(scene, kFoundation), dir, false);
  } catch (const std::exception& e) {
    r.message = e.what();
  }
  std::string message = r.message;
  std::replace(message.begin(), message.end(), '\n', ' ');
  std::printf("%d %d %d %d %d %d %.6f %.6f %.6f %.6f %.6f %ld %s\n", r.completed ? 1 : 0, r.ndof, r.steps,
              r.newton_iterations_total, r.newton_iterations_max_per_step, r.factorizations, r.wall_seconds,
              r.assembly_seconds, r.factorize_seconds, r.solve_seconds, r.condensation_seconds, study::peak_rss_kib(),
              message.c_str());
  return r.completed ? 0 : 1;
}

// ------------------------------------------------------------------------------------------- errors
// A CSV table of numbers with a header line, by column.
using Table = std::map<std::string, std::vector<double>>;

Table read_table(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::string> names;
  Table table;
  if (!std::getline(in, line)) return table;
  std::stringstream header(line);
  for (std::string name; std::getline(header, name, ',');) names.push_back(name);
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string field;
    for (const std::string& name : names) {
      std::getline(fields, field, ',');
      table[name].push_back(std::strtod(field.c_str(), nullptr));
    }
  }
  return table;
}

// ||a - ref|| / ||ref|| over the given columns together (NaN when a column is missing or the sizes differ).
double relative_l2(const Table& a, const Table& ref, const std::vector<std::string>& columns) {
  double diff = 0, norm = 0;
  for (const std::string& c : columns) {
    if (!a.count(c) || !ref.count(c) || a.at(c).size() != ref.at(c).size() || ref.at(c).empty()) return NAN;
    for (size_t i = 0; i < ref.at(c).size(); ++i) {
      diff += std::pow(a.at(c)[i] - ref.at(c)[i], 2);
      norm += std::pow(ref.at(c)[i], 2);
    }
  }
  return std::sqrt(diff / norm);
}

// y(t) by linear interpolation of the samples (ts, ys), ts increasing (steps may be cut back: not uniform).
double interpolate(const std::vector<double>& ts, const std::vector<double>& ys, double t) {
  if (ts.size() == 1) return ys[0];
  const size_t k = std::clamp<size_t>(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin(), 1, ts.size() - 1);
  const double w = (t - ts[k - 1]) / (ts[k] - ts[k - 1]);
  return (1 - w) * ys[k - 1] + w * ys[k];
}

// max_t |a(t) - ref(t)| / max_t |ref(t)| over the reference's times inside the run's time span (a run
// with fewer steps starts later), a interpolated linearly between its own times.
double relative_history_error(const Table& a, const Table& ref, const std::string& column) {
  if (!a.count("t") || !a.count(column) || !ref.count("t") || !ref.count(column) || a.at("t").empty()) return NAN;
  const std::vector<double>&ta = a.at("t"), &tr = ref.at("t"), &yr = ref.at(column);
  const double slack = 1e-9 * tr.back();
  double diff = 0, norm = 0;
  for (size_t i = 0; i < tr.size(); ++i) {
    norm = std::max(norm, std::abs(yr[i]));
    if (tr[i] >= ta.front() - slack && tr[i] <= ta.back() + slack)
      diff = std::max(diff, std::abs(interpolate(ta, a.at(column), tr[i]) - yr[i]));
  }
  return norm > 0 ? diff / norm : NAN;
}

// Richardson extrapolation in time of a first-order scheme from runs with k and 2k: 2 fine - coarse, on
// the grid (same points) and on the histories (at the coarse run's times).
void write_extrapolated(const fs::path& fine, const fs::path& coarse, const fs::path& out) {
  const std::vector<std::string> grid_columns = {"x", "y", "ux", "uy", "vx", "vy", "phi"};
  const Table gf = read_table(fine / "grid.csv"), gc = read_table(coarse / "grid.csv");
  std::vector<std::vector<double>> rows(gc.at("x").size());
  for (size_t i = 0; i < rows.size(); ++i)
    for (const std::string& c : grid_columns)
      rows[i].push_back(c == "x" || c == "y" ? gc.at(c)[i] : 2 * gf.at(c)[i] - gc.at(c)[i]);
  write_csv((out / "grid.csv").string(), grid_columns, rows);

  const Table hf = read_table(fine / "history.csv"), hc = read_table(coarse / "history.csv");
  rows.assign(hc.at("t").size(), {});
  for (size_t i = 0; i < rows.size(); ++i) {
    const double t = hc.at("t")[i];
    rows[i] = {t};
    for (const char* c : {"uy_corner", "phi_center"})
      rows[i].push_back(2 * interpolate(hf.at("t"), hf.at(c), t) - hc.at(c)[i]);
  }
  write_csv((out / "history.csv").string(), {"t", "uy_corner", "phi_center"}, rows);
}

// ------------------------------------------------------------------------------------------- parent
struct Result {
  bool completed = false;
  int dofs = 0, steps = 0, newton = 0, newton_max = 0, factorizations = 0;
  double wall = NAN, assembly = NAN, factorize = NAN, solve = NAN, condensation = NAN, rss_mib = NAN;
  double err_u = NAN, err_v = NAN, err_phi = NAN, err_uy_t = NAN, err_phi_t = NAN;
  std::string message;
  double error() const { return std::max({err_u, err_v, err_phi}); }  // NaN if any is NaN
};

// One run of `s` in a child process writing into `dir`: its numbers, no errors yet.
Result run_once(const Settings& s, const fs::path& dir) {
  fs::remove_all(dir);  // no stale grid.csv from an earlier study
  std::vector<std::string> args = {"--child", dir.string()};
  for (const std::string& o : s.overrides()) args.push_back(o);
  const study::ChildOutput child = study::run_child(args);
  Result r;
  int completed = 0, consumed = 0;
  long rss_kib = -1;
  if (!child.ran || std::sscanf(child.line.c_str(), "%d %d %d %d %d %d %lf %lf %lf %lf %lf %ld %n", &completed, &r.dofs,
                                &r.steps, &r.newton, &r.newton_max, &r.factorizations, &r.wall, &r.assembly,
                                &r.factorize, &r.solve, &r.condensation, &rss_kib, &consumed) < 12) {
    r.message = "the child process failed (status " + std::to_string(child.status) + ")";
    return r;
  }
  r.completed = completed == 1;
  r.message = child.line.substr(size_t(consumed));
  r.rss_mib = rss_kib / 1024.0;
  return r;
}

// The fastest of `repeat` runs (other processes on a shared machine only ever slow a run down; the
// results are the same each time), with its errors against the reference.
Result run(const Settings& s, const fs::path& dir, int repeat, const Table& ref_grid, const Table& ref_history) {
  Result r = run_once(s, dir);
  for (int i = 1; i < repeat && r.completed; ++i) {
    const Result again = run_once(s, dir);
    if (again.completed && again.wall < r.wall) r = again;
  }
  const Table grid = read_table(dir / "grid.csv"), history = read_table(dir / "history.csv");
  r.err_u = relative_l2(grid, ref_grid, {"ux", "uy"});
  r.err_v = relative_l2(grid, ref_grid, {"vx", "vy"});
  r.err_phi = relative_l2(grid, ref_grid, {"phi"});
  r.err_uy_t = relative_history_error(history, ref_history, "uy_corner");
  r.err_phi_t = relative_history_error(history, ref_history, "phi_center");
  // Keep the small tables only: the VTU files and final-state tables of a P2 run are megabytes.
  if (fs::exists(dir))
    for (const auto& entry : fs::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      if (name != "grid.csv" && name != "history.csv" && name != "summary.json" && name != "gamma_c.csv")
        fs::remove(entry.path());
    }
  return r;
}

std::string csv_text(std::string s) {
  std::replace(s.begin(), s.end(), '"', '\'');
  return "\"" + s + "\"";
}

const char* kColumns =
    "axis,label,baseline,nx,ny,order,steps,scheme,c_nu,tolerance,linear,condensation,completed,dofs,steps_done,"
    "newton_iterations,newton_max_per_step,factorizations,wall_s,assembly_s,factorize_s,solve_s,condensation_s,"
    "peak_rss_mib,err_u,err_v,err_phi,err_uy_corner_t,err_phi_center_t,error,message";

// Opens the CSV: appends to a file with the same columns, else starts it.
std::ofstream open_csv(const fs::path& path) {
  std::string header;
  if (std::ifstream existing(path); existing && std::getline(existing, header) && header == kColumns)
    return std::ofstream(path, std::ios::app);
  std::ofstream out(path);
  out << kColumns << "\n" << std::flush;
  return out;
}

void write_row(std::ofstream& csv, const std::string& axis, const Settings& s, bool baseline, const Result& r) {
  char numbers[1024];
  std::snprintf(numbers, sizeof numbers,
                "%d,%d,%d,%d,%s,%g,%g,%s,%s,%d,%d,%d,%d,%d,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.1f,%.6e,%.6e,%.6e,%.6e,%.6e,"
                "%.6e",
                s.nx, s.ny, s.order, s.steps, s.scheme.c_str(), s.c_nu, s.tolerance, s.linear.c_str(),
                s.condensation.c_str(), r.completed ? 1 : 0, r.dofs, r.steps, r.newton, r.newton_max, r.factorizations,
                r.wall, r.assembly, r.factorize, r.solve, r.condensation, r.rss_mib, r.err_u, r.err_v, r.err_phi,
                r.err_uy_t, r.err_phi_t, r.error());
  csv << axis << "," << s.label() << "," << (baseline ? 1 : 0) << "," << numbers << "," << csv_text(r.message) << "\n"
      << std::flush;
}

void print_row(const std::string& axis, const Settings& s, const Result& r, bool as_above) {
  std::printf("| %s | %s%s%s | %d | %d | %.2f | %.0f | %.2e | %.2e | %.2e | %.2e | %.2e |\n", axis.c_str(),
              s.label().c_str(), r.completed ? "" : " (STOPPED)", as_above ? " (as above)" : "", r.dofs, r.newton,
              r.wall, r.rss_mib, r.err_u, r.err_v, r.err_phi, r.err_uy_t, r.err_phi_t);
  std::fflush(stdout);
}

// The reference's directory: --reference DIR, or OUT/reference: the Richardson extrapolation of the
// reference run (OUT/reference/fine) and of the same with half its steps (OUT/reference/coarse), run now
// unless OUT/reference holds one of the same settings (recorded in settings.txt).
fs::path reference_directory(const fs::path& out, const std::string& given) {
  if (!given.empty()) return given;
  const fs::path dir = out / "reference";
  const Settings fine = reference_settings();
  Settings coarse = fine;
  coarse.steps = fine.steps / 2;
  const std::string description = fine.label() + ", extrapolated with " + std::to_string(coarse.steps) + " steps";
  std::string recorded;
  if (std::ifstream in(dir / "settings.txt"); in) std::getline(in, recorded);
  if (recorded == description && fs::exists(dir / "grid.csv") && fs::exists(dir / "history.csv")) {
    std::printf("reference: %s (cached in %s)\n", description.c_str(), dir.string().c_str());
    return dir;
  }
  fs::remove_all(dir);
  for (const auto& [name, s] : {std::pair{"fine", fine}, std::pair{"coarse", coarse}}) {
    std::printf("reference: running %s into %s ...\n", s.label().c_str(), (dir / name).string().c_str());
    std::fflush(stdout);
    std::vector<std::string> args = {"--child", (dir / name).string()};
    for (const std::string& o : s.overrides()) args.push_back(o);
    const study::ChildOutput child = study::run_child(args);
    if (!child.ran || child.status != 0) {
      std::fprintf(stderr, "the reference run failed (status %d): %s\n", child.status, child.line.c_str());
      return {};
    }
    // completed dofs steps newton newton_max factorizations wall ... as run_child prints them
    std::printf("  done: %s\n", child.line.c_str());
  }
  write_extrapolated(dir / "fine", dir / "coarse", dir);
  std::ofstream(dir / "settings.txt") << description << "\n";
  return dir;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 3 && std::string(argv[1]) == "--child")
    return child_main(argv[2], std::vector<std::string>(argv + 3, argv + argc));
  std::string axis_names;
  for (const std::string& a : kAxes) axis_names += " " + a;
  if (argc < 2 || argv[1][0] == '-') {
    std::fprintf(stderr, "usage: %s OUT [--reference DIR] [--repeat N = 3] [axis ...]   (axes:%s; default all)\n",
                 argv[0], axis_names.c_str());
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  const fs::path out = argv[1];
  std::string given_reference;
  int repeat = 3;
  std::vector<std::string> axes;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--reference" && i + 1 < argc) {
      given_reference = argv[++i];
    } else if (a == "--repeat" && i + 1 < argc) {
      repeat = std::max(1, std::stoi(argv[++i]));
    } else if (std::find(kAxes.begin(), kAxes.end(), a) != kAxes.end()) {
      axes.push_back(a);
    } else {
      std::fprintf(stderr, "unknown argument '%s' (axes:%s)\n", a.c_str(), axis_names.c_str());
      return 2;
    }
  }
  if (axes.empty()) axes = kAxes;
  fs::create_directories(out);

  const fs::path reference = reference_directory(out, given_reference);
  const Table ref_grid = read_table(reference / "grid.csv"), ref_history = read_table(reference / "history.csv");
  if (reference.empty() || ref_grid.empty() || ref_history.empty()) {
    std::fprintf(stderr, "no usable reference (grid.csv and history.csv) in '%s'\n", reference.string().c_str());
    return 1;
  }

  const Settings base = baseline();
  std::ofstream csv = open_csv(out / "speed_accuracy.csv");
  std::printf(
      "\nbaseline: %s; wall time: the fastest of %d runs; errors relative to the reference (c_nu axis: the "
      "reference has c_nu = %g, so these errors include the modelling error of the penalty)\n\n",
      base.label().c_str(), repeat, reference_settings().c_nu);
  std::printf(
      "| axis | settings | dofs | Newton its | wall [s] | peak RSS [MiB] | err u | err v | err phi | "
      "err uy_corner(t) | err phi_center(t) |\n");
  std::printf("|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
  std::map<std::string, Result> done;  // by label: a setting already run in this invocation
  int stopped = 0;
  for (const std::string& axis : axes)
    for (const Settings& s : axis_settings(axis, base)) {
      std::string dir_name = s.label();
      std::replace(dir_name.begin(), dir_name.end(), ' ', '_');
      const bool already_run = done.count(s.label()) > 0;
      if (!already_run) done[s.label()] = run(s, out / "runs" / dir_name, repeat, ref_grid, ref_history);
      const Result& r = done.at(s.label());
      stopped += !r.completed && !already_run;
      write_row(csv, axis, s, s.label() == base.label(), r);
      print_row(axis, s, r, already_run);
    }
  std::printf("\n%zu run(s), %d did not complete; study wall time %.0f s; CSV: %s\n", done.size(), stopped,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
              (out / "speed_accuracy.csv").string().c_str());
  return stopped == 0 ? 0 : 1;
}

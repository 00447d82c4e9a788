// How cost grows with problem size: wall time and peak memory against dofs for the paper's scene
// (scenes/paper2d.json, conductive foundation, the harder case), on meshes nx x nx/3 for
// nx = 30, 60, ..., max_nx in P1 and nx = 30, ..., max_nx/2 in P2 (P2 at nx has the dofs of P1 at 2 nx),
// each by three Newton paths: the condensed solve (solver.condensed=true) by its two methods, "schur" and
// "columns" (solver.condensation, see models/solvers/condensed_solve.hpp), and "plain" (a factorisation per Newton
// iteration). Every run has the same number of steps with the scene's own step size (T scaled), so that
// the cost per step is comparable across meshes.
// VmHWM is a process-wide high-water mark, so every run goes into a fresh child process (this program,
// re-executed with --child and the scene overrides); "rss_increment" is VmHWM at the end minus VmHWM after
// loading the scene (mesh built, model not yet): the memory of the model and its run. "other" is the wall
// time outside the phases: model build, the initial potential's solve, the runner's own work. "CPU" is the
// run's user + system time (getrusage), steadier than wall time when the machine is shared.
// The exponent p of cost ~ dofs^p is fitted per order and path by least squares on log-log over the
// completed runs with at least kMinFitDofs dofs (the smaller meshes are dominated by fixed costs).
// The default path (NewtonOptions::condensation) runs on every mesh; a run of another path predicted (from
// its previous mesh) to take longer than budget_s is skipped, and said so. Prints markdown tables (the runs,
// then the exponents); writes the CSV row by row as the runs finish.
//   build/release/benchmarks/cost_growth_study [out.csv = cost_growth.csv] [steps = 20] [max_nx = 480]
//                                              [budget_s = 180]
// Run it with `nice` on a shared machine; timings are of one run each.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>
#include <string>
#include <sys/resource.h>
#include <vector>

#include "models/output/csv_log.hpp"
#include "models/scene/scene_runner.hpp"
#include "models/solvers/newton.hpp"
#include "support/child_process.hpp"

namespace {

using namespace pc;

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";
constexpr double kMinFitDofs = 1e4;
const char* kPaths[] = {"schur", "columns", "plain"};  // solver.condensation, or "plain": not condensed

// The numbers of one run, as the child prints them on one line.
struct Run {
  int completed = 0, dofs = 0, steps = 0, newton_iterations = 0, factorizations = 0;
  double wall = 0, assembly = 0, factorize = 0, solve = 0, condensation = 0, ux_corner = 0;
  double cpu_user = 0, cpu_system = 0;  // of the run (getrusage): on a loaded machine, steadier than wall time
  long minor_faults = 0;                // of the run: pages the allocator mapped and touched
  long hwm_before = 0, hwm = 0;
  long rss_increment() const { return hwm - hwm_before; }
  // Model build, the initial potential's solve (not in the phases) and the runner's own work.
  double other() const { return wall - assembly - factorize - solve - condensation; }
};
const char* kRunFormat = "%d %d %d %d %d %lf %lf %lf %lf %lf %lf %lf %lf %ld %ld %ld";

// The child: loads the scene with the overrides, runs the conductive foundation, prints its numbers.
int run_child(const std::vector<std::string>& overrides) {
  const Scene scene = load_scene_file(kScene, overrides);
  const long hwm_before = study::peak_rss_kib();
  rusage before{}, after{};
  getrusage(RUSAGE_SELF, &before);
  const FoundationRunResult r = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
  getrusage(RUSAGE_SELF, &after);
  auto seconds = [](const timeval& end, const timeval& start) {
    return double(end.tv_sec - start.tv_sec) + 1e-6 * double(end.tv_usec - start.tv_usec);
  };
  std::printf("%d %d %d %d %d %.6f %.6f %.6f %.6f %.6f %.17g %.6f %.6f %ld %ld %ld\n", r.completed ? 1 : 0, r.ndof,
              r.steps, r.newton_iterations_total, r.factorizations, r.wall_seconds, r.assembly_seconds,
              r.factorize_seconds, r.solve_seconds, r.condensation_seconds, r.ux_corner,
              seconds(after.ru_utime, before.ru_utime), seconds(after.ru_stime, before.ru_stime),
              long(after.ru_minflt - before.ru_minflt), hwm_before, study::peak_rss_kib());
  return r.completed ? 0 : 1;
}

// Least-squares slope of log y against log x; NaN with fewer than two points or a non-positive value.
double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const int n = int(x.size());
  if (n < 2) return NAN;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < n; ++i) {
    if (!(x[i] > 0 && y[i] > 0)) return NAN;
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

std::string exponent_text(double p) {
  if (std::isnan(p)) return "-";
  char text[16];
  std::snprintf(text, sizeof text, "%.2f", p);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--child") return run_child(std::vector<std::string>(argv + 2, argv + argc));
  const std::string csv_path = argc > 1 ? argv[1] : "cost_growth.csv";
  const int steps = argc > 2 ? std::stoi(argv[2]) : 20;
  const int max_nx = argc > 3 ? std::stoi(argv[3]) : 480;
  const double budget = argc > 4 ? std::stod(argv[4]) : 180;
  // Keep the scene's step size: T = steps * (T / steps) of the scene as shipped.
  const Scene shipped = load_scene_file(kScene);
  char end_time[32];
  std::snprintf(end_time, sizeof end_time, "%.15g", shipped.end_time / shipped.steps * steps);

  // "path" in the CSV: the index in kPaths.
  CsvLog csv(csv_path, {"order",
                        "nx",
                        "ny",
                        "path",
                        "dofs",
                        "completed",
                        "steps",
                        "newton_iterations",
                        "factorizations",
                        "wall_s",
                        "assembly_s",
                        "factorize_s",
                        "solve_s",
                        "condensation_s",
                        "ux_corner",
                        "cpu_user_s",
                        "cpu_system_s",
                        "minor_page_faults",
                        "vmhwm_before_model_kib",
                        "vmhwm_kib",
                        "rss_increment_kib"});
  std::printf(
      "| order | mesh | dofs | path | Newton its | factorisations | wall [s] | CPU [s] | assembly [s] | factorise [s] "
      "| "
      "solve [s] | condensation [s] | other [s] | peak RSS [MiB] | RSS increment [MiB] |\n");
  std::printf("|--:|---|--:|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
  std::fflush(stdout);

  const std::string default_path = NewtonOptions{}.condensation;
  std::map<std::pair<int, int>, std::vector<std::pair<int, Run>>> runs;  // (order, path) -> (nx, run), nx growing
  int failures = 0;
  for (const int order : {1, 2})
    for (int nx = 30; nx <= (order == 1 ? max_nx : max_nx / 2); nx *= 2)
      for (int path_index = 0; path_index < int(std::size(kPaths)); ++path_index) {
        const int ny = nx / 3;
        const std::string path = kPaths[path_index];
        std::vector<std::pair<int, Run>>& done = runs[{order, path_index}];
        // Predicted time: the previous mesh's, scaled by the cell ratio to the local exponent of the last
        // two meshes (1.5 with only one): a guess good enough to skip what would blow the budget.
        if (path != default_path && !done.empty()) {
          const auto& [last_nx, last] = done.back();
          double p = 1.5;
          if (done.size() >= 2) {
            const Run& before = done[done.size() - 2].second;
            p = std::max(1.0, std::log(last.wall / before.wall) / std::log(double(last.dofs) / before.dofs));
          }
          const double predicted = last.wall * std::pow(double(nx) * ny / (double(last_nx) * (last_nx / 3)), p);
          if (predicted > budget) {
            std::printf("| %d | %d x %d | | %s | skipped: predicted %.0f s > budget %.0f s | | | | | | | | | | |\n",
                        order, nx, ny, path.c_str(), predicted, budget);
            std::fflush(stdout);
            continue;
          }
        }
        std::vector<std::string> args = {"--child",
                                         "mesh.nx=" + std::to_string(nx),
                                         "mesh.ny=" + std::to_string(ny),
                                         "mesh.order=" + std::to_string(order),
                                         "time.steps=" + std::to_string(steps),
                                         std::string("time.T=") + end_time};
        if (path == "plain") {
          args.push_back("solver.condensed=false");
        } else {
          args.push_back("solver.condensed=true");
          args.push_back("solver.condensation=" + path);
        }
        const study::ChildOutput child = study::run_child(args);
        Run r;
        if (!child.ran ||
            std::sscanf(child.line.c_str(), kRunFormat, &r.completed, &r.dofs, &r.steps, &r.newton_iterations,
                        &r.factorizations, &r.wall, &r.assembly, &r.factorize, &r.solve, &r.condensation, &r.ux_corner,
                        &r.cpu_user, &r.cpu_system, &r.minor_faults, &r.hwm_before, &r.hwm) != 16) {
          std::printf("| %d | %d x %d | | %s | FAILED: the child exited with status %d | | | | | | | | | | |\n", order,
                      nx, ny, path.c_str(), child.status);
          std::fflush(stdout);
          ++failures;
          continue;
        }
        failures += !r.completed;
        done.emplace_back(nx, r);
        csv.row({double(order),
                 double(nx),
                 double(ny),
                 double(path_index),
                 double(r.dofs),
                 double(r.completed),
                 double(r.steps),
                 double(r.newton_iterations),
                 double(r.factorizations),
                 r.wall,
                 r.assembly,
                 r.factorize,
                 r.solve,
                 r.condensation,
                 r.ux_corner,
                 r.cpu_user,
                 r.cpu_system,
                 double(r.minor_faults),
                 double(r.hwm_before),
                 double(r.hwm),
                 double(r.rss_increment())});
        std::printf(
            "| %d | %d x %d | %d | %s%s | %d | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.1f | "
            "%.1f |\n",
            order, nx, ny, r.dofs, path.c_str(), r.completed ? "" : " (STOPPED)", r.newton_iterations, r.factorizations,
            r.wall, r.cpu_user + r.cpu_system, r.assembly, r.factorize, r.solve, r.condensation, r.other(),
            r.hwm / 1024.0, r.rss_increment() / 1024.0);
        std::fflush(stdout);
      }

  std::printf("\n%d steps of %g s (T = %s s); CSV: %s\n\n", steps, shipped.end_time / shipped.steps, end_time,
              csv_path.c_str());
  std::printf("Exponent p of cost ~ dofs^p, least squares on log-log over the completed runs with dofs >= %.0e:\n\n",
              kMinFitDofs);
  std::printf(
      "| order | path | dofs range (runs) | wall | CPU | assembly | factorise | solve | condensation | "
      "RSS increment |\n");
  std::printf("|--:|---|---|--:|--:|--:|--:|--:|--:|--:|\n");
  for (const auto& [key, done] : runs) {
    std::vector<const Run*> fitted;
    for (const auto& [nx, r] : done)
      if (r.completed && r.dofs >= kMinFitDofs) fitted.push_back(&r);
    std::vector<double> dofs;
    for (const Run* r : fitted) dofs.push_back(r->dofs);
    auto exponent = [&](auto cost) {
      std::vector<double> y;
      for (const Run* r : fitted) y.push_back(cost(*r));
      return exponent_text(loglog_slope(dofs, y));
    };
    const std::string range =
        dofs.empty() ? "-" : std::to_string(int(dofs.front())) + " .. " + std::to_string(int(dofs.back()));
    std::printf("| %d | %s | %s (%zu) | %s | %s | %s | %s | %s | %s | %s |\n", key.first, kPaths[key.second],
                range.c_str(), dofs.size(), exponent([](const Run& r) { return r.wall; }).c_str(),
                exponent([](const Run& r) { return r.cpu_user + r.cpu_system; }).c_str(),
                exponent([](const Run& r) { return r.assembly; }).c_str(),
                exponent([](const Run& r) { return r.factorize; }).c_str(),
                exponent([](const Run& r) { return r.solve; }).c_str(),
                exponent([](const Run& r) { return r.condensation; }).c_str(),
                exponent([](const Run& r) { return double(r.rss_increment()); }).c_str());
  }
  return failures == 0 ? 0 : 1;
}

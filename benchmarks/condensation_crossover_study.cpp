// Where the dense Schur condensation stops paying and the Krylov path takes over, and what
// solver.condensation = "auto" predicts there: the paper's scene (conductive foundation) on strips
// x in [0, L] of growing length at a fixed thickness of ny cells, so that the contact set grows while
// everything else per contact node stays the same. For contact sets of about 100, 1 000, 10 000 and
// 100 000 dofs (m = 2 nx: the two velocity components of each free contact node), three steps each by
//   schur   dense S_c^-1 on the m contact dofs (skipped where the cost model predicts more than budget_s)
//   krylov  GMRES preconditioned by a kept factorisation of an earlier J
//   full    a factorisation per Newton iteration (solver.condensed = false)
// Each run is a fresh child process (peak memory is per process). "per iteration" is the linear algebra
// of one Newton iteration, (factorise + solve + condensation) / iterations, measured; next to it the
// cost model's prediction (models/solvers/strategy_cost_model.hpp) for the same problem, and auto's choice.
//   build/release/benchmarks/condensation_crossover_study [out.csv = crossover.csv] [max_m = 100000]
//                                                         [budget_s = 300] [ny = 2]
#include <cstdio>
#include <string>
#include <vector>

#include "models/output/csv_log.hpp"
#include "models/scene/scene_runner.hpp"
#include "models/solvers/strategy_cost_model.hpp"
#include "support/child_process.hpp"

namespace {
using namespace pc;

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";
const char* kPaths[] = {"schur", "krylov", "full"};
// The paper's cell size along x (0.03 m / 60 cells), kept as the strip grows.
constexpr double kCellLength = 0.03 / 60;

struct Run {
  int completed = 0, dofs = 0, contact_dofs = 0, newton_iterations = 0, factorizations = 0;
  double wall = 0, factorize = 0, solve = 0, dense = 0, linear_algebra = 0, predicted_full = 0, predicted_schur = 0,
         predicted_krylov = 0, schur_mib = 0;
  long hwm_before = 0, hwm = 0;
  double per_iteration() const { return linear_algebra / std::max(newton_iterations, 1); }
};
const char* kRunFormat = "%d %d %d %d %d %lf %lf %lf %lf %lf %lf %lf %lf %ld %ld";

std::vector<std::string> overrides(int nx, int ny) {
  char x[64];
  const double length = nx * kCellLength;
  std::snprintf(x, sizeof x, "mesh.x=[0,%.10g]", length);
  char probes[160], grid[64];
  std::snprintf(probes, sizeof probes, "output.probes={\"corner\": [%.10g, 0.01], \"center\": [%.10g, 0.005]}", length,
                length / 2);
  std::snprintf(grid, sizeof grid, "output.grid.x=[0,%.10g,31]", length);
  return {x,   "mesh.nx=" + std::to_string(nx), "mesh.ny=" + std::to_string(ny), "time.steps=3", "time.T=0.003", probes,
          grid};
}

// The cost model for this problem: its sizes and the factor size UMFPACK's analysis predicts.
StrategyCosts predict(Model& model) {
  model.assemble(true);
  StrategyCostInputs in;
  in.dofs = double(model.residual().size());
  in.nonlinear_dofs = double(model.nonlinear_dofs().size());
  in.jacobian_nonzeros = double(model.jacobian().nonZeros());
  auto solver = make_linear_solver("umfpack");
  solver->analyze(model.jacobian());
  in.factors = solver->factor_estimate();
  return predict_strategy_costs(in);
}

int run_child(const std::vector<std::string>& args) {
  const Scene scene = load_scene_file(kScene, args);
  const long hwm_before = study::peak_rss_kib();
  FoundationRun run(scene, find_foundation(scene, "conductive"));
  const FoundationRunResult r = run.run("", false);
  const StrategyCosts costs = predict(run.model());
  std::printf("%d %d %d %d %d %.6f %.6f %.6f %.6f %.6f %.6g %.6g %.6g %ld %ld\n", r.completed ? 1 : 0, r.ndof,
              int(run.model().nonlinear_dofs().size()), r.newton_iterations_total, r.factorizations, r.wall_seconds,
              r.factorize_seconds, r.solve_seconds, r.condensation_seconds, costs.full_seconds, costs.schur_seconds,
              costs.krylov_seconds, costs.schur_bytes / 1048576.0, hwm_before, study::peak_rss_kib());
  return r.completed ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--child") return run_child(std::vector<std::string>(argv + 2, argv + argc));
  const std::string csv_path = argc > 1 ? argv[1] : "crossover.csv";
  const int max_m = argc > 2 ? std::stoi(argv[2]) : 100000;
  const double budget = argc > 3 ? std::stod(argv[3]) : 300;
  const int ny = argc > 4 ? std::stoi(argv[4]) : 2;
  CsvLog csv(csv_path, {"nx", "ny", "dofs", "contact_dofs", "path", "completed", "newton_iterations", "factorizations",
                        "wall_s", "linear_algebra_s", "per_iteration_s", "predicted_full_s", "predicted_schur_s",
                        "predicted_krylov_s", "schur_dense_mib", "rss_increment_mib"});
  std::printf(
      "| contact dofs | dofs | path | Newton its | factorisations | wall [s] | factorise / solve / dense [s] | "
      "per iteration [ms] | predicted [ms] | RSS increment [MiB] |\n|--:|--:|---|--:|--:|--:|--:|--:|--:|--:|\n");
  std::fflush(stdout);
  for (int nx = 50; 2 * nx <= max_m; nx *= 10)
    for (int p = 0; p < int(std::size(kPaths)); ++p) {
      const std::string path = kPaths[p];
      std::vector<std::string> args = {"--child"};
      for (const std::string& o : overrides(nx, ny)) args.push_back(o);
      if (path == "full") {
        args.push_back("solver.condensed=false");
      } else {
        args.push_back("solver.condensation=\"" + path + "\"");
        args.push_back("solver.condensed_max_dofs=100000000");  // forced: no cap
      }
      // Schur's dense work grows as m^3: forming S_c^-1 (2 m^3 at 1e10 flop/s) for each of the about 20
      // step sizes a strip's cut-backs visit must fit the budget.
      const double m = 2.0 * nx;
      if (path == "schur" && 20 * 2 * m * m * m / 1e10 > budget) {
        std::printf("| %d | | schur | skipped: predicted over %.0f s | | | | | | |\n", int(m), budget);
        continue;
      }
      const study::ChildOutput child = study::run_child(args);
      Run r;
      if (!child.ran ||
          std::sscanf(child.line.c_str(), kRunFormat, &r.completed, &r.dofs, &r.contact_dofs, &r.newton_iterations,
                      &r.factorizations, &r.wall, &r.factorize, &r.solve, &r.dense, &r.predicted_full,
                      &r.predicted_schur, &r.predicted_krylov, &r.schur_mib, &r.hwm_before, &r.hwm) != 15) {
        std::printf("| %d | | %s | FAILED: the child exited with status %d | | | | | | |\n", int(m), path.c_str(),
                    child.status);
        continue;
      }
      r.linear_algebra = r.factorize + r.solve + r.dense;
      const double predicted = p == 0 ? r.predicted_schur : p == 1 ? r.predicted_krylov : r.predicted_full;
      std::printf("| %d | %d | %s%s | %d | %d | %.2f | %.2f / %.2f / %.2f | %.3f | %.3f | %.0f |\n", r.contact_dofs,
                  r.dofs, path.c_str(), r.completed ? "" : " (STOPPED)", r.newton_iterations, r.factorizations, r.wall,
                  r.factorize, r.solve, r.dense, 1e3 * r.per_iteration(), 1e3 * predicted,
                  (r.hwm - r.hwm_before) / 1024.0);
      std::fflush(stdout);
      csv.row({double(nx), double(ny), double(r.dofs), double(r.contact_dofs), double(p), double(r.completed),
               double(r.newton_iterations), double(r.factorizations), r.wall, r.linear_algebra, r.per_iteration(),
               r.predicted_full, r.predicted_schur, r.predicted_krylov, r.schur_mib, (r.hwm - r.hwm_before) / 1024.0});
    }
  return 0;
}

// The fast path against the plain one on the paper's scene (conductive foundation, the harder case):
// for meshes from 30 x 10 to 480 x 160, the same run with a factorisation per Newton iteration (plain),
// and with the condensed Newton solve (linear part factorised once per step size, contact dofs through a
// small dense system) by its two methods: MUMPS's Schur complement (schur, the default) and Woodbury
// columns by solves (columns). "iteration [solves]" is the cost of a Newton iteration outside
// factorisations, (wall - factorise) / iterations, in units of one solve with an existing factorisation
// (the plain path's solve time per iteration on the same mesh). Prints a markdown table and writes CSV as
// it goes ("path": 0 plain, 1 columns, 2 schur).
//   build/release/benchmarks/fast_path_study [steps=20] [max_nx=480] [out=fast_path.csv]
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "models/output/csv_log.hpp"
#include "models/scene/scene_runner.hpp"

using namespace pc;

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 20;
  const int max_nx = argc > 2 ? std::atoi(argv[2]) : 480;
  const std::string out = argc > 3 ? argv[3] : "fast_path.csv";
  CsvLog csv(out, {"nx", "ny", "ndof", "path", "newton_iterations", "factorizations", "wall_s", "assembly_s",
                   "factorize_s", "solve_s", "condensation_s", "ux_corner", "iteration_in_solves"});
  std::printf(
      "| mesh | dofs | path | Newton its | factorisations | wall [s] | assembly | factorise | solve | condensation | "
      "iteration [solves] | speed-up |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int nx = 30; nx <= max_nx; nx *= 2) {
    double plain_wall = 0, one_solve = 0;
    const std::vector<std::string> paths = {"plain", "columns", "schur", "krylov"};
    for (size_t p = 0; p < paths.size(); ++p) {
      const std::string& path = paths[p];
      const bool condensed = path != "plain";
      const Scene scene =
          load_scene_file(std::string(PIEZOCONTACT_SOURCE_DIR) + "/scenes/paper2d.json",
                          {"mesh.nx=" + std::to_string(nx), "mesh.ny=" + std::to_string(nx / 3),
                           "time.steps=" + std::to_string(steps), "time.T=" + std::to_string(0.2 * steps / 200.0),
                           std::string("solver.condensed=") + (condensed ? "true" : "false"),
                           "solver.condensation=\"" + (condensed ? path : "schur") + "\""});
      const FoundationRunResult r = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
      if (!condensed) {
        plain_wall = r.wall_seconds;
        one_solve = r.solve_seconds / r.newton_iterations_total;
      }
      const double iteration_in_solves = (r.wall_seconds - r.factorize_seconds) / r.newton_iterations_total / one_solve;
      std::printf("| %d x %d | %d | %s | %d | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %.1f | %.2f |\n", nx, nx / 3,
                  r.ndof, path.c_str(), r.newton_iterations_total, r.factorizations, r.wall_seconds, r.assembly_seconds,
                  r.factorize_seconds, r.solve_seconds, r.condensation_seconds, iteration_in_solves,
                  plain_wall / r.wall_seconds);
      std::fflush(stdout);
      csv.row({double(nx), double(nx / 3), double(r.ndof), double(p), double(r.newton_iterations_total),
               double(r.factorizations), r.wall_seconds, r.assembly_seconds, r.factorize_seconds, r.solve_seconds,
               r.condensation_seconds, r.ux_corner, iteration_in_solves});
    }
  }
  return 0;
}

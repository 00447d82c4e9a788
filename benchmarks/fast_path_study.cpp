// The fast path against the plain one on the paper's scene (conductive foundation, the harder case):
// for meshes from 30 x 10 to 480 x 160, the same run with the condensed Newton solve (linear part
// factorised once per step size, contact dofs through a small dense system) and with a factorisation
// per Newton iteration. Prints a markdown table and writes CSV as it goes.
//   build/release/benchmarks/fast_path_study [steps=20] [max_nx=480] [out=fast_path.csv]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "models/csv_log.hpp"
#include "models/scene_runner.hpp"

using namespace pc;

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 20;
  const int max_nx = argc > 2 ? std::atoi(argv[2]) : 480;
  const std::string out = argc > 3 ? argv[3] : "fast_path.csv";
  CsvLog csv(out, {"nx", "ny", "ndof", "condensed", "newton_iterations", "factorizations", "wall_s", "assembly_s",
                   "factorize_s", "solve_s", "condensation_s", "ux_corner"});
  std::printf("| mesh | dofs | path | Newton its | factorisations | wall [s] | assembly | factorise | solve | condensation | speed-up |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int nx = 30; nx <= max_nx; nx *= 2) {
    double plain_wall = 0;
    for (const bool condensed : {false, true}) {
      const Scene scene = load_scene_file(std::string(PIEZOCONTACT_SOURCE_DIR) + "/scenes/paper2d.json",
                                          {"mesh.nx=" + std::to_string(nx), "mesh.ny=" + std::to_string(nx / 3),
                                           "time.steps=" + std::to_string(steps),
                                           "time.T=" + std::to_string(0.2 * steps / 200.0),
                                           std::string("solver.condensed=") + (condensed ? "true" : "false")});
      const FoundationRunResult r = run_foundation(scene, find_foundation(scene, "conductive"), "", false);
      if (!condensed) plain_wall = r.wall_seconds;
      std::printf("| %d x %d | %d | %s | %d | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %s |\n", nx, nx / 3, r.ndof,
                  condensed ? "condensed" : "plain", r.newton_iterations_total, r.factorizations, r.wall_seconds,
                  r.assembly_seconds, r.factorize_seconds, r.solve_seconds, r.condensation_seconds,
                  condensed ? std::to_string(plain_wall / r.wall_seconds).substr(0, 4).c_str() : "1");
      std::fflush(stdout);
      csv.row({double(nx), double(nx / 3), double(r.ndof), condensed ? 1.0 : 0.0, double(r.newton_iterations_total),
               double(r.factorizations), r.wall_seconds, r.assembly_seconds, r.factorize_seconds, r.solve_seconds,
               r.condensation_seconds, r.ux_corner});
    }
  }
  return 0;
}

// Numerical stability at the extremes, on the paper's scene as shipped (60 x 20 triangles, 200 steps) in
// P1 and P2: every case of tests/support/extreme_cases.hpp (the test runs the same cases on a coarse
// mesh), one row each: outcome, Newton iterations, wall time, key numbers of the run, and the penetration
// max(-u_y) over the contact nodes. A study, not a Google Benchmark. Run:
//   build/release/benchmarks/extremes_study [extremes.csv] [key=value ...] [case ...]
// The table goes to stdout and, row by row as the cases finish, to the CSV file; extra key=value
// arguments are applied to every case before its own (e.g. mesh.nx=12 mesh.ny=4 time.steps=10); case
// names, if any, select the cases to run.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "../tests/support/extreme_cases.hpp"
#include "models/scene/scene_runner.hpp"

namespace {

namespace fs = std::filesystem;

std::string csv_text(std::string s) {
  for (char& c : s)
    if (c == '"' || c == '\n') c = '\'';
  return "\"" + s + "\"";
}

// max(-u_y) over the contact nodes, from the run's gamma_c.csv (columns x, ux, uy, ...).
double penetration(const fs::path& gamma_c) {
  std::ifstream in(gamma_c);
  std::string line;
  std::getline(in, line);
  double worst = -INFINITY;
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string x, ux, uy;
    std::getline(fields, x, ',');
    std::getline(fields, ux, ',');
    std::getline(fields, uy, ',');
    worst = std::max(worst, -std::strtod(uy.c_str(), nullptr));
  }
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string csv_path = argc > 1 ? argv[1] : "extremes.csv";
  std::vector<std::string> extra, only;
  for (int i = 2; i < argc; ++i)
    (std::string(argv[i]).find('=') == std::string::npos ? only : extra).push_back(argv[i]);
  const std::string scene_path = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";
  const fs::path scratch = fs::temp_directory_path() / ("extremes_study_" + std::to_string(getpid()));

  std::ofstream csv(csv_path);
  csv << "case,order,foundation,outcome,steps,ndof,newton_total,newton_max,wall_s,max_abs_ux,max_abs_uy,"
         "penetration,phi_min,phi_max,ux_corner,uy_corner,phi_center,n_contact_nodes,n_slip_nodes,message\n";
  std::printf("%-26s %2s %-10s %-9s %5s %6s %7s %4s %8s %11s %11s %11s %11s  %s\n", "case", "p", "foundation",
              "outcome", "steps", "ndof", "newton", "max", "wall_s", "max|uy|", "penetration", "phi_min", "phi_max",
              "message");
  int failures = 0;
  for (const int order : {1, 2}) {
    for (const pc::testing::ExtremeCase& c : pc::testing::extreme_cases()) {
      std::vector<std::string> overrides = extra;
      overrides.push_back("mesh.order=" + std::to_string(order));
      overrides.push_back("output.vtu_every=1000000");  // the tables and the first and last VTU only
      overrides.insert(overrides.end(), c.overrides.begin(), c.overrides.end());
      pc::FoundationRunResult r;
      std::string outcome;
      double pen = NAN;
      if (order == 2 && std::find(c.overrides.begin(), c.overrides.end(), "mesh.order=2") != c.overrides.end())
        continue;  // a P2 case: run in the first pass already
      if (!only.empty() && std::find(only.begin(), only.end(), c.name) == only.end()) continue;
      int scene_order = order;
      try {
        const pc::Scene scene = pc::load_scene_file(scene_path, overrides);
        scene_order = scene.spec.order;
        const fs::path dir = scratch / (c.name + "_p" + std::to_string(order));
        r = pc::run_foundation(scene, pc::find_foundation(scene, c.foundation), dir.string(), false);
        pen = penetration(dir / "gamma_c.csv");
        const bool finite = std::isfinite(r.max_abs_ux) && std::isfinite(r.max_abs_uy) && std::isfinite(r.phi_min) &&
                            std::isfinite(r.phi_max) && std::isfinite(r.ux_corner) && std::isfinite(r.uy_corner) &&
                            std::isfinite(r.phi_center) && std::isfinite(r.max_abs_vtau_contact) && std::isfinite(pen);
        outcome = !finite ? "NOT_FINITE" : r.completed ? "completed" : "stopped";
      } catch (const std::exception& e) {
        outcome = "exception";
        r.message = e.what();
      }
      failures += outcome != "completed";
      std::printf("%-26s %2d %-10s %-9s %5d %6d %7d %4d %8.2f %11.4g %11.4g %11.4g %11.4g  %s\n", c.name.c_str(),
                  scene_order, c.foundation.c_str(), outcome.c_str(), r.steps, r.ndof, r.newton_iterations_total,
                  r.newton_iterations_max_per_step, r.wall_seconds, r.max_abs_uy, pen, r.phi_min, r.phi_max,
                  r.message.c_str());
      std::fflush(stdout);
      char numbers[512];
      std::snprintf(numbers, sizeof numbers, "%d,%d,%d,%d,%.6g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d",
                    r.steps, r.ndof, r.newton_iterations_total, r.newton_iterations_max_per_step, r.wall_seconds,
                    r.max_abs_ux, r.max_abs_uy, pen, r.phi_min, r.phi_max, r.ux_corner, r.uy_corner, r.phi_center,
                    r.n_contact_nodes, r.n_slip_nodes);
      csv << c.name << "," << scene_order << "," << c.foundation << "," << outcome << "," << numbers << ","
          << csv_text(r.message) << "\n"
          << std::flush;
    }
  }
  fs::remove_all(scratch);
  std::printf("%d case(s) did not complete with finite results; table in %s\n", failures, csv_path.c_str());
  return failures == 0 ? 0 : 1;
}

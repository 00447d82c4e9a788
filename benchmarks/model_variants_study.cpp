// What modelling only what a scene requires saves: the paper's scene run as four variants of its physics,
//   a_mechanical   no E, no beta: viscoelastic contact without electric field
//   b_insulated    piezoelectric, insulated foundation (the paper's first run)
//   c_conductive   piezoelectric, conductive foundation (the paper's second run)
//   d_quasistatic  as b_insulated with rho = 0
// measuring dofs, bricks, peak resident memory, wall time split into assembly / factorisation / solve
// (summed over the Newton solves of the accepted steps and of the initial potential) and Newton iterations.
// VmHWM is a process-wide high-water mark, so every variant runs in a fresh child process (this program,
// re-executed with --child); "rss_model" is VmHWM at the end minus VmHWM before the model was built (after
// reading the scene and building the mesh). Prints a markdown table and writes a CSV.
//   model_variants_study [out.csv = model_variants.csv] [steps = 200] [meshes = 60x20,120x40]
// The time span is the scene's (T = 0.2 s): fewer steps mean larger ones.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "models/piezo/initial_potential.hpp"
#include "models/scene/scene.hpp"
#include "support/child_process.hpp"
#include "support/stopwatch.hpp"

namespace {

using namespace pc;
using study::Clock;
using study::seconds_since;
const char* kVariants[] = {"a_mechanical", "b_insulated", "c_conductive", "d_quasistatic"};
const std::string kScene =
    (std::filesystem::path(__FILE__).parent_path().parent_path() / "scenes/paper2d.json").string();

PiezoContactSpec variant_spec(const Scene& scene, const std::string& variant) {
  PiezoContactSpec spec = scene.spec;
  spec.foundation = find_foundation(scene, variant == "c_conductive" ? "conductive" : "insulated").law;
  if (variant == "a_mechanical") {
    spec.E.resize(0, 0);
    spec.beta.resize(0, 0);
  }
  if (variant == "d_quasistatic") spec.rho = 0;
  return spec;
}

// One variant on one mesh; prints its numbers on one line for the parent.
int run_child(const std::string& variant, int nx, int ny, int steps) {
  const Scene scene = load_scene_file(kScene, {"mesh.nx=" + std::to_string(nx), "mesh.ny=" + std::to_string(ny)});
  const long hwm_before = study::peak_rss_kib();
  const auto start = Clock::now();
  PiezoContactModel built = build_piezo_contact_model(variant_spec(scene, variant));
  Model& m = *built.model;
  int dofs = 0;
  for (const std::string& u : m.unknowns()) dofs += m.space(u).num_dofs();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(m.space("v").num_dofs());  // the scene's u0 = v0 = 0
  built.scheme->set_initial_state(m, zero, zero);
  const double build_seconds = seconds_since(start);

  StepperOptions options;
  options.end = scene.end_time;
  options.step = scene.end_time / steps;
  options.cutback_factor = scene.cutback_factor;
  options.prediction = scene.prediction;
  options.output_every = steps + 1;
  NewtonSolver newton(scene.newton);
  double assembly = 0, factorize = 0, solve = 0, condensation = 0;
  auto add = [&](const NewtonReport& r) {
    assembly += r.assembly_seconds;
    factorize += r.analyze_seconds + r.factorize_seconds;
    solve += r.solve_seconds;
    condensation += r.condensation_seconds;
  };
  StepperCallbacks callbacks;
  callbacks.on_start = [&](Model& model) { return solve_initial_potential(model, *built.scheme, newton); };
  callbacks.on_step = [&](const Model&, const StepRecord& r) { add(r.newton); };
  callbacks.on_output = [&](const Model&, const StepRecord& r) {
    if (r.step == 0) add(r.newton);  // the initial potential's solve (empty without a potential)
  };
  const auto run_start = Clock::now();
  const RunSummary run = Stepper(options).run(m, *built.scheme, newton, callbacks);
  const double run_seconds = seconds_since(run_start);
  std::printf("%d %d %zu %d %d %d %d %.6f %.6f %.6f %.6f %.6f %.6f %ld %ld\n", run.completed ? 1 : 0, dofs,
              m.bricks().size(), m.layout().size(), run.steps, run.newton_iterations_total, run.cutbacks, build_seconds,
              run_seconds, assembly, factorize, solve, condensation, hwm_before, study::peak_rss_kib());
  return run.completed ? 0 : 1;
}

struct Row {
  std::string variant, mesh, line;  // line: the child's numbers
};

}  // namespace

int main(int argc, char** argv) {
  if (argc == 6 && std::string(argv[1]) == "--child")
    return run_child(argv[2], std::stoi(argv[3]), std::stoi(argv[4]), std::stoi(argv[5]));
  const std::string csv_path = argc > 1 ? argv[1] : "model_variants.csv";
  const int steps = argc > 2 ? std::stoi(argv[2]) : 200;
  std::vector<std::pair<int, int>> meshes;
  std::stringstream list(argc > 3 ? argv[3] : "60x20,120x40");
  for (std::string item; std::getline(list, item, ',');)
    meshes.emplace_back(std::stoi(item), std::stoi(item.substr(item.find('x') + 1)));

  std::ofstream csv(csv_path);
  csv << "variant,mesh,completed,dofs,bricks,free_dofs,steps,newton_iterations,cutbacks,build_s,run_s,assembly_s,"
         "factorize_s,solve_s,condensation_s,vmhwm_before_model_kib,vmhwm_kib\n";
  std::printf(
      "| variant | mesh | dofs | bricks | Newton its | cutbacks | run [s] | assembly [s] | factorize [s] | "
      "solve [s] | condense [s] | peak RSS [MiB] | RSS model+run [MiB] |\n");
  std::printf("|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
  int failures = 0;
  for (const auto& [nx, ny] : meshes) {
    const std::string mesh = std::to_string(nx) + "x" + std::to_string(ny);
    for (const char* variant : kVariants) {
      const study::ChildOutput child =
          study::run_child({"--child", variant, std::to_string(nx), std::to_string(ny), std::to_string(steps)});
      int completed = 0, dofs = 0, bricks = 0, free_dofs = 0, done = 0, iterations = 0, cutbacks = 0;
      double build = 0, run = 0, assembly = 0, factorize = 0, solve = 0, condensation = 0;
      long hwm_before = 0, hwm = 0;
      if (!child.ran || std::sscanf(child.line.c_str(), "%d %d %d %d %d %d %d %lf %lf %lf %lf %lf %lf %ld %ld",
                                    &completed, &dofs, &bricks, &free_dofs, &done, &iterations, &cutbacks, &build, &run,
                                    &assembly, &factorize, &solve, &condensation, &hwm_before, &hwm) != 15) {
        std::fprintf(stderr, "%s on %s: the child failed (status %d)\n", variant, mesh.c_str(), child.status);
        ++failures;
        continue;
      }
      failures += child.status != 0;
      std::string line = child.line;
      for (char& c : line) c = c == ' ' ? ',' : c;
      csv << variant << "," << mesh << "," << line << "\n";
      std::printf("| %s%s | %s | %d | %d | %d | %d | %.3f | %.3f | %.3f | %.3f | %.3f | %.1f | %.1f |\n", variant,
                  completed ? "" : " (STOPPED)", mesh.c_str(), dofs, bricks, iterations, cutbacks, run, assembly,
                  factorize, solve, condensation, hwm / 1024.0, (hwm - hwm_before) / 1024.0);
      std::fflush(stdout);
    }
  }
  std::printf("\n%d steps over the scene's T; CSV: %s\n", steps, csv_path.c_str());
  return failures == 0 ? 0 : 1;
}

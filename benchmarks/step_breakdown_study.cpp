// Where the time of a run goes, phase by phase, on the paper's scene (scenes/paper2d.json, conductive
// foundation, the scene's step of 1 ms): each mesh is run as `piezocontact run` runs it, results written
// into a temporary folder (removed afterwards), and FoundationRunResult's measured phases are printed
// (models/scene/run_timing.hpp): assembly of the residual and of the Jacobian, sparse solves,
// factorisations (symbolic analyses included), condensation (the dense interface systems), output (history
// rows, VTU series, checkpoints, final tables) and other (the wall time outside them).
// Besides, in units of one solve with existing factors -- a forward and a backward substitution with the
// factorisation the run's condensed Newton uses (assembly/schur_complement.hpp: reduce then expand, of the
// final linear part; the median of kSolveRepeats), each after an assembly of the model (untimed), so that the
// caches hold what they hold in a Newton iteration (back to back, the factors of 120 x 40, about 20 MB, stay
// in a 32 MB L3 and a solve takes half the time or less; both are printed, the first is the unit) --
//   "Newton iteration": Newton's work outside factorisations, (assembly + solve + condensation) / iterations
//                       (each step's first residual and the initial potential's solve included);
//   "step of one Newton iteration": the median wall time of the steps that took one iteration and no
//                       cut-back, measured from one accepted step to the next (the previous step's VTU output
//                       falls in one step of ten, so the median leaves it out), step 1 aside (it follows
//                       the initial potential).
// On a shared machine the run's phases include the time the process waits for a core (a step's solve then
// takes 4 ms longer now and then at 120 x 40), which the median of the timed solves leaves out: the two
// ratios are then too large by the load's share. And where the machine's speed drifts between the run and
// the timed solves after it, both ratios move with the drift (1.4 to 2.4 for the step at 120 x 40 in three
// runs of one hour). Hence the same two in units of the run's own solve pair, timed in place:
//   "[own solves]":     the unit is the median solve phase of the steps of one iteration (on the Schur path
//                       exactly one reduction and one expansion); the step's ratio is the median over those
//                       steps of each one's wall time over its own solve phase (1.54 to 1.61 in those runs).
//   "solve phase per step [solves]": the solve phase over the steps, in that unit (1: one solve pair per
//                       step, as Newton on the contact dofs makes; the time estimate's solve adds one).
// Prints a markdown table and writes a CSV row per mesh. Further arguments are scene overrides, as --set
// takes them (time.error_estimate=none: without the time estimate, as the GetFEM runs).
//   build/release/benchmarks/step_breakdown_study [steps=200] [sizes=120x40,240x80] [out=step_breakdown.csv]
//                                                 [key=value ...]
// Run it with `nice` on a shared machine; timings are of one run each.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "assembly/schur_complement.hpp"
#include "models/output/csv_log.hpp"
#include "models/scene/run_timing.hpp"
#include "models/scene/scene_runner.hpp"
#include "support/stopwatch.hpp"

using namespace pc;
using study::Clock;
using study::median;
using study::seconds_since;

namespace {

constexpr int kSolveRepeats = 21;

// "120x40,240x80" -> {{120, 40}, {240, 80}}
std::vector<std::pair<int, int>> parse_sizes(const std::string& text) {
  std::vector<std::pair<int, int>> sizes;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    const size_t x = item.find('x');
    if (x == std::string::npos) continue;
    sizes.emplace_back(std::atoi(item.substr(0, x).c_str()), std::atoi(item.substr(x + 1).c_str()));
  }
  return sizes;
}

struct SolveTimes {
  double in_iteration = 0, back_to_back = 0;  // after an assembly of the model each, or one after the other
};

// One forward and backward substitution with the factorisation of the model's linear part condensed on its
// nonlinear dofs, as the run's Newton iterations do it (medians of kSolveRepeats, after one warm-up).
SolveTimes one_solve_seconds(Model& model) {
  const CsrMatrix& A = model.linear_jacobian();
  SchurComplement schur;
  schur.analyze(A, model.nonlinear_dofs());
  schur.factorize(A);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
  double checksum = 0;  // uses the solutions, so that no solve can be left out
  auto timed = [&](bool assemble) {
    std::vector<double> times;
    for (int k = 0; k <= kSolveRepeats; ++k) {
      if (assemble) model.assemble(true);  // the state does not change: the same residual and Jacobian
      const auto t = Clock::now();
      const Eigen::VectorXd reduced = schur.reduce(b);
      checksum += schur.expand(b, Eigen::VectorXd::Zero(reduced.size())).sum();
      if (k > 0) times.push_back(seconds_since(t));
    }
    return median(times);
  };
  SolveTimes t;
  t.in_iteration = timed(true);
  t.back_to_back = timed(false);
  if (!std::isfinite(checksum)) std::fprintf(stderr, "warning: the timed solves gave non-finite values\n");
  return t;
}

struct Breakdown {
  int nx = 0, ny = 0;
  FoundationRunResult result;
  std::vector<RunPhase> phases;
  SolveTimes one_solve;
  double iteration_in_solves = 0, one_iteration_step = 0;
  int one_iteration_steps = 0;
  // The same two ratios in units of the run's own solve pairs: the median solve phase of the steps of one
  // iteration (one reduction and one expansion each), and the median over those steps of each one's wall
  // time over its own solve phase. Both sides are timed in the same few milliseconds, so that a machine
  // whose speed drifts between the run and the timed solves above moves neither.
  double own_solve = 0, iteration_in_own_solves = 0, one_iteration_step_in_own_solves = 0;
};

Breakdown run_mesh(int nx, int ny, int steps, const std::vector<std::string>& extra_overrides) {
  std::vector<std::string> overrides = {"mesh.nx=" + std::to_string(nx), "mesh.ny=" + std::to_string(ny),
                                        "time.steps=" + std::to_string(steps),
                                        "time.T=" + std::to_string(0.2 * steps / 200.0)};
  overrides.insert(overrides.end(), extra_overrides.begin(), extra_overrides.end());
  const Scene scene = load_scene_file(std::string(PIEZOCONTACT_SCENES) + "/paper2d.json", overrides);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("step_breakdown_" + std::to_string(nx) + "x" + std::to_string(ny));
  std::filesystem::remove_all(dir);
  FoundationRun run(scene, find_foundation(scene, "conductive"));
  FoundationRunOptions options;
  options.directory = dir.string();
  options.progress = false;
  std::vector<double> one_iteration_steps, their_solves, their_ratios;
  auto last = Clock::now();
  options.after_step = [&](const StepRecord& r) {
    const double seconds = seconds_since(last);
    last = Clock::now();
    if (r.step > 1 && r.newton.iterations == 1 && r.cutbacks == 0) {
      one_iteration_steps.push_back(seconds);
      their_solves.push_back(r.newton.solve_seconds);
      if (r.newton.solve_seconds > 0) their_ratios.push_back(seconds / r.newton.solve_seconds);
    }
  };
  Breakdown b;
  b.nx = nx;
  b.ny = ny;
  b.result = run.run(options);
  std::filesystem::remove_all(dir);
  b.phases = run_phases(b.result);
  b.one_solve = one_solve_seconds(run.model());
  const FoundationRunResult& r = b.result;
  const double newton_work = r.assembly_seconds + r.solve_seconds + r.condensation_seconds;
  b.iteration_in_solves = newton_work / r.newton_iterations_total / b.one_solve.in_iteration;
  b.one_iteration_step = median(one_iteration_steps) / b.one_solve.in_iteration;
  b.one_iteration_steps = int(one_iteration_steps.size());
  if (!their_ratios.empty()) {
    b.own_solve = median(their_solves);
    b.iteration_in_own_solves = newton_work / r.newton_iterations_total / b.own_solve;
    b.one_iteration_step_in_own_solves = median(their_ratios);
  }
  return b;
}

}  // namespace

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 200;
  const auto sizes = parse_sizes(argc > 2 ? argv[2] : "120x40,240x80");
  const std::string out = argc > 3 ? argv[3] : "step_breakdown.csv";
  const std::vector<std::string> overrides(argv + std::min(argc, 4), argv + argc);
  std::vector<Breakdown> runs;
  for (const auto& [nx, ny] : sizes) {
    runs.push_back(run_mesh(nx, ny, steps, overrides));
    const Breakdown& b = runs.back();
    std::fprintf(stderr, "%d x %d: %d dofs, %s in %.2f s\n", nx, ny, b.result.ndof,
                 b.result.completed ? "completed" : "STOPPED", b.result.wall_seconds);
  }
  if (runs.empty()) return 1;

  std::vector<std::string> columns = {"nx", "ny", "ndof", "steps", "newton_iterations", "factorizations", "wall_s"};
  for (const RunPhase& p : runs.front().phases) columns.push_back(p.name + "_s");
  for (const char* c : {"one_solve_s", "one_solve_back_to_back_s", "solve_per_iteration_s", "iteration_in_solves",
                        "one_iteration_step_in_solves", "one_iteration_steps", "own_solve_s", "iteration_in_own_solves",
                        "one_iteration_step_in_own_solves"})
    columns.push_back(c);
  CsvLog csv(out, columns);

  std::printf("| phase |");
  for (const Breakdown& b : runs) std::printf(" %d x %d (%d dofs) |", b.nx, b.ny, b.result.ndof);
  std::printf("\n|---|");
  for (size_t i = 0; i < runs.size(); ++i) std::printf("---|");
  std::printf("\n");
  for (size_t p = 0; p < runs.front().phases.size(); ++p) {
    std::printf("| %s |", runs.front().phases[p].name.c_str());
    for (const Breakdown& b : runs)
      std::printf(" %.2f s (%.1f %%) |", b.phases[p].seconds, 100 * b.phases[p].seconds / b.result.wall_seconds);
    std::printf("\n");
  }
  auto row = [&](const char* name, auto&& value) {
    std::printf("| %s |", name);
    for (const Breakdown& b : runs) std::printf(" %s |", value(b).c_str());
    std::printf("\n");
  };
  auto text = [](const char* format, auto... values) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, format, values...);
    return std::string(buffer);
  };
  row("wall", [&](const Breakdown& b) { return text("%.2f s", b.result.wall_seconds); });
  row("steps / Newton iterations / factorisations", [&](const Breakdown& b) {
    return text("%d / %d / %d", b.result.steps, b.result.newton_iterations_total, b.result.factorizations);
  });
  row("one solve with existing factors (back to back)", [&](const Breakdown& b) {
    return text("%.2f ms (%.2f ms)", 1e3 * b.one_solve.in_iteration, 1e3 * b.one_solve.back_to_back);
  });
  row("solve phase per Newton iteration", [&](const Breakdown& b) {
    return text("%.2f ms", 1e3 * b.result.solve_seconds / b.result.newton_iterations_total);
  });
  row("solve phase per step [solves]", [&](const Breakdown& b) {
    return text("%.2f", b.result.solve_seconds / b.result.steps / b.one_solve.in_iteration);
  });
  row("Newton iteration [solves]", [&](const Breakdown& b) { return text("%.2f", b.iteration_in_solves); });
  row("step of one Newton iteration [solves]",
      [&](const Breakdown& b) { return text("%.2f (median of %d)", b.one_iteration_step, b.one_iteration_steps); });
  row("the run's own solve pair (median over those steps)",
      [&](const Breakdown& b) { return text("%.2f ms", 1e3 * b.own_solve); });
  row("Newton iteration [own solves]", [&](const Breakdown& b) { return text("%.2f", b.iteration_in_own_solves); });
  row("step of one Newton iteration [own solves]",
      [&](const Breakdown& b) { return text("%.2f", b.one_iteration_step_in_own_solves); });

  for (const Breakdown& b : runs) {
    const FoundationRunResult& r = b.result;
    std::vector<double> values = {double(b.nx),
                                  double(b.ny),
                                  double(r.ndof),
                                  double(r.steps),
                                  double(r.newton_iterations_total),
                                  double(r.factorizations),
                                  r.wall_seconds};
    for (const RunPhase& p : b.phases) values.push_back(p.seconds);
    for (double v : {b.one_solve.in_iteration, b.one_solve.back_to_back, r.solve_seconds / r.newton_iterations_total,
                     b.iteration_in_solves, b.one_iteration_step, double(b.one_iteration_steps), b.own_solve,
                     b.iteration_in_own_solves, b.one_iteration_step_in_own_solves})
      values.push_back(v);
    csv.row(values);
  }
  return 0;
}

// Error against dofs on the paper's scene (scenes/paper2d.json, conductive foundation) for uniform and
// adaptive refinement, and how well the spatial estimate (models/space_error_estimate.hpp) tracks it.
//   uniform    the generated meshes nx x nx/3, nx = 15, 30, 60, 120
//   adaptive   from 15 x 5: run, estimate, mark by Dörfler (fraction 0.5 of the squared indicator), bisect
//              the marked cells (newest-vertex bisection, assembly/mesh_bisection.hpp), run again on the
//              new mesh, until it has as many dofs as the finest uniform mesh
// Every run has the same 40 steps over the scene's T (time.error_estimate none): the time error is the
// same in all of them, and what differs is the spatial one. Per run: cells, dofs, wall time, and for
// u, v, phi the true error of the final state against a reference run on 240 x 80 cells (in each field's
// energy norm, relative to the reference's norm: models/space_error_estimate.hpp's
// energy_norm_difference) with the estimate beside it, and `error`, the largest of the three. Cells are
// marked by SpaceErrorEstimate::relative_cell_indicators. The reference's own error (about half the
// 120 x 40 run's) is the floor below which the study cannot tell errors apart.
//
// Rows go to OUT/adaptive_mesh.csv and as a markdown table to stdout. Run (nice: the machine is shared):
//   nice build/release/benchmarks/adaptive_mesh_study OUT [--reference-nx N] [--steps N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "assembly/mesh_bisection.hpp"
#include "assembly/point_locator.hpp"
#include "models/piezo/piezo_space_error.hpp"
#include "models/scene/scene.hpp"
#include "models/scene/scene_runner.hpp"

namespace {

using namespace pc;

const char* const kFields[] = {"u", "v", "phi"};

struct Run {
  std::unique_ptr<Scene> scene;
  std::unique_ptr<FoundationRun> run;
  FoundationRunResult result;
  double seconds = 0;
};

std::unique_ptr<Run> run_on(const std::string& scene_file, int nx, int steps,
                            std::shared_ptr<const Mesh> mesh = nullptr) {
  auto r = std::make_unique<Run>();
  r->scene = std::make_unique<Scene>(
      load_scene_file(scene_file, {"mesh.nx=" + std::to_string(nx), "mesh.ny=" + std::to_string(nx / 3),
                                   "time.steps=" + std::to_string(steps), "time.error_estimate=none"}));
  if (mesh) r->scene->spec.mesh = std::move(mesh);
  r->run = std::make_unique<FoundationRun>(*r->scene, find_foundation(*r->scene, "conductive"));
  const auto start = std::chrono::steady_clock::now();
  r->result = r->run->run("", false);
  r->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!r->result.completed) {
    std::fprintf(stderr, "the run on %d cells did not complete: %s\n", r->run->model().mesh().num_cells(),
                 r->result.message.c_str());
    std::exit(1);
  }
  return r;
}

GradientMeasure measure_of(const std::string& field) {
  return field == "phi" ? GradientMeasure::Gradient : GradientMeasure::Strain;
}
const char* weight_of(const std::string& field) { return field == "u" ? "B" : field == "v" ? "A" : "beta"; }

struct Row {
  std::string kind;
  int cells = 0, dofs = 0;
  double seconds = 0;
  double error[3] = {}, estimate[3] = {};
  double largest_error() const { return *std::max_element(error, error + 3); }
};

Row measure(const std::string& kind, const Run& run, const Model& reference) {
  Row row;
  row.kind = kind;
  const Model& m = run.run->model();
  row.cells = m.mesh().num_cells();
  row.dofs = run.result.ndof;
  row.seconds = run.seconds;
  const PointLocator locator(m.mesh());
  const SpaceErrorEstimate estimate = piezo_space_error(m);
  for (int f = 0; f < 3; ++f) {
    const std::string field = kFields[f];
    const auto coarse_gradient = [&](const double* x, double* out) {
      const std::vector<double> g = gradient_at(m.space(field), m.values(field), locator, x);
      std::copy(g.begin(), g.end(), out);
    };
    const Eigen::MatrixXd& W = reference.constant(weight_of(field));
    const int width = reference.space(field).num_components() * reference.mesh().dim();
    const double norm = energy_norm_difference(
        reference.space(field), reference.values(field),
        [&](const double*, double* out) { std::fill(out, out + width, 0.0); }, measure_of(field), W);
    row.error[f] =
        energy_norm_difference(reference.space(field), reference.values(field), coarse_gradient, measure_of(field), W) /
        norm;
    row.estimate[f] = estimate.field(field)->relative();
  }
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s OUT [--reference-nx N] [--steps N]\n", argv[0]);
    return 2;
  }
  const std::filesystem::path out = argv[1];
  int reference_nx = 240, steps = 40;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--reference-nx")
      reference_nx = std::atoi(argv[i + 1]);
    else if (flag == "--steps")
      steps = std::atoi(argv[i + 1]);
    else {
      std::fprintf(stderr, "unknown option '%s'\n", flag.c_str());
      return 2;
    }
  }
  std::filesystem::create_directories(out);
  const std::string scene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";
  std::printf("reference: %d x %d cells, %d steps\n", reference_nx, reference_nx / 3, steps);
  std::fflush(stdout);
  const auto reference = run_on(scene, reference_nx, steps);

  std::ofstream csv(out / "adaptive_mesh.csv");
  csv << "kind,cells,dofs,wall_s,err_u,est_u,err_v,est_v,err_phi,est_phi,error\n";
  std::printf(
      "| refinement | cells | dofs | wall s | u: error, estimate | v: error, estimate | phi: error, estimate |\n");
  std::printf("|---|---:|---:|---:|---|---|---|\n");
  const auto report = [&](const Row& r) {
    csv << r.kind << ',' << r.cells << ',' << r.dofs << ',' << r.seconds;
    for (int f = 0; f < 3; ++f) csv << ',' << r.error[f] << ',' << r.estimate[f];
    csv << ',' << r.largest_error() << '\n';
    csv.flush();
    std::printf("| %s | %d | %d | %.2f | %.3e, %.3e | %.3e, %.3e | %.3e, %.3e |\n", r.kind.c_str(), r.cells, r.dofs,
                r.seconds, r.error[0], r.estimate[0], r.error[1], r.estimate[1], r.error[2], r.estimate[2]);
    std::fflush(stdout);
  };

  int finest_dofs = 0;
  for (int nx : {15, 30, 60, 120}) {
    const auto run = run_on(scene, nx, steps);
    report(measure("uniform", *run, reference->run->model()));
    finest_dofs = run->result.ndof;
  }
  auto run = run_on(scene, 15, steps);
  RefinementEdge edges = RefinementEdge::Longest;
  for (;;) {
    report(measure("adaptive", *run, reference->run->model()));
    if (run->result.ndof >= finest_dofs) break;
    const Model& m = run->run->model();
    const MeshBisection refined =
        bisect(m.mesh(), dorfler_marking(piezo_space_error(m).relative_cell_indicators(), 0.5), edges);
    edges = RefinementEdge::OppositeVertexZero;
    run = run_on(scene, 15, steps, refined.mesh);
  }
  return 0;
}

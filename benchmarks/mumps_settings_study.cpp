// MUMPS's own settings, chosen by measurement: the symmetry of the factorisation (LU, or LDL^T on the
// rows weighted by assembly/symmetrizing_scale.hpp), the fill-reducing ordering ICNTL(7) and the memory
// relaxation ICNTL(14), on the matrices a run factorises: the linear part of the Jacobian (which the
// Schur condensation and the Krylov path factorise once per step size) and the whole Jacobian at the end
// of the first step (which the full path factorises every Newton iteration), for backward Euler.
// For each setting: analysis, factorisation and solve times (medians of kRepeats, after one of each
// untimed), the entries of the factors (INFOG(20), L alone for LDL^T), the flops of the elimination
// (RINFOG(1)), MUMPS's working memory (INFOG(22), MB) and the ordering MUMPS used (INFOG(7): an ordering
// the library was built without falls back to another).
//   build/release/benchmarks/mumps_settings_study [scene=paper2d.json] [key=value ...] [--out FILE.csv]
// e.g. mumps_settings_study box3d.json mesh.size_factor=0.5
// Run it with `nice` on a shared machine; the settings of a mesh are timed one after the other.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "assembly/mumps_handle.hpp"
#include "assembly/symmetrizing_scale.hpp"
#include "models/scene/scene_runner.hpp"
#include "support/stopwatch.hpp"

using namespace pc;
using study::Clock;
using study::median;
using study::seconds_since;

namespace {

constexpr int kRepeats = 5;

struct Setting {
  const char* ordering_name;
  int ordering;    // ICNTL(7)
  int relaxation;  // ICNTL(14), percent
  bool symmetric;  // LDL^T on the weighted rows
};

struct Measured {
  double analysis = 0, factorization = 0, solve = 0, entries = 0, flops = 0, residual = 0;
  int memory_mb = 0, ordering_used = -1;
  std::string failure;
};

const char* ordering_name(int icntl7) {
  switch (icntl7) {
    case 0: return "AMD";
    case 2: return "AMF";
    case 3: return "SCOTCH";
    case 4: return "PORD";
    case 5: return "METIS";
    case 6: return "QAMD";
    case 7: return "auto";
    default: return "?";
  }
}

Measured measure(const CsrMatrix& a, const std::optional<Eigen::VectorXd>& scale, const Setting& setting) {
  Measured out;
  if (setting.symmetric && !scale) {
    out.failure = "not symmetric after any row scaling";
    return out;
  }
  const Eigen::VectorXd weights = setting.symmetric ? *scale : Eigen::VectorXd();
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(a.rows());
  try {
    std::vector<double> analysis, factorization, solve;
    Eigen::VectorXd x;
    for (int repeat = 0; repeat <= kRepeats; ++repeat) {
      MumpsHandle mumps("study");
      mumps.set_pattern(a, setting.symmetric ? MumpsHandle::Symmetric : MumpsHandle::General);
      mumps.icntl(7) = setting.ordering;
      mumps.icntl(14) = setting.relaxation;
      mumps.set_values(a, weights);
      auto t = Clock::now();
      mumps.run(MumpsHandle::Analyze, "analysis");
      analysis.push_back(seconds_since(t));
      t = Clock::now();
      mumps.run(MumpsHandle::Factorize, "factorization");
      factorization.push_back(seconds_since(t));
      for (int s = 0; s < 3; ++s) {
        x = setting.symmetric ? Eigen::VectorXd(weights.cwiseProduct(b)) : b;
        mumps->rhs = x.data();
        mumps->nrhs = 1;
        mumps->lrhs = mumps->n;
        t = Clock::now();
        mumps.run(MumpsHandle::Solve, "solve");
        solve.push_back(seconds_since(t));
      }
      const double stored = mumps->infog[19];
      out.entries = stored < 0 ? -1e6 * stored : stored;
      out.flops = mumps->rinfog[0];
      out.memory_mb = mumps->infog[21];
      out.ordering_used = mumps->infog[6];
    }
    // The first of each phase warms the caches up and is left out.
    analysis.erase(analysis.begin());
    factorization.erase(factorization.begin());
    solve.erase(solve.begin(), solve.begin() + 3);
    out.analysis = median(analysis);
    out.factorization = median(factorization);
    out.solve = median(solve);
    out.residual = (a * x - b).norm() / b.norm();
  } catch (const Error& e) {
    out.failure = e.what();
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene_file = "paper2d.json", out = "mumps_settings.csv";
  std::vector<std::string> sets;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc)
      out = argv[++i];
    else if (arg.find('=') != std::string::npos)
      sets.push_back(arg);
    else
      scene_file = arg;
  }
  const Scene scene = load_scene_file(std::string(PIEZOCONTACT_SCENES) + "/" + scene_file, sets);
  FoundationRun run(scene, find_foundation(scene, "conductive"));
  const FoundationRunResult first_step = run.run("", false, 1);
  Model& model = run.model();
  const CsrMatrix linear = model.linear_jacobian();
  // Between steps the scheme reads u as the committed displacement; within a backward Euler step (the
  // scheme of the shipped scenes) u = u_n-1 + k v, which gives the Jacobian its v-phi coupling.
  model.set_affine("u", scene.end_time / scene.steps, {1.0});
  model.assemble(true);
  const CsrMatrix full = model.jacobian();
  std::fprintf(stderr, "%s: %d dofs, first step %s\n", scene_file.c_str(), first_step.ndof,
               first_step.completed ? "done" : "STOPPED");

  std::vector<Setting> settings;
  for (bool symmetric : {false, true})
    for (int ordering : {0, 2, 3, 4, 5, 6, 7}) settings.push_back({ordering_name(ordering), ordering, 20, symmetric});
  for (int relaxation : {5, 50}) settings.push_back({"auto", 7, relaxation, true});

  std::FILE* csv = std::fopen(out.c_str(), "w");
  if (!csv) {
    std::fprintf(stderr, "cannot write %s\n", out.c_str());
    return 1;
  }
  std::fprintf(csv,
               "scene,sets,matrix,n,nonzeros,factorisation,ordering,ordering_used,icntl14,analysis_s,"
               "factorization_s,solve_s,entries,flops,memory_mb,relative_residual,failure\n");
  std::string set_text;
  for (const std::string& s : sets) set_text += (set_text.empty() ? "" : " ") + s;
  std::printf(
      "%s %s\n\n| matrix | factorisation | ICNTL(7) (used) | ICNTL(14) | analysis | factorisation | solve | entries | "
      "GFlop | MUMPS MB |\n|---|---|---|---|---|---|---|---|---|---|\n",
      scene_file.c_str(), set_text.c_str());
  for (const auto& [matrix_name, matrix] : {std::pair<const char*, const CsrMatrix*>{"linear part", &linear},
                                            std::pair<const char*, const CsrMatrix*>{"whole Jacobian", &full}}) {
    const std::optional<Eigen::VectorXd> scale = symmetrizing_row_scale(*matrix);
    for (const Setting& setting : settings) {
      const Measured m = measure(*matrix, scale, setting);
      const char* kind = setting.symmetric ? "LDL^T" : "LU";
      std::fprintf(csv, "%s,%s,%s,%d,%ld,%s,%s,%s,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%d,%.3g,\"%s\"\n", scene_file.c_str(),
                   set_text.c_str(), matrix_name, int(matrix->rows()), long(matrix->nonZeros()), kind,
                   setting.ordering_name, ordering_name(m.ordering_used), setting.relaxation, m.analysis,
                   m.factorization, m.solve, m.entries, m.flops, m.memory_mb, m.residual, m.failure.c_str());
      std::fflush(csv);
      if (!m.failure.empty()) {
        std::printf("| %s | %s | %s | %d | %s |||||\n", matrix_name, kind, setting.ordering_name, setting.relaxation,
                    m.failure.c_str());
        continue;
      }
      std::printf("| %s (%d dofs) | %s | %s (%s) | %d | %.1f ms | %.1f ms | %.2f ms | %.3g | %.2f | %d |\n",
                  matrix_name, int(matrix->rows()), kind, setting.ordering_name, ordering_name(m.ordering_used),
                  setting.relaxation, 1e3 * m.analysis, 1e3 * m.factorization, 1e3 * m.solve, m.entries, 1e-9 * m.flops,
                  m.memory_mb);
    }
  }
  std::fclose(csv);
  std::printf("\nCSV: %s\n", out.c_str());
  return 0;
}

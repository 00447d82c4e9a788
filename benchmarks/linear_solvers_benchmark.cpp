// The three phases of every sparse direct solver on finite-difference Laplacians: 5-point in 2D and
// 7-point in 3D (the 3D ones fill in much more, like 3D finite-element systems).
//   linear_solvers_benchmark --benchmark_filter=umfpack/factorize
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include "assembly/linear_solver.hpp"
#include "assembly/sparse.hpp"

namespace {

using pc::CsrMatrix;

// Dirichlet Laplacian on an m^dimension grid (neighbours outside the grid eliminated).
CsrMatrix laplacian(int dimension, int m) {
  const int n = dimension == 2 ? m * m : m * m * m;
  const int strides[3] = {1, m, m * m};
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(static_cast<size_t>(n) * (2 * dimension + 1));
  for (int node = 0; node < n; ++node) {
    triplets.emplace_back(node, node, 2.0 * dimension);
    for (int axis = 0; axis < dimension; ++axis) {
      const int coordinate = node / strides[axis] % m;
      if (coordinate > 0) triplets.emplace_back(node, node - strides[axis], -1.0);
      if (coordinate + 1 < m) triplets.emplace_back(node, node + strides[axis], -1.0);
    }
  }
  CsrMatrix matrix(n, n);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  matrix.makeCompressed();
  return matrix;
}

enum class Phase { Analyze, Factorize, Solve };

// Each benchmark times one phase, the earlier ones done once beforehand.
void run_phase(benchmark::State& state, const std::string& solver_name, int dimension, Phase phase) {
  const CsrMatrix matrix = laplacian(dimension, static_cast<int>(state.range(0)));
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(matrix.rows());
  const auto solver = pc::make_linear_solver(solver_name);
  if (phase != Phase::Analyze) solver->analyze(matrix);
  if (phase == Phase::Solve) {
    solver->factorize(matrix);
    solver->solve(b);  // warm-up: UMFPACK's first solve takes twice as long as the next ones
  }
  for (auto _ : state) {
    switch (phase) {
      case Phase::Analyze: solver->analyze(matrix); break;
      case Phase::Factorize: solver->factorize(matrix); break;
      case Phase::Solve: benchmark::DoNotOptimize(solver->solve(b)); break;
    }
  }
  state.counters["dofs"] = static_cast<double>(matrix.rows());
  state.counters["nnz"] = static_cast<double>(matrix.nonZeros());
}

void register_benchmarks() {
  const std::pair<const char*, Phase> phases[] = {
      {"analyze", Phase::Analyze}, {"factorize", Phase::Factorize}, {"solve", Phase::Solve}};
  for (const std::string& solver : pc::linear_solver_names())
    for (const auto& [phase_name, phase] : phases) {
      const std::string prefix = solver + "/" + phase_name;
      // Short minimum times: the large cases take tenths of a second per iteration already.
      benchmark::RegisterBenchmark((prefix + "/laplacian2d").c_str(), run_phase, solver, 2, phase)
          ->Arg(64)
          ->Arg(128)
          ->Arg(256)
          ->Unit(benchmark::kMillisecond)
          ->MinTime(0.1);
      benchmark::RegisterBenchmark((prefix + "/laplacian3d").c_str(), run_phase, solver, 3, phase)
          ->Arg(16)
          ->Arg(32)
          ->Unit(benchmark::kMillisecond)
          ->MinTime(0.1);
    }
}

}  // namespace

int main(int argc, char** argv) {
  register_benchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

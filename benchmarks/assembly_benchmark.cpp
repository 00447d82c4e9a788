// Assembly throughput of the engine: cells per second for linear elasticity, P1 and P2, 2D and 3D, through
// the generic weak form (tangent by Dual numbers) and through a hand-written term, plus the cost of
// building a term's pattern and slot maps (done once per run). Run:
//   build/release/benchmarks/assembly_benchmark
#include <benchmark/benchmark.h>

#include <memory>

#include "assembly/mesh_generators.hpp"
#include "assembly/pointwise_term.hpp"
#include "assembly/term_assembly.hpp"
#include "bricks/elastic_flux_kernel.hpp"
#include "bricks/strain_stiffness_term.hpp"
#include "bricks/voigt.hpp"

namespace pc {
namespace {

std::shared_ptr<const Mesh> mesh_for(int dim, int n) {
  if (dim == 2) return std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, n, n, Shape::Triangle));
  return std::make_shared<const Mesh>(box_mesh({0, 0, 0}, {1, 1, 1}, n, n, n, Shape::Tetrahedron));
}

std::shared_ptr<const Term> generic_term() {
  return std::make_shared<PointwiseTerm<ElasticFlux>>("elasticity (Dual)", Integration::Cells,
                                                      std::vector<FieldUse>{{"u", true}}, std::vector<int>{0},
                                                      std::vector<Coupling>{{0, 0}}, ElasticFlux{});
}

// args: dim, order, cells per side, hand-written (1) or generic (0)
void BM_ElasticityTangent(benchmark::State& state) {
  const int dim = int(state.range(0)), order = int(state.range(1)), n = int(state.range(2));
  const bool hand = state.range(3) == 1;
  auto mesh = mesh_for(dim, n);
  FESpace space(mesh, order, dim);
  std::shared_ptr<const Term> term = hand ? std::make_shared<const StrainStiffnessTerm>(
                                                "elasticity (hand)", "u", "u", "C", isotropic_stiffness(dim, 1.2, 0.8))
                                          : generic_term();
  TermAssembly assembly(term, "all", {&space});
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(space.num_dofs());
  const Eigen::VectorXd* values[] = {&u};
  Eigen::VectorXd* none[] = {nullptr};
  for (auto _ : state) {
    assembly.assemble(values, 0, none, true);
    benchmark::DoNotOptimize(assembly.block(0).valuePtr());
  }
  state.counters["cells"] = mesh->num_cells();
  state.counters["dofs"] = space.num_dofs();
  state.counters["cells_per_s"] =
      benchmark::Counter(double(mesh->num_cells()) * state.iterations(), benchmark::Counter::kIsRate);
}

void BM_PatternAndSlots(benchmark::State& state) {
  const int dim = int(state.range(0)), order = int(state.range(1)), n = int(state.range(2));
  auto mesh = mesh_for(dim, n);
  FESpace space(mesh, order, dim);
  auto term = generic_term();
  for (auto _ : state) {
    TermAssembly assembly(term, "all", {&space});
    benchmark::DoNotOptimize(assembly.block(0).nonZeros());
  }
  state.counters["cells"] = mesh->num_cells();
}

BENCHMARK(BM_ElasticityTangent)
    ->ArgsProduct({{2}, {1, 2}, {64}, {0, 1}})
    ->ArgsProduct({{3}, {1, 2}, {12}, {0, 1}})
    ->ArgNames({"dim", "order", "n", "hand"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PatternAndSlots)
    ->Args({2, 1, 64})
    ->Args({2, 2, 64})
    ->Args({3, 1, 12})
    ->Args({3, 2, 12})
    ->ArgNames({"dim", "order", "n"})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace pc

BENCHMARK_MAIN();

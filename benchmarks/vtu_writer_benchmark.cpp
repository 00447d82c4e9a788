// Time and size of one VTU file of the paper scene at 240 x 80 (19521 nodes, 38400 triangles) with the
// arrays the runner writes (v, u, phi, contact_pressure; strain, stress, von_mises, electric_field,
// electric_displacement), in each VtuFormat. The fields are smooth functions of the size of the paper's,
// not a solution: their doubles compress about as little as a solution's, but not identically (the sizes
// of a real series are in docs/scenes.md). Run:
//   build/release/benchmarks/vtu_writer_benchmark
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include "assembly/mesh_generators.hpp"
#include "assembly/vtu_writer.hpp"

namespace pc {
namespace {

constexpr VtuFormat kFormats[] = {VtuFormat::Ascii, VtuFormat::Base64, VtuFormat::Binary, VtuFormat::Zlib};

// Cell data: `components` smooth values of a cell's centroid, scaled like a stress (1e5) or a strain (1e-6).
std::vector<double> cell_values(const Mesh& mesh, int components, double scale) {
  std::vector<double> values(size_t(mesh.num_cells()) * components);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    double x = 0, y = 0;
    for (const int n : mesh.cell(c)) x += mesh.node(n)[0] / 3, y += mesh.node(n)[1] / 3;
    for (int k = 0; k < components; ++k)
      values[size_t(c) * components + k] = scale * std::sin(300 * x + k) * std::cos(500 * y);
  }
  return values;
}

void BM_WriteVtu(benchmark::State& state) {
  const VtuFormat format = kFormats[state.range(0)];
  state.SetLabel(to_string(format));
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {0.03, 0.01}, 240, 80, Shape::Triangle));
  const FESpace vectors(mesh, 1, 2), scalars(mesh, 1, 1);
  VtuWriter writer(*mesh);
  writer.add_point_field("v", vectors, vectors.interpolate([](const double* x, double* out) {
    out[0] = 1e-7 * std::sin(200 * x[0]) * x[1];
    out[1] = -2e-7 * x[0] * std::cos(300 * x[1]);
  }));
  writer.add_point_field("u", vectors, vectors.interpolate([](const double* x, double* out) {
    out[0] = 4e-8 * x[0] / 0.03 + 1e-9 * std::sin(500 * x[1]);
    out[1] = -1e-8 * (x[0] / 0.03) * (x[0] / 0.03);
  }));
  writer.add_point_field("phi", scalars, scalars.interpolate([](const double* x, double* out) {
    out[0] = -48 * (1 - x[1] / 0.01) + 0.8 * std::sin(400 * x[0]);
  }));
  std::vector<double> pressure(mesh->num_nodes(), 0.0);
  for (int n = 0; n < mesh->num_nodes(); ++n)
    if (mesh->node(n)[1] == 0) pressure[n] = 1e3 * (1 + std::sin(300 * mesh->node(n)[0]));
  writer.add_point_data("contact_pressure", 1, pressure);
  writer.add_cell_data("strain", 3, cell_values(*mesh, 3, 1e-6));
  writer.add_cell_data("stress", 3, cell_values(*mesh, 3, 1e5));
  writer.add_cell_data("von_mises", 1, cell_values(*mesh, 1, 1e5));
  writer.add_cell_data("electric_field", 2, cell_values(*mesh, 2, 5e3));
  writer.add_cell_data("electric_displacement", 2, cell_values(*mesh, 2, 1e-4));

  const std::string path =
      (std::filesystem::temp_directory_path() / ("vtu_writer_benchmark_" + std::to_string(::getpid()) + ".vtu"))
          .string();
  for (auto _ : state) writer.write(path, format);
  const double bytes = double(std::filesystem::file_size(path));
  std::filesystem::remove(path);
  state.counters["MB"] = bytes / 1e6;
  state.counters["MB_per_s"] = benchmark::Counter(bytes * state.iterations() / 1e6, benchmark::Counter::kIsRate);
}

BENCHMARK(BM_WriteVtu)->DenseRange(0, 3)->ArgName("format")->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace pc

BENCHMARK_MAIN();

#include "models/output/mesh_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pc {

MeshStatistics mesh_statistics(const Mesh& mesh) {
  MeshStatistics s;
  s.dim = mesh.dim();
  s.nodes = mesh.num_nodes();
  s.cells = mesh.num_cells();
  s.cell_shape = mesh.cell_shape();
  double h_min = std::numeric_limits<double>::infinity(), h_max = 0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto vertices = mesh.cell(c);
    for (int e = 0; e < num_edges(s.cell_shape); ++e) {
      const auto ends = edge_vertices(s.cell_shape, e);
      const auto a = mesh.node(vertices[ends[0]]), b = mesh.node(vertices[ends[1]]);
      double length2 = 0;
      for (int d = 0; d < s.dim; ++d) length2 += (a[d] - b[d]) * (a[d] - b[d]);
      h_min = std::min(h_min, std::sqrt(length2));
      h_max = std::max(h_max, std::sqrt(length2));
    }
  }
  if (s.cells > 0) s.h_min = h_min, s.h_max = h_max;
  return s;
}

}  // namespace pc

#pragma once
// The shortest and longest edge of a simplex mesh, computed apart from the library (every pair of a
// simplex's vertices is an edge), to check what a summary says about its mesh.
#include <algorithm>
#include <cmath>
#include <utility>

#include "assembly/mesh.hpp"

namespace pc::testing {

inline std::pair<double, double> simplex_edge_range(const Mesh& mesh) {
  double lo = 1e300, hi = 0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto v = mesh.cell(c);
    for (size_t a = 0; a < v.size(); ++a)
      for (size_t b = a + 1; b < v.size(); ++b) {
        double l2 = 0;
        for (int d = 0; d < mesh.dim(); ++d) l2 += std::pow(mesh.node(v[a])[d] - mesh.node(v[b])[d], 2);
        lo = std::min(lo, std::sqrt(l2));
        hi = std::max(hi, std::sqrt(l2));
      }
  }
  return {lo, hi};
}

}  // namespace pc::testing

#include "assembly/mesh_bisection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

#include "assembly/error.hpp"

namespace pc {
namespace {

using Triangle = std::array<int, 3>;  // vertex 0 the newest, (1, 2) the refinement edge
using Edge = std::pair<int, int>;     // the smaller node first

Edge edge(int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; }

double squared_length(const Mesh& mesh, int a, int b) {
  const auto p = mesh.node(a), q = mesh.node(b);
  return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]);
}

// The mesh's cells as triangles whose refinement edge is (1, 2), rotated (which keeps the orientation).
std::vector<Triangle> oriented_cells(const Mesh& mesh, RefinementEdge edges) {
  std::vector<Triangle> cells(mesh.num_cells());
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto t = mesh.cell(c);
    int first = 0;
    if (edges == RefinementEdge::Longest) {
      double longest = -1;
      for (int k = 0; k < 3; ++k) {
        const double length = squared_length(mesh, t[(k + 1) % 3], t[(k + 2) % 3]);
        if (length > longest * (1 + 1e-12)) {
          longest = length;
          first = k;
        }
      }
    }
    cells[c] = {t[first], t[(first + 1) % 3], t[(first + 2) % 3]};
  }
  return cells;
}

// The local face of a triangle whose vertices are the nodes a and b, or -1.
int local_face_of(const int* triangle, int a, int b) {
  for (int f = 0; f < 3; ++f) {
    const auto v = face_vertices(Shape::Triangle, f);
    if (edge(triangle[v[0]], triangle[v[1]]) == edge(a, b)) return f;
  }
  return -1;
}

}  // namespace

MeshBisection bisect(const Mesh& mesh, const std::vector<int>& marked_cells, RefinementEdge edges) {
  require(mesh.dim() == 2 && mesh.cell_shape() == Shape::Triangle,
          "bisect: newest-vertex bisection takes a 2D mesh of triangles; this one is ", mesh.dim(), "D of ",
          to_string(mesh.cell_shape()));
  const std::vector<Triangle> cells = oriented_cells(mesh, edges);
  std::map<Edge, int> split;  // edge -> its midpoint's node, -1 until made
  for (int c : marked_cells) {
    require(c >= 0 && c < mesh.num_cells(), "bisect: marked cell ", c, " does not exist; the mesh has ",
            mesh.num_cells(), " cells");
    split.emplace(edge(cells[c][1], cells[c][2]), -1);
  }
  // The conforming closure: a cell with a bisected edge has its refinement edge bisected first.
  for (bool grew = !split.empty(); grew;) {
    grew = false;
    for (const Triangle& t : cells) {
      const Edge refinement = edge(t[1], t[2]);
      if (split.contains(refinement)) continue;
      if (split.contains(edge(t[0], t[1])) || split.contains(edge(t[2], t[0]))) {
        split.emplace(refinement, -1);
        grew = true;
      }
    }
  }

  std::vector<double> coordinates = mesh.coordinates();
  const auto midpoint = [&](int& node, const Edge& e) {
    if (node >= 0) return node;
    node = int(coordinates.size() / 2);
    for (int d = 0; d < 2; ++d)
      coordinates.push_back(0.5 * (coordinates[2 * e.first + d] + coordinates[2 * e.second + d]));
    return node;
  };
  std::vector<int> connectivity, parent;
  std::vector<std::vector<int>> children(mesh.num_cells());
  for (int c = 0; c < mesh.num_cells(); ++c) {
    std::vector<Triangle> pending{cells[c]};
    while (!pending.empty()) {
      const Triangle t = pending.back();
      pending.pop_back();
      const auto it = split.find(edge(t[1], t[2]));
      if (it == split.end()) {
        children[c].push_back(int(parent.size()));
        connectivity.insert(connectivity.end(), t.begin(), t.end());
        parent.push_back(c);
        continue;
      }
      const int m = midpoint(it->second, it->first);
      pending.push_back({m, t[2], t[0]});
      pending.push_back({m, t[0], t[1]});
    }
  }

  auto refined = std::make_shared<Mesh>(2, Shape::Triangle, std::move(coordinates), connectivity);
  for (const std::string& name : mesh.region_names()) {
    if (name == "all" || name == "boundary") continue;  // every mesh makes its own
    if (mesh.region_kind(name) == RegionKind::Cells) {
      std::vector<int> region;
      for (int c : mesh.cell_region(name)) region.insert(region.end(), children[c].begin(), children[c].end());
      refined->add_cell_region(name, std::move(region));
      continue;
    }
    std::vector<FaceRef> region;
    for (const FaceRef& face : mesh.face_region(name)) {
      const std::vector<int> nodes = mesh.face_nodes(face);
      std::vector<Edge> pieces{edge(nodes[0], nodes[1])};
      if (const auto it = split.find(pieces[0]); it != split.end())
        pieces = {edge(nodes[0], it->second), edge(it->second, nodes[1])};
      for (const Edge& piece : pieces)
        for (int child : children[face.cell]) {
          const int local = local_face_of(connectivity.data() + 3 * child, piece.first, piece.second);
          if (local >= 0) {
            region.push_back({child, local});
            break;
          }
        }
    }
    refined->add_face_region(name, std::move(region));
  }
  return {std::move(refined), std::move(parent)};
}

std::vector<int> dorfler_marking(const std::vector<double>& indicators, double fraction) {
  require(fraction > 0 && fraction <= 1, "Dörfler marking: the fraction must be in (0, 1], got ", fraction);
  double total = 0;
  for (size_t i = 0; i < indicators.size(); ++i) {
    require(std::isfinite(indicators[i]) && indicators[i] >= 0, "Dörfler marking: the indicator of cell ", i, " is ",
            indicators[i], "; indicators are finite and not negative");
    total += indicators[i] * indicators[i];
  }
  std::vector<int> order(indicators.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return indicators[a] > indicators[b]; });
  std::vector<int> marked;
  double sum = 0;
  for (int cell : order) {
    if (sum >= fraction * total || indicators[cell] == 0) break;
    marked.push_back(cell);
    sum += indicators[cell] * indicators[cell];
  }
  std::sort(marked.begin(), marked.end());
  return marked;
}

}  // namespace pc

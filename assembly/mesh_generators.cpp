#include "assembly/mesh_generators.hpp"

#include <algorithm>
#include <cmath>

#include "assembly/error.hpp"

namespace pc {
namespace {

void check_axis(const char* function, const char* axis, double lower, double upper, int n) {
  require(n >= 1, function, ": n", axis, " must be at least 1, got ", n);
  require(upper > lower, function, ": upper ", axis, " (", upper, ") must be greater than lower ", axis, " (", lower,
          ")");
}

// n + 1 equally spaced coordinates; the last is set to upper exactly so that the sides of the domain can
// be found by comparing coordinates.
std::vector<double> grid_line(double lower, double upper, int n) {
  std::vector<double> x(n + 1);
  for (int i = 0; i < n; ++i) x[i] = lower + (upper - lower) * i / n;
  x[n] = upper;
  return x;
}

// Face regions "xmin", "xmax", ... for the sides of the axis-aligned box [lower, upper].
void add_side_regions(Mesh& mesh, std::span<const double> lower, std::span<const double> upper) {
  static const char* const names[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
  for (int axis = 0; axis < int(lower.size()); ++axis) {
    const double tolerance = 1e-10 * (upper[axis] - lower[axis]);
    for (int side = 0; side < 2; ++side) {
      const double value = side == 0 ? lower[axis] : upper[axis];
      mesh.add_boundary_region_where(names[axis][side],
                                     [&](std::span<const double> x) { return std::abs(x[axis] - value) <= tolerance; });
    }
  }
}

double tetrahedron_det(const std::vector<double>& coordinates, const std::array<int, 4>& tet) {
  double e[3][3];
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) e[k][i] = coordinates[3 * tet[k + 1] + i] - coordinates[3 * tet[0] + i];
  return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
         e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}

}  // namespace

Mesh rectangle_mesh(std::array<double, 2> lower, std::array<double, 2> upper, int nx, int ny, Shape shape) {
  check_axis("rectangle_mesh", "x", lower[0], upper[0], nx);
  check_axis("rectangle_mesh", "y", lower[1], upper[1], ny);
  require(shape == Shape::Triangle || shape == Shape::Quadrilateral,
          "rectangle_mesh: shape must be triangle or quadrilateral, got ", to_string(shape));
  const auto x = grid_line(lower[0], upper[0], nx);
  const auto y = grid_line(lower[1], upper[1], ny);

  std::vector<double> coordinates;
  coordinates.reserve(size_t(nx + 1) * (ny + 1) * 2);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) coordinates.insert(coordinates.end(), {x[i], y[j]});

  auto node = [&](int i, int j) { return j * (nx + 1) + i; };
  std::vector<int> connectivity;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      // Counterclockwise corners, so every cell is positively oriented.
      const int n0 = node(i, j), n1 = node(i + 1, j), n2 = node(i + 1, j + 1), n3 = node(i, j + 1);
      if (shape == Shape::Quadrilateral) {
        connectivity.insert(connectivity.end(), {n0, n1, n2, n3});
      } else {
        connectivity.insert(connectivity.end(), {n0, n1, n2, n0, n2, n3});
      }
    }
  }

  Mesh mesh(2, shape, std::move(coordinates), std::move(connectivity));
  add_side_regions(mesh, lower, upper);
  const char* const aliases[4][2] = {{"left", "xmin"}, {"right", "xmax"}, {"bottom", "ymin"}, {"top", "ymax"}};
  for (const auto& [alias, side] : aliases) mesh.add_face_region(alias, mesh.face_region(side));
  return mesh;
}

Mesh box_mesh(std::array<double, 3> lower, std::array<double, 3> upper, int nx, int ny, int nz, Shape shape) {
  check_axis("box_mesh", "x", lower[0], upper[0], nx);
  check_axis("box_mesh", "y", lower[1], upper[1], ny);
  check_axis("box_mesh", "z", lower[2], upper[2], nz);
  require(shape == Shape::Tetrahedron || shape == Shape::Hexahedron,
          "box_mesh: shape must be tetrahedron or hexahedron, got ", to_string(shape));
  const std::array<std::vector<double>, 3> axes = {grid_line(lower[0], upper[0], nx), grid_line(lower[1], upper[1], ny),
                                                   grid_line(lower[2], upper[2], nz)};

  std::vector<double> coordinates;
  coordinates.reserve(size_t(nx + 1) * (ny + 1) * (nz + 1) * 3);
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) coordinates.insert(coordinates.end(), {axes[0][i], axes[1][j], axes[2][k]});

  auto node = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  std::vector<int> connectivity;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        if (shape == Shape::Hexahedron) {
          // Vertex order of reference_vertex: the bottom face counterclockwise, then the top face.
          for (int dk = 0; dk < 2; ++dk)
            connectivity.insert(connectivity.end(), {node(i, j, k + dk), node(i + 1, j, k + dk),
                                                     node(i + 1, j + 1, k + dk), node(i, j + 1, k + dk)});
          continue;
        }
        // Kuhn (Freudenthal) split: one tetrahedron per monotone path from the corner (i, j, k) to
        // (i+1, j+1, k+1), stepping along the axes in each of the six orders. Every cube uses the same
        // main diagonal, so the diagonals of shared faces match and the mesh is conforming.
        std::array<int, 3> order = {0, 1, 2};
        do {
          std::array<int, 3> corner = {i, j, k};
          std::array<int, 4> tet;
          tet[0] = node(corner[0], corner[1], corner[2]);
          for (int step = 0; step < 3; ++step) {
            ++corner[order[step]];
            tet[step + 1] = node(corner[0], corner[1], corner[2]);
          }
          if (tetrahedron_det(coordinates, tet) < 0) std::swap(tet[2], tet[3]);
          connectivity.insert(connectivity.end(), tet.begin(), tet.end());
        } while (std::next_permutation(order.begin(), order.end()));
      }
    }
  }

  Mesh mesh(3, shape, std::move(coordinates), std::move(connectivity));
  add_side_regions(mesh, lower, upper);
  return mesh;
}

}  // namespace pc

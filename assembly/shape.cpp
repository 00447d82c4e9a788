#include "assembly/shape.hpp"

#include "assembly/error.hpp"

namespace pc {
namespace {

// Local entity tables (VTK/gmsh vertex order).
constexpr int kSegmentFaces[2][1] = {{0}, {1}};
constexpr int kTriangleEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
constexpr int kQuadEdges[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
constexpr int kTetEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
constexpr int kTetFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
constexpr int kHexEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                  {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
// Faces in VTK's order for the triquadratic hexahedron: x = 0, x = 1, y = 0, y = 1, z = 0, z = 1.
constexpr int kHexFaces[6][4] = {{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 3, 2, 1}, {4, 5, 6, 7}};

void check_index(int index, int count, const char* what, Shape shape) {
  require(index >= 0 && index < count, what, " ", index, " does not exist on a ", to_string(shape), " (it has ", count,
          ")");
}

}  // namespace

std::string to_string(Shape shape) {
  switch (shape) {
    case Shape::Point: return "point";
    case Shape::Segment: return "segment";
    case Shape::Triangle: return "triangle";
    case Shape::Quadrilateral: return "quadrilateral";
    case Shape::Tetrahedron: return "tetrahedron";
    case Shape::Hexahedron: return "hexahedron";
  }
  return "unknown shape";
}

int dimension(Shape shape) {
  switch (shape) {
    case Shape::Point: return 0;
    case Shape::Segment: return 1;
    case Shape::Triangle:
    case Shape::Quadrilateral: return 2;
    case Shape::Tetrahedron:
    case Shape::Hexahedron: return 3;
  }
  return -1;
}

int num_vertices(Shape shape) {
  constexpr int counts[] = {1, 2, 3, 4, 4, 8};
  return counts[static_cast<int>(shape)];
}

int num_faces(Shape shape) {
  constexpr int counts[] = {0, 2, 3, 4, 4, 6};
  return counts[static_cast<int>(shape)];
}

int num_edges(Shape shape) {
  constexpr int counts[] = {0, 1, 3, 4, 6, 12};
  return counts[static_cast<int>(shape)];
}

bool is_simplex(Shape shape) {
  return shape == Shape::Segment || shape == Shape::Triangle || shape == Shape::Tetrahedron;
}

std::array<double, 3> reference_vertex(Shape shape, int vertex) {
  check_index(vertex, num_vertices(shape), "vertex", shape);
  switch (shape) {
    case Shape::Point: return {0, 0, 0};
    case Shape::Segment: return {double(vertex), 0, 0};
    case Shape::Triangle:
    case Shape::Tetrahedron: {
      std::array<double, 3> x{0, 0, 0};
      if (vertex > 0) x[vertex - 1] = 1;
      return x;
    }
    case Shape::Quadrilateral: {
      constexpr double q[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      return {q[vertex][0], q[vertex][1], 0};
    }
    case Shape::Hexahedron: {
      constexpr double q[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      return {q[vertex % 4][0], q[vertex % 4][1], double(vertex / 4)};
    }
  }
  return {0, 0, 0};
}

std::span<const int> edge_vertices(Shape cell, int edge) {
  check_index(edge, num_edges(cell), "edge", cell);
  switch (cell) {
    case Shape::Segment: return {kTriangleEdges[0], 2};
    case Shape::Triangle: return {kTriangleEdges[edge], 2};
    case Shape::Quadrilateral: return {kQuadEdges[edge], 2};
    case Shape::Tetrahedron: return {kTetEdges[edge], 2};
    case Shape::Hexahedron: return {kHexEdges[edge], 2};
    default: break;
  }
  fail("a ", to_string(cell), " has no edges");
}

std::span<const int> face_vertices(Shape cell, int face) {
  check_index(face, num_faces(cell), "face", cell);
  switch (cell) {
    case Shape::Segment: return {kSegmentFaces[face], 1};
    case Shape::Triangle: return {kTriangleEdges[face], 2};
    case Shape::Quadrilateral: return {kQuadEdges[face], 2};
    case Shape::Tetrahedron: return {kTetFaces[face], 3};
    case Shape::Hexahedron: return {kHexFaces[face], 4};
    default: break;
  }
  fail("a ", to_string(cell), " has no faces");
}

Shape face_shape(Shape cell, int face) {
  check_index(face, num_faces(cell), "face", cell);
  switch (cell) {
    case Shape::Segment: return Shape::Point;
    case Shape::Triangle:
    case Shape::Quadrilateral: return Shape::Segment;
    case Shape::Tetrahedron: return Shape::Triangle;
    case Shape::Hexahedron: return Shape::Quadrilateral;
    default: break;
  }
  fail("a ", to_string(cell), " has no faces");
}

std::array<double, 3> face_to_cell(Shape cell, int face, const double* s) {
  const auto vertices = face_vertices(cell, face);
  auto corner = [&](int k) { return reference_vertex(cell, vertices[k]); };
  std::array<double, 3> x{0, 0, 0};
  switch (face_shape(cell, face)) {
    case Shape::Point: return corner(0);
    case Shape::Segment:
    case Shape::Triangle: {
      // Affine: x = v0 + sum_k s_k (v_{k+1} - v0).
      const auto v0 = corner(0);
      x = v0;
      for (int k = 1; k < int(vertices.size()); ++k) {
        const auto vk = corner(k);
        for (int d = 0; d < 3; ++d) x[d] += s[k - 1] * (vk[d] - v0[d]);
      }
      return x;
    }
    case Shape::Quadrilateral: {
      const double w[4] = {(1 - s[0]) * (1 - s[1]), s[0] * (1 - s[1]), s[0] * s[1], (1 - s[0]) * s[1]};
      for (int k = 0; k < 4; ++k) {
        const auto vk = corner(k);
        for (int d = 0; d < 3; ++d) x[d] += w[k] * vk[d];
      }
      return x;
    }
    default: break;
  }
  fail("unsupported face of a ", to_string(cell));
}

}  // namespace pc

#include "assembly/reference_element.hpp"

#include <algorithm>

#include "assembly/error.hpp"

namespace pc {
namespace {

// Simplices: barycentric coordinates lambda_0 = 1 - sum_d xi_d and lambda_k = xi_{k-1}, so that
// lambda_k is one at vertex k. P1 functions are lambda_v; P2 functions are lambda_v (2 lambda_v - 1) on
// vertices and 4 lambda_a lambda_b on the edge (a, b).
void barycentric(int dim, const double* xi, double* lambda) {
  lambda[0] = 1;
  for (int d = 0; d < dim; ++d) {
    lambda[0] -= xi[d];
    lambda[d + 1] = xi[d];
  }
}

constexpr double barycentric_gradient(int k, int d) { return k == 0 ? -1.0 : (k - 1 == d ? 1.0 : 0.0); }

void simplex_values(Shape shape, int order, std::span<const DofEntity> entities, const double* xi, double* N) {
  double lambda[4];
  barycentric(dimension(shape), xi, lambda);
  for (std::size_t i = 0; i < entities.size(); ++i) {
    if (entities[i].dim == 0) {
      const double l = lambda[entities[i].index];
      N[i] = order == 1 ? l : l * (2 * l - 1);
    } else {
      const auto edge = edge_vertices(shape, entities[i].index);
      N[i] = 4 * lambda[edge[0]] * lambda[edge[1]];
    }
  }
}

void simplex_gradients(Shape shape, int order, std::span<const DofEntity> entities, const double* xi, double* dN) {
  const int dim = dimension(shape);
  double lambda[4];
  barycentric(dim, xi, lambda);
  for (std::size_t i = 0; i < entities.size(); ++i) {
    double* gradient = dN + i * dim;
    if (entities[i].dim == 0) {
      const int k = entities[i].index;
      const double slope = order == 1 ? 1.0 : 4 * lambda[k] - 1;
      for (int d = 0; d < dim; ++d) gradient[d] = slope * barycentric_gradient(k, d);
    } else {
      const auto edge = edge_vertices(shape, entities[i].index);
      const int a = edge[0], b = edge[1];
      for (int d = 0; d < dim; ++d) {
        gradient[d] = 4 * (lambda[b] * barycentric_gradient(a, d) + lambda[a] * barycentric_gradient(b, d));
      }
    }
  }
}

// Quadrilaterals and hexahedra: products of one-dimensional Lagrange polynomials, one per axis.
struct Lagrange1D {
  double value[3];
  double derivative[3];
};

// The Lagrange polynomials of [0, 1] for nodes j / order, j = 0..order, at t.
Lagrange1D lagrange_1d(int order, double t) {
  if (order == 1) return {{1 - t, t, 0}, {-1, 1, 0}};
  return {{(1 - t) * (1 - 2 * t), 4 * t * (1 - t), t * (2 * t - 1)}, {4 * t - 3, 4 - 8 * t, 4 * t - 1}};
}

// The index j of the one-dimensional node at coordinate c = j / order.
int node_index(int order, double c) { return static_cast<int>(order * c + 0.5); }

// The dimension is a template parameter so that the short loops over axes unroll.
template <int dim>
void tensor_values(int order, std::span<const std::array<double, 3>> nodes, const double* xi, double* N) {
  Lagrange1D axis[dim];
  for (int d = 0; d < dim; ++d) axis[d] = lagrange_1d(order, xi[d]);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    double value = 1;
    for (int d = 0; d < dim; ++d) value *= axis[d].value[node_index(order, nodes[i][d])];
    N[i] = value;
  }
}

template <int dim>
void tensor_gradients(int order, std::span<const std::array<double, 3>> nodes, const double* xi, double* dN) {
  Lagrange1D axis[dim];
  for (int d = 0; d < dim; ++d) axis[d] = lagrange_1d(order, xi[d]);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    double value[dim], derivative[dim];
    for (int d = 0; d < dim; ++d) {
      const int j = node_index(order, nodes[i][d]);
      value[d] = axis[d].value[j];
      derivative[d] = axis[d].derivative[j];
    }
    for (int d = 0; d < dim; ++d) {
      double gradient = derivative[d];
      for (int e = 0; e < dim; ++e) {
        if (e != d) gradient *= value[e];
      }
      dN[i * dim + d] = gradient;
    }
  }
}

std::array<double, 3> centroid(Shape shape, std::span<const int> vertices) {
  std::array<double, 3> x{0, 0, 0};
  for (const int v : vertices) {
    const auto p = reference_vertex(shape, v);
    for (int d = 0; d < 3; ++d) x[d] += p[d] / static_cast<double>(vertices.size());
  }
  return x;
}

// A dof's node lies on a face when its entity is one of the face's vertices or edges, or the face itself.
bool lies_on_face(Shape shape, DofEntity entity, int face) {
  const auto vertices = face_vertices(shape, face);
  auto on_face = [&](int v) { return std::find(vertices.begin(), vertices.end(), v) != vertices.end(); };
  if (entity.dim == 0) return on_face(entity.index);
  if (entity.dim == 1) {
    const auto edge = edge_vertices(shape, entity.index);
    return on_face(edge[0]) && on_face(edge[1]);
  }
  // Dimension 2 is a face of a 3D cell but the interior of a 2D one.
  return entity.dim == 2 && dimension(shape) == 3 && entity.index == face;
}

}  // namespace

ReferenceElement::ReferenceElement(Shape shape, int order) : shape_(shape), order_(order) {
  auto add = [this](const std::array<double, 3>& point, DofEntity entity) {
    points_.push_back(point);
    entities_.push_back(entity);
  };
  for (int v = 0; v < num_vertices(shape); ++v) add(reference_vertex(shape, v), {0, v});
  if (order == 2) {
    for (int e = 0; e < num_edges(shape); ++e) add(centroid(shape, edge_vertices(shape, e)), {1, e});
    // Quadratic simplices stop at the edges; Q2 adds the face centres (3D) and the cell centre.
    if (!is_simplex(shape)) {
      const int dim = dimension(shape);
      if (dim == 3) {
        for (int f = 0; f < num_faces(shape); ++f) add(centroid(shape, face_vertices(shape, f)), {2, f});
      }
      add({0.5, 0.5, dim == 3 ? 0.5 : 0.0}, {dim, 0});
    }
  }
  for (int f = 0; f < num_faces(shape); ++f) {
    std::vector<int> dofs;
    for (int i = 0; i < num_dofs(); ++i) {
      if (lies_on_face(shape, entities_[i], f)) dofs.push_back(i);
    }
    face_dofs_.push_back(std::move(dofs));
  }
}

const ReferenceElement& ReferenceElement::get(Shape shape, int order) {
  require(dimension(shape) >= 2, "no Lagrange element of order ", order, " on a ", to_string(shape),
          ": elements exist on triangles, quadrilaterals, tetrahedra and hexahedra");
  require(order == 1 || order == 2, "no Lagrange element of order ", order, " on a ", to_string(shape),
          ": orders 1 and 2 are available");
  // Built together on first use; initialising a local static is thread-safe.
  static const std::array<ReferenceElement, 8> elements = {
      ReferenceElement(Shape::Triangle, 1),      ReferenceElement(Shape::Triangle, 2),
      ReferenceElement(Shape::Quadrilateral, 1), ReferenceElement(Shape::Quadrilateral, 2),
      ReferenceElement(Shape::Tetrahedron, 1),   ReferenceElement(Shape::Tetrahedron, 2),
      ReferenceElement(Shape::Hexahedron, 1),    ReferenceElement(Shape::Hexahedron, 2)};
  const int index = 2 * (static_cast<int>(shape) - static_cast<int>(Shape::Triangle)) + order - 1;
  return elements[index];
}

void ReferenceElement::values(const double* xi, double* N) const {
  if (is_simplex(shape_)) {
    simplex_values(shape_, order_, entities_, xi, N);
  } else if (dim() == 2) {
    tensor_values<2>(order_, points_, xi, N);
  } else {
    tensor_values<3>(order_, points_, xi, N);
  }
}

void ReferenceElement::gradients(const double* xi, double* dN) const {
  if (is_simplex(shape_)) {
    simplex_gradients(shape_, order_, entities_, xi, dN);
  } else if (dim() == 2) {
    tensor_gradients<2>(order_, points_, xi, dN);
  } else {
    tensor_gradients<3>(order_, points_, xi, dN);
  }
}

}  // namespace pc

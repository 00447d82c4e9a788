#pragma once
// Quadrature rules on reference shapes, chosen by the polynomial degree they integrate exactly: total
// degree on simplices, degree in each coordinate on quadrilaterals and hexahedra. Weights sum to the
// reference measure (1/2 for the triangle, 1/6 for the tetrahedron, 1 for the unit square and cube).
#include <array>
#include <vector>

#include "assembly/shape.hpp"

namespace pc {

struct QuadratureRule {
  Shape shape;
  int degree;  // highest degree integrated exactly
  std::vector<std::array<double, 3>> points;
  std::vector<double> weights;
  int size() const { return static_cast<int>(weights.size()); }
};

inline constexpr int kMaxQuadratureDegree = 20;

// Shared, immutable rules; degree 0..kMaxQuadratureDegree, throws otherwise.
const QuadratureRule& quadrature(Shape shape, int degree);

}  // namespace pc

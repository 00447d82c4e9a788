// FESpace's pointwise derivatives: the physical shape gradients sum to zero (the shape functions are a
// partition of unity), and the gradient of an interpolated field its space holds exactly (affine for
// order 1, quadratic for order 2) is that field's gradient anywhere in a cell, on every shape.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "assembly/fe_space.hpp"
#include "assembly/mesh_generators.hpp"

namespace pc {
namespace {

struct Case {
  Shape shape;
  int order;
};

std::string name_of(const ::testing::TestParamInfo<Case>& info) {
  return to_string(info.param.shape) + "_P" + std::to_string(info.param.order);
}

class FESpaceDerivatives : public ::testing::TestWithParam<Case> {};

std::shared_ptr<const Mesh> mesh_for(Shape shape) {
  if (shape == Shape::Triangle || shape == Shape::Quadrilateral)
    return std::make_shared<const Mesh>(rectangle_mesh({0.1, -0.2}, {2.1, 0.6}, 5, 3, shape));
  return std::make_shared<const Mesh>(box_mesh({0.1, -0.2, 0.3}, {1.1, 0.6, 0.8}, 3, 2, 2, shape));
}

// f_0 = 1 + 2x - 3y + z + (order 2) x^2 + 3xy - y^2 - 2xz; f_1 = -x + 4y - z + (order 2) y z - z^2. The
// mixed terms lie in Q1 as well; on Q1 only the bilinear ones are kept.
struct Field {
  int dim;
  bool quadratic, bilinear_only;
  void value(const double* x, double* out) const {
    const double X = x[0], Y = x[1], Z = dim == 3 ? x[2] : 0.0;
    out[0] = 1 + 2 * X - 3 * Y + Z + 3 * X * Y * (quadratic || bilinear_only);
    out[1] = -X + 4 * Y - Z + (dim == 3) * Y * Z * (quadratic || bilinear_only);
    if (quadratic) {
      out[0] += X * X - Y * Y - 2 * X * Z;
      out[1] += -Z * Z;
    }
  }
  void gradient(const double* x, double* out) const {  // out[c * dim + d]
    const double X = x[0], Y = x[1], Z = dim == 3 ? x[2] : 0.0;
    const double m = (quadratic || bilinear_only) ? 1.0 : 0.0, q = quadratic ? 1.0 : 0.0;
    const double g0[3] = {2 + 3 * Y * m + q * (2 * X - 2 * Z), -3 + 3 * X * m - q * 2 * Y, 1 - q * 2 * X};
    const double g1[3] = {-1, 4 + (dim == 3) * Z * m, -1 + (dim == 3) * Y * m - q * 2 * Z};
    for (int d = 0; d < dim; ++d) {
      out[d] = g0[d];
      out[dim + d] = g1[d];
    }
  }
};

TEST_P(FESpaceDerivatives, ShapeGradientsSumToZeroAndReproduceTheFieldsGradient) {
  const Case c = GetParam();
  const auto mesh = mesh_for(c.shape);
  const int dim = mesh->dim();
  const FESpace space(mesh, c.order, 2);
  const bool tensor = c.shape == Shape::Quadrilateral || c.shape == Shape::Hexahedron;
  const Field field{dim, c.order == 2, tensor && c.order == 1};
  const Eigen::VectorXd f = space.interpolate([&](const double* x, double* out) { field.value(x, out); });
  const int nloc = space.element().num_dofs();
  std::vector<double> shape_gradients(size_t(nloc) * dim), gradient(2 * dim), exact(2 * dim);
  // Reference points inside every shape's reference cell (the simplices' and [-1, 1]^d or [0, 1]^d alike).
  const std::array<double, 3> xi{0.21, 0.17, 0.13};
  // The physical point of xi: the order-1 interpolant of x itself (the geometric map), evaluated there.
  const FESpace coordinates(mesh, 1, dim);
  const Eigen::VectorXd identity = coordinates.interpolate([&](const double* p, double* out) {
    for (int d = 0; d < dim; ++d) out[d] = p[d];
  });
  for (int cell = 0; cell < mesh->num_cells(); ++cell) {
    space.shape_gradients_in_cell(cell, xi.data(), shape_gradients.data());
    for (int d = 0; d < dim; ++d) {
      double sum = 0, size = 0;
      for (int i = 0; i < nloc; ++i) {
        sum += shape_gradients[size_t(i) * dim + d];
        size += std::abs(shape_gradients[size_t(i) * dim + d]);
      }
      EXPECT_LT(std::abs(sum), 1e-13 * size) << "cell " << cell << ", direction " << d;
    }
    std::array<double, 3> x{};
    coordinates.evaluate_in_cell(identity, cell, xi.data(), x.data());
    space.gradient_in_cell(f, cell, xi.data(), gradient.data());
    field.gradient(x.data(), exact.data());
    for (int a = 0; a < 2 * dim; ++a) EXPECT_NEAR(gradient[a], exact[a], 1e-12) << "cell " << cell << ", entry " << a;
  }
}

INSTANTIATE_TEST_SUITE_P(EachShape, FESpaceDerivatives,
                         ::testing::Values(Case{Shape::Triangle, 1}, Case{Shape::Triangle, 2},
                                           Case{Shape::Quadrilateral, 1}, Case{Shape::Quadrilateral, 2},
                                           Case{Shape::Tetrahedron, 1}, Case{Shape::Tetrahedron, 2},
                                           Case{Shape::Hexahedron, 1}, Case{Shape::Hexahedron, 2}),
                         name_of);

}  // namespace
}  // namespace pc

#include "assembly/reference_element.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "assembly/error.hpp"

namespace pc {
namespace {

struct ElementCase {
  Shape shape;
  int order;
  int num_dofs;
  int dofs_per_face;
};

constexpr ElementCase kElements[] = {{Shape::Triangle, 1, 3, 2},      {Shape::Triangle, 2, 6, 3},
                                     {Shape::Quadrilateral, 1, 4, 2}, {Shape::Quadrilateral, 2, 9, 3},
                                     {Shape::Tetrahedron, 1, 4, 3},   {Shape::Tetrahedron, 2, 10, 6},
                                     {Shape::Hexahedron, 1, 8, 4},    {Shape::Hexahedron, 2, 27, 9}};

std::string describe(const ElementCase& c) { return to_string(c.shape) + " order " + std::to_string(c.order); }

// Uniform random points of the reference cell (the simplex by rejection from the cube).
std::vector<std::array<double, 3>> random_points(Shape shape, int count) {
  std::mt19937 generator(12345);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<std::array<double, 3>> points;
  while (static_cast<int>(points.size()) < count) {
    std::array<double, 3> x{0, 0, 0};
    double sum = 0;
    for (int d = 0; d < dimension(shape); ++d) sum += x[d] = uniform(generator);
    if (!is_simplex(shape) || sum <= 1) points.push_back(x);
  }
  return points;
}

std::vector<double> values_at(const ReferenceElement& element, const std::array<double, 3>& x) {
  std::vector<double> N(element.num_dofs());
  element.values(x.data(), N.data());
  return N;
}

std::vector<double> gradients_at(const ReferenceElement& element, const std::array<double, 3>& x) {
  std::vector<double> dN(element.num_dofs() * element.dim());
  element.gradients(x.data(), dN.data());
  return dN;
}

TEST(ReferenceElement, ReportsShapeOrderAndDofCount) {
  for (const auto& c : kElements) {
    const ReferenceElement& element = ReferenceElement::get(c.shape, c.order);
    EXPECT_EQ(element.shape(), c.shape);
    EXPECT_EQ(element.order(), c.order);
    EXPECT_EQ(element.dim(), dimension(c.shape));
    EXPECT_EQ(element.num_dofs(), c.num_dofs) << describe(c);
    EXPECT_EQ(&element, &ReferenceElement::get(c.shape, c.order)) << "instances are shared";
  }
}

TEST(ReferenceElement, RejectsUnknownOrdersAndNonCellShapes) {
  EXPECT_THROW(ReferenceElement::get(Shape::Triangle, 0), Error);
  EXPECT_THROW(ReferenceElement::get(Shape::Hexahedron, 3), Error);
  EXPECT_THROW(ReferenceElement::get(Shape::Segment, 1), Error);
  EXPECT_THROW(ReferenceElement::get(Shape::Point, 1), Error);
  try {
    ReferenceElement::get(Shape::Tetrahedron, 3);
    ADD_FAILURE() << "order 3 was accepted";
  } catch (const Error& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("tetrahedron"), std::string::npos) << what;
    EXPECT_NE(what.find('3'), std::string::npos) << what;
  }
}

// Dofs follow VTK's node order: vertices, edge midpoints, face centres, cell centre.
TEST(ReferenceElement, DofsFollowVtkNodeOrder) {
  for (const auto& c : kElements) {
    const ReferenceElement& element = ReferenceElement::get(c.shape, c.order);
    int i = 0;
    for (int v = 0; v < num_vertices(c.shape); ++v, ++i) {
      EXPECT_EQ(element.dof_entity(i).dim, 0);
      EXPECT_EQ(element.dof_entity(i).index, v);
      EXPECT_EQ(element.dof_point(i), reference_vertex(c.shape, v)) << describe(c) << " dof " << i;
    }
    if (c.order == 1) continue;
    for (int e = 0; e < num_edges(c.shape); ++e, ++i) {
      EXPECT_EQ(element.dof_entity(i).dim, 1);
      EXPECT_EQ(element.dof_entity(i).index, e);
      const auto a = reference_vertex(c.shape, edge_vertices(c.shape, e)[0]);
      const auto b = reference_vertex(c.shape, edge_vertices(c.shape, e)[1]);
      for (int d = 0; d < 3; ++d) EXPECT_EQ(element.dof_point(i)[d], 0.5 * (a[d] + b[d])) << describe(c);
    }
    if (is_simplex(c.shape)) {
      EXPECT_EQ(i, element.num_dofs()) << describe(c);
      continue;
    }
    if (c.shape == Shape::Hexahedron) {
      // VTK_TRIQUADRATIC_HEXAHEDRON face centres: x = 0, x = 1, y = 0, y = 1, z = 0, z = 1.
      const std::array<double, 3> centres[6] = {{0, 0.5, 0.5}, {1, 0.5, 0.5}, {0.5, 0, 0.5},
                                                {0.5, 1, 0.5}, {0.5, 0.5, 0}, {0.5, 0.5, 1}};
      for (int f = 0; f < 6; ++f, ++i) {
        EXPECT_EQ(element.dof_entity(i).dim, 2);
        EXPECT_EQ(element.dof_entity(i).index, f);
        EXPECT_EQ(element.dof_point(i), centres[f]) << "face " << f;
      }
    }
    EXPECT_EQ(element.dof_entity(i).dim, element.dim());
    EXPECT_EQ(element.dof_entity(i).index, 0);
    const std::array<double, 3> centre{0.5, 0.5, element.dim() == 3 ? 0.5 : 0.0};
    EXPECT_EQ(element.dof_point(i), centre);
    EXPECT_EQ(i + 1, element.num_dofs()) << describe(c);
  }
}

TEST(ReferenceElement, IsKroneckerAtDofPoints) {
  for (const auto& c : kElements) {
    const ReferenceElement& element = ReferenceElement::get(c.shape, c.order);
    for (int i = 0; i < element.num_dofs(); ++i) {
      const auto N = values_at(element, element.dof_point(i));
      for (int j = 0; j < element.num_dofs(); ++j) {
        EXPECT_NEAR(N[j], i == j ? 1.0 : 0.0, 1e-14) << describe(c) << " N_" << j << " at node " << i;
      }
    }
  }
}

TEST(ReferenceElement, IsPartitionOfUnityWithGradientsSummingToZero) {
  for (const auto& c : kElements) {
    const ReferenceElement& element = ReferenceElement::get(c.shape, c.order);
    for (const auto& x : random_points(c.shape, 20)) {
      double sum = 0;
      for (const double n : values_at(element, x)) sum += n;
      EXPECT_NEAR(sum, 1.0, 1e-14) << describe(c);
      const auto dN = gradients_at(element, x);
      for (int d = 0; d < element.dim(); ++d) {
        double gradient_sum = 0;
        for (int i = 0; i < element.num_dofs(); ++i) gradient_sum += dN[i * element.dim() + d];
        EXPECT_NEAR(gradient_sum, 0.0, 1e-13) << describe(c) << " axis " << d;
      }
    }
  }
}

TEST(ReferenceElement, GradientsMatchCentralDifferences) {
  const double h = 1e-5;
  for (const auto& c : kElements) {
    const ReferenceElement& element = ReferenceElement::get(c.shape, c.order);
    for (const auto& x : random_points(c.shape, 10)) {
      const auto dN = gradients_at(element, x);
      for (int d = 0; d < element.dim(); ++d) {
        auto plus = x, minus = x;
        plus[d] += h;
        minus[d] -= h;
        const auto N_plus = values_at(element, plus), N_minus = values_at(element, minus);
        for (int i = 0; i < element.num_dofs(); ++i) {
          EXPECT_NEAR(dN[i * element.dim() + d], (N_plus[i] - N_minus[i]) / (2 * h), 1e-7)
              << describe(c) << " dN_" << i << "/dx_" << d;
        }
      }
    }
  }
}

// The element's polynomial space: total degree <= order on simplices, degree <= order per axis otherwise.
std::vector<std::array<int, 3>> element_monomials(const ElementCase& c) {
  const int dim = dimension(c.shape);
  std::vector<std::array<int, 3>> monomials;
  for (int a = 0; a <= c.order; ++a) {
    for (int b = 0; b <= (dim >= 2 ? c.order : 0); ++b) {
      for (int e = 0; e <= (dim >= 3 ? c.order : 0); ++e) {
        if (is_simplex(c.shape) && a + b + e > c.order) continue;
        monomials.push_back({a, b, e});
      }
    }
  }
  return monomials;
}

double monomial(const std::array<int, 3>& e, const std::array<double, 3>& x) {
  return std::pow(x[0], e[0]) * std::pow(x[1], e[1]) * std::pow(x[2], e[2]);
}

double monomial_derivative(const std::array<int, 3>& e, const std::array<double, 3>& x, int d) {
  if (e[d] == 0) return 0;
  auto lowered = e;
  --lowered[d];
  return e[d] * monomial(lowered, x);
}

TEST(ReferenceElement, ReproducesItsPolynomialSpaceExactly) {
  for (const auto& c : kElements) {
    const ReferenceElement& element = ReferenceElement::get(c.shape, c.order);
    const auto monomials = element_monomials(c);
    EXPECT_EQ(static_cast<int>(monomials.size()), element.num_dofs()) << describe(c);
    for (const auto& e : monomials) {
      std::vector<double> nodal(element.num_dofs());
      for (int i = 0; i < element.num_dofs(); ++i) nodal[i] = monomial(e, element.dof_point(i));
      for (const auto& x : random_points(c.shape, 10)) {
        const auto N = values_at(element, x);
        const auto dN = gradients_at(element, x);
        double value = 0;
        std::array<double, 3> gradient{0, 0, 0};
        for (int i = 0; i < element.num_dofs(); ++i) {
          value += nodal[i] * N[i];
          for (int d = 0; d < element.dim(); ++d) gradient[d] += nodal[i] * dN[i * element.dim() + d];
        }
        EXPECT_NEAR(value, monomial(e, x), 1e-13) << describe(c);
        for (int d = 0; d < element.dim(); ++d) {
          EXPECT_NEAR(gradient[d], monomial_derivative(e, x, d), 1e-12) << describe(c) << " axis " << d;
        }
      }
    }
  }
}

TEST(ReferenceElement, FaceDofsAreExactlyTheFunctionsAliveOnTheFace) {
  for (const auto& c : kElements) {
    const ReferenceElement& element = ReferenceElement::get(c.shape, c.order);
    for (int f = 0; f < num_faces(c.shape); ++f) {
      const auto dofs = element.face_dofs(f);
      EXPECT_EQ(static_cast<int>(dofs.size()), c.dofs_per_face) << describe(c) << " face " << f;
      EXPECT_TRUE(std::is_sorted(dofs.begin(), dofs.end())) << describe(c) << " face " << f;
      std::vector<bool> on_face(element.num_dofs(), false);
      for (const int i : dofs) on_face[i] = true;
      for (const auto& s : random_points(face_shape(c.shape, f), 10)) {
        const auto x = face_to_cell(c.shape, f, s.data());
        const auto N = values_at(element, x);
        double face_sum = 0;
        for (int i = 0; i < element.num_dofs(); ++i) {
          if (on_face[i]) {
            face_sum += N[i];
          } else {
            EXPECT_NEAR(N[i], 0.0, 1e-14) << describe(c) << " face " << f << " dof " << i;
          }
        }
        // The face functions alone form a partition of unity on the face, so they do not all vanish.
        EXPECT_NEAR(face_sum, 1.0, 1e-14) << describe(c) << " face " << f;
      }
    }
  }
}

TEST(ReferenceElement, FaceDofsOfTheQuadraticTriangleAndHexahedron) {
  const ReferenceElement& triangle = ReferenceElement::get(Shape::Triangle, 2);
  const auto edge0 = triangle.face_dofs(0);
  EXPECT_EQ(std::vector<int>(edge0.begin(), edge0.end()), (std::vector<int>{0, 1, 3}));
  const auto edge2 = triangle.face_dofs(2);
  EXPECT_EQ(std::vector<int>(edge2.begin(), edge2.end()), (std::vector<int>{0, 2, 5}));
  // Hexahedron face 0 (x = 0): vertices 0 3 4 7, edges 3 7 8 11, its face centre 20.
  const auto face0 = ReferenceElement::get(Shape::Hexahedron, 2).face_dofs(0);
  EXPECT_EQ(std::vector<int>(face0.begin(), face0.end()), (std::vector<int>{0, 3, 4, 7, 11, 15, 16, 19, 20}));
}

}  // namespace
}  // namespace pc

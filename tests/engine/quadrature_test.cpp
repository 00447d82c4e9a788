#include "assembly/quadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "assembly/error.hpp"

namespace pc {
namespace {

constexpr Shape kCells[] = {Shape::Segment, Shape::Triangle, Shape::Quadrilateral, Shape::Tetrahedron,
                            Shape::Hexahedron};

double factorial(int n) {
  double f = 1;
  for (int k = 2; k <= n; ++k) f *= k;
  return f;
}

// Exact integral of x^e[0] y^e[1] z^e[2] over the reference shape.
double exact_monomial_integral(Shape shape, const std::array<int, 3>& e) {
  switch (shape) {
    case Shape::Segment:
    case Shape::Quadrilateral:
    case Shape::Hexahedron: {
      double integral = 1;
      for (int d = 0; d < dimension(shape); ++d) integral /= e[d] + 1;
      return integral;
    }
    case Shape::Triangle: return factorial(e[0]) * factorial(e[1]) / factorial(e[0] + e[1] + 2);
    case Shape::Tetrahedron:
      return factorial(e[0]) * factorial(e[1]) * factorial(e[2]) / factorial(e[0] + e[1] + e[2] + 3);
    default: break;
  }
  ADD_FAILURE() << "no closed form on a " << to_string(shape);
  return 0;
}

// Applies a rule to monomials x^e[0] y^e[1] z^e[2], with the coordinates' powers tabulated once.
class MonomialIntegrator {
 public:
  MonomialIntegrator(const QuadratureRule& rule, int max_exponent)
      : rule_(rule), max_exponent_(max_exponent), powers_(rule.size() * 3 * (max_exponent + 1)) {
    for (int q = 0; q < rule.size(); ++q) {
      for (int d = 0; d < 3; ++d) {
        double power = 1;
        for (int k = 0; k <= max_exponent; ++k, power *= rule.points[q][d]) powers_[index(q, d, k)] = power;
      }
    }
  }

  double integrate(const std::array<int, 3>& e) const {
    double sum = 0;
    for (int q = 0; q < rule_.size(); ++q) {
      sum += rule_.weights[q] * powers_[index(q, 0, e[0])] * powers_[index(q, 1, e[1])] * powers_[index(q, 2, e[2])];
    }
    return sum;
  }

 private:
  int index(int q, int d, int k) const { return (q * 3 + d) * (max_exponent_ + 1) + k; }

  const QuadratureRule& rule_;
  int max_exponent_;
  std::vector<double> powers_;
};

// Monomials a rule of the given degree must integrate exactly: total degree on simplices, degree per
// coordinate on quadrilaterals and hexahedra.
std::vector<std::array<int, 3>> exact_monomials(Shape shape, int degree) {
  const int dim = dimension(shape);
  std::vector<std::array<int, 3>> monomials;
  for (int a = 0; a <= degree; ++a) {
    for (int b = 0; b <= (dim >= 2 ? degree : 0); ++b) {
      for (int c = 0; c <= (dim >= 3 ? degree : 0); ++c) {
        if (is_simplex(shape) && a + b + c > degree) continue;
        monomials.push_back({a, b, c});
      }
    }
  }
  return monomials;
}

bool inside_reference(Shape shape, const std::array<double, 3>& x) {
  const int dim = dimension(shape);
  double sum = 0;
  for (int d = 0; d < 3; ++d) {
    if (d >= dim && x[d] != 0) return false;
    if (x[d] < 0 || x[d] > 1) return false;
    sum += x[d];
  }
  return !is_simplex(shape) || sum <= 1 + 1e-15;
}

TEST(Quadrature, IntegratesEveryMonomialOfItsDegreeExactly) {
  for (const Shape shape : kCells) {
    for (int degree = 0; degree <= kMaxQuadratureDegree; ++degree) {
      const MonomialIntegrator integrator(quadrature(shape, degree), degree);
      for (const auto& e : exact_monomials(shape, degree)) {
        const double exact = exact_monomial_integral(shape, e);
        EXPECT_NEAR(integrator.integrate(e), exact, 1e-13 * exact)
            << to_string(shape) << " degree " << degree << " monomial x^" << e[0] << " y^" << e[1] << " z^" << e[2];
      }
    }
  }
}

TEST(Quadrature, OddDegreesAreTight) {
  // Gauss rules of odd degree use the fewest points, so x^(degree + 1) is no longer exact; so are the
  // symmetric degree-2 simplex rules. The error shrinks fast with the degree but stays far above round-off.
  for (const Shape shape : kCells) {
    for (int degree = 1; degree <= kMaxQuadratureDegree; ++degree) {
      const bool symmetric_rule = degree == 2 && (shape == Shape::Triangle || shape == Shape::Tetrahedron);
      if (degree % 2 == 0 && !symmetric_rule) continue;
      const MonomialIntegrator integrator(quadrature(shape, degree), degree + 1);
      const std::array<int, 3> e{degree + 1, 0, 0};
      const double exact = exact_monomial_integral(shape, e);
      EXPECT_GT(std::abs(integrator.integrate(e) - exact), 1e-11 * exact) << to_string(shape) << " degree " << degree;
    }
  }
}

TEST(Quadrature, WeightsArePositiveAndPointsInsideTheReferenceShape) {
  for (const Shape shape : kCells) {
    for (int degree = 0; degree <= kMaxQuadratureDegree; ++degree) {
      const QuadratureRule& rule = quadrature(shape, degree);
      EXPECT_EQ(rule.shape, shape);
      EXPECT_EQ(rule.degree, degree);
      ASSERT_EQ(rule.points.size(), rule.weights.size());
      ASSERT_GT(rule.size(), 0);
      for (int q = 0; q < rule.size(); ++q) {
        EXPECT_GT(rule.weights[q], 0) << to_string(shape) << " degree " << degree << " point " << q;
        EXPECT_TRUE(inside_reference(shape, rule.points[q]))
            << to_string(shape) << " degree " << degree << " point " << q;
      }
    }
  }
}

// Tolerances of two units in the last place.
TEST(Quadrature, GaussLegendreMatchesKnownNodesToFullPrecision) {
  const QuadratureRule& two = quadrature(Shape::Segment, 3);
  ASSERT_EQ(two.size(), 2);
  EXPECT_NEAR(two.points[0][0], 0.5 - 0.5 / std::sqrt(3.0), 2.3e-16);
  EXPECT_NEAR(two.points[1][0], 0.5 + 0.5 / std::sqrt(3.0), 2.3e-16);
  EXPECT_NEAR(two.weights[0], 0.5, 2.3e-16);
  EXPECT_NEAR(two.weights[1], 0.5, 2.3e-16);
  const QuadratureRule& three = quadrature(Shape::Segment, 5);
  ASSERT_EQ(three.size(), 3);
  const double offset = 0.5 * std::sqrt(0.6);
  EXPECT_NEAR(three.points[0][0], 0.5 - offset, 2.3e-16);
  EXPECT_NEAR(three.points[1][0], 0.5, 2.3e-16);
  EXPECT_NEAR(three.points[2][0], 0.5 + offset, 2.3e-16);
  EXPECT_NEAR(three.weights[0], 5.0 / 18, 2.3e-16);
  EXPECT_NEAR(three.weights[1], 4.0 / 9, 2.3e-16);
  EXPECT_NEAR(three.weights[2], 5.0 / 18, 2.3e-16);
}

TEST(Quadrature, RuleSizesAreCompact) {
  EXPECT_EQ(quadrature(Shape::Segment, 3).size(), 2);
  EXPECT_EQ(quadrature(Shape::Quadrilateral, 20).size(), 121);
  EXPECT_EQ(quadrature(Shape::Hexahedron, 2).size(), 8);
  EXPECT_EQ(quadrature(Shape::Triangle, 1).size(), 1);
  EXPECT_EQ(quadrature(Shape::Triangle, 2).size(), 3);
  EXPECT_EQ(quadrature(Shape::Triangle, 5).size(), 9);
  EXPECT_EQ(quadrature(Shape::Tetrahedron, 1).size(), 1);
  EXPECT_EQ(quadrature(Shape::Tetrahedron, 2).size(), 4);
  EXPECT_EQ(quadrature(Shape::Tetrahedron, 3).size(), 8);
}

TEST(Quadrature, PointRuleIsOneUnitPoint) {
  for (int degree = 0; degree <= kMaxQuadratureDegree; ++degree) {
    const QuadratureRule& rule = quadrature(Shape::Point, degree);
    ASSERT_EQ(rule.size(), 1);
    EXPECT_EQ(rule.weights[0], 1.0);
    EXPECT_EQ(rule.degree, degree);
  }
}

TEST(Quadrature, RulesAreSharedInstances) {
  EXPECT_EQ(&quadrature(Shape::Tetrahedron, 7), &quadrature(Shape::Tetrahedron, 7));
}

TEST(Quadrature, RejectsDegreesOutOfRangeNamingShapeAndDegree) {
  for (const int degree : {-1, kMaxQuadratureDegree + 1}) {
    try {
      quadrature(Shape::Tetrahedron, degree);
      ADD_FAILURE() << "degree " << degree << " was accepted";
    } catch (const Error& error) {
      const std::string what = error.what();
      EXPECT_NE(what.find("tetrahedron"), std::string::npos) << what;
      EXPECT_NE(what.find(std::to_string(degree)), std::string::npos) << what;
    }
  }
}

// A point of a face and the normal of its line (2D) or plane (3D), not normalised.
struct FaceFrame {
  std::array<double, 3> origin;
  std::array<double, 3> normal;
};

std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

std::array<double, 3> difference(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double norm(const std::array<double, 3>& a) { return std::sqrt(dot(a, a)); }

FaceFrame face_frame(Shape cell, int face) {
  const auto vertices = face_vertices(cell, face);
  const auto v0 = reference_vertex(cell, vertices[0]);
  switch (dimension(cell)) {
    case 1: return {v0, {1, 0, 0}};
    case 2: {
      const auto t = difference(reference_vertex(cell, vertices[1]), v0);
      return {v0, {-t[1], t[0], 0}};
    }
    default:
      return {v0, cross(difference(reference_vertex(cell, vertices[1]), v0),
                        difference(reference_vertex(cell, vertices[2]), v0))};
  }
}

// |d x / d s| of the face map: length, area or (for a point face) one. Central differences are exact
// here up to round-off since the face maps are affine or bilinear.
double face_map_jacobian(Shape cell, int face, const std::array<double, 3>& s) {
  const int face_dim = dimension(cell) - 1;
  if (face_dim == 0) return 1;
  const double h = 1e-3;
  std::array<std::array<double, 3>, 2> tangent{};
  for (int k = 0; k < face_dim; ++k) {
    auto plus = s, minus = s;
    plus[k] += h;
    minus[k] -= h;
    const auto xp = face_to_cell(cell, face, plus.data());
    const auto xm = face_to_cell(cell, face, minus.data());
    for (int d = 0; d < 3; ++d) tangent[k][d] = (xp[d] - xm[d]) / (2 * h);
  }
  return face_dim == 1 ? norm(tangent[0]) : norm(cross(tangent[0], tangent[1]));
}

double expected_face_measure(Shape cell, int face) {
  if (cell == Shape::Triangle && face == 1) return std::sqrt(2.0);
  if (cell == Shape::Tetrahedron) return face == 3 ? std::sqrt(3.0) / 2 : 0.5;
  return 1;
}

// Face rules mapped into the cell: the points lie on the face and the weights, scaled by the area ratio
// of the face map, add up to the face's measure.
TEST(Quadrature, FaceRulesMapOntoTheFacesWithTheirMeasure) {
  for (const Shape cell : kCells) {
    for (int face = 0; face < num_faces(cell); ++face) {
      const FaceFrame frame = face_frame(cell, face);
      const double unit = norm(frame.normal);
      for (const int degree : {0, 2, 5}) {
        const QuadratureRule& rule = quadrature(face_shape(cell, face), degree);
        double measure = 0;
        std::array<double, 3> moment{0, 0, 0};
        for (int q = 0; q < rule.size(); ++q) {
          const auto x = face_to_cell(cell, face, rule.points[q].data());
          EXPECT_NEAR(dot(difference(x, frame.origin), frame.normal) / unit, 0, 1e-14)
              << to_string(cell) << " face " << face;
          EXPECT_TRUE(inside_reference(cell, x)) << to_string(cell) << " face " << face;
          const double w = rule.weights[q] * face_map_jacobian(cell, face, rule.points[q]);
          measure += w;
          for (int d = 0; d < 3; ++d) moment[d] += w * x[d];
        }
        EXPECT_NEAR(measure, expected_face_measure(cell, face), 1e-12) << to_string(cell) << " face " << face;
        // Triangles, squares and points have their centroid at the mean of their vertices.
        const auto vertices = face_vertices(cell, face);
        for (int d = 0; d < 3; ++d) {
          double mean = 0;
          for (const int v : vertices) mean += reference_vertex(cell, v)[d] / double(vertices.size());
          EXPECT_NEAR(moment[d] / measure, mean, 1e-12) << to_string(cell) << " face " << face << " axis " << d;
        }
      }
    }
  }
}

}  // namespace
}  // namespace pc

#include "assembly/quadrature.hpp"

#include <cmath>
#include <limits>

#include "assembly/error.hpp"

namespace pc {
namespace {

// Gauss nodes and weights are computed in extended precision and then rounded, so that the round-off of
// the recurrences stays below the last bit of a double.
using Real = long double;

// Three-term recurrence of the monic polynomials orthogonal for the weight (1 - x)^alpha on [0, 1]:
// q_{k+1}(x) = (x - a_k) q_k(x) - b_k q_{k-1}(x). It is the Jacobi (alpha, 0) recurrence on [-1, 1]
// carried over by x = (t + 1) / 2.
struct Recurrence {
  std::vector<Real> a;
  std::vector<Real> b;  // b[0] is unused
  Real mass;            // integral of the weight, the squared norm of q_0
};

Recurrence jacobi_recurrence(int alpha, int n) {
  Recurrence r{std::vector<Real>(n), std::vector<Real>(n, 0), Real(1) / (alpha + 1)};
  for (int k = 0; k < n; ++k) {
    const Real s = 2 * k + alpha;
    // The general formula is 0/0 for k = 0 and alpha = 0; its limit is the k = 0 expression.
    const Real a_on_symmetric = k == 0 ? -alpha / (alpha + Real(2)) : -alpha * alpha / (s * (s + 2));
    r.a[k] = (1 + a_on_symmetric) / 2;
    if (k > 0) r.b[k] = Real(k) * k * (k + alpha) * (k + alpha) / (s * s * (s + 1) * (s - 1));
  }
  return r;
}

struct PolynomialValue {
  Real value;
  Real derivative;
};

PolynomialValue evaluate(const Recurrence& r, int m, Real x) {
  Real q_previous = 0, q = 1, dq_previous = 0, dq = 0;
  for (int k = 0; k < m; ++k) {
    const Real q_next = (x - r.a[k]) * q - r.b[k] * q_previous;
    const Real dq_next = q + (x - r.a[k]) * dq - r.b[k] * dq_previous;
    q_previous = q;
    q = q_next;
    dq_previous = dq;
    dq = dq_next;
  }
  return {q, dq};
}

// The root of q_m in (lo, hi), where q_m changes sign once: Newton's method, falling back to bisection
// whenever a step would leave the shrinking bracket, so it always converges.
Real bracketed_root(const Recurrence& r, int m, Real lo, Real hi) {
  const bool negative_at_lo = evaluate(r, m, lo).value < 0;
  Real x = (lo + hi) / 2;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const auto [q, dq] = evaluate(r, m, x);
    if (q == 0) return x;
    if ((q < 0) == negative_at_lo) {
      lo = x;
    } else {
      hi = x;
    }
    Real next = x - q / dq;
    if (!(next > lo && next < hi)) next = (lo + hi) / 2;
    if (std::abs(next - x) <= 2 * std::numeric_limits<Real>::epsilon() * x) return next;
    x = next;
  }
  return x;
}

// The roots of q_n, increasing. The roots of q_{m-1} separate those of q_m, so each degree's roots
// bracket the next degree's ones.
std::vector<Real> roots(const Recurrence& r, int n) {
  std::vector<Real> previous;
  for (int m = 1; m <= n; ++m) {
    std::vector<Real> current(m);
    for (int i = 0; i < m; ++i) {
      const Real lo = i == 0 ? 0 : previous[i - 1];
      const Real hi = i == m - 1 ? 1 : previous[i];
      current[i] = bracketed_root(r, m, lo, hi);
    }
    previous = std::move(current);
  }
  return previous;
}

// n-point Gauss rule on [0, 1] for the weight (1 - x)^alpha, exact up to degree 2n - 1. alpha = 0 is
// Gauss-Legendre; alpha = 1 and 2 absorb the Jacobians of the collapsed simplex maps.
struct GaussRule {
  std::vector<double> points;
  std::vector<double> weights;
};

GaussRule gauss_rule(int alpha, int n) {
  const Recurrence r = jacobi_recurrence(alpha, n);
  GaussRule rule;
  for (const Real x : roots(r, n)) {
    // Christoffel number 1 / sum_k q_k(x)^2 / |q_k|^2: a sum of positive terms, hence accurate and positive.
    Real q_previous = 0, q = 1, norm = r.mass, sum = 1 / r.mass;
    for (int k = 0; k + 1 < n; ++k) {
      const Real q_next = (x - r.a[k]) * q - r.b[k] * q_previous;
      q_previous = q;
      q = q_next;
      norm *= r.b[k + 1];
      sum += q * q / norm;
    }
    rule.points.push_back(static_cast<double>(x));
    rule.weights.push_back(static_cast<double>(1 / sum));
  }
  return rule;
}

// Gauss points per direction for exactness up to the degree: 2n - 1 >= degree.
int points_per_direction(int degree) { return degree / 2 + 1; }

QuadratureRule tensor_rule(Shape shape, int degree) {
  const GaussRule gauss = gauss_rule(0, points_per_direction(degree));
  const int n = static_cast<int>(gauss.points.size());
  const int dim = dimension(shape);
  QuadratureRule rule{shape, degree, {}, {}};
  int count = 1;
  for (int d = 0; d < dim; ++d) count *= n;
  for (int index = 0; index < count; ++index) {
    std::array<double, 3> point{0, 0, 0};
    double weight = 1;
    for (int d = 0, stride = 1; d < dim; ++d, stride *= n) {
      const int k = index / stride % n;
      point[d] = gauss.points[k];
      weight *= gauss.weights[k];
    }
    rule.points.push_back(point);
    rule.weights.push_back(weight);
  }
  return rule;
}

// Collapsed (Duffy) rule: x = u, y = (1 - u) v maps the unit square onto the triangle with Jacobian
// 1 - u, which the Gauss-Jacobi weight in u absorbs.
QuadratureRule collapsed_triangle_rule(int degree) {
  const int n = points_per_direction(degree);
  const GaussRule gu = gauss_rule(1, n), gv = gauss_rule(0, n);
  QuadratureRule rule{Shape::Triangle, degree, {}, {}};
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double u = gu.points[i], v = gv.points[j];
      rule.points.push_back({u, (1 - u) * v, 0});
      rule.weights.push_back(gu.weights[i] * gv.weights[j]);
    }
  }
  return rule;
}

// Collapsed rule on the tetrahedron: x = u, y = (1 - u) v, z = (1 - u)(1 - v) w, Jacobian (1 - u)^2 (1 - v).
QuadratureRule collapsed_tetrahedron_rule(int degree) {
  const int n = points_per_direction(degree);
  const GaussRule gu = gauss_rule(2, n), gv = gauss_rule(1, n), gw = gauss_rule(0, n);
  QuadratureRule rule{Shape::Tetrahedron, degree, {}, {}};
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const double u = gu.points[i], v = gv.points[j], w = gw.points[k];
        rule.points.push_back({u, (1 - u) * v, (1 - u) * (1 - v) * w});
        rule.weights.push_back(gu.weights[i] * gv.weights[j] * gw.weights[k]);
      }
    }
  }
  return rule;
}

// Symmetric rules with fewer points than the collapsed ones for the low degrees used most.
QuadratureRule triangle_rule(int degree) {
  if (degree <= 1) return {Shape::Triangle, degree, {{1.0 / 3, 1.0 / 3, 0}}, {0.5}};
  if (degree == 2) {
    return {Shape::Triangle,
            degree,
            {{1.0 / 6, 1.0 / 6, 0}, {2.0 / 3, 1.0 / 6, 0}, {1.0 / 6, 2.0 / 3, 0}},
            {1.0 / 6, 1.0 / 6, 1.0 / 6}};
  }
  return collapsed_triangle_rule(degree);
}

QuadratureRule tetrahedron_rule(int degree) {
  if (degree <= 1) return {Shape::Tetrahedron, degree, {{0.25, 0.25, 0.25}}, {1.0 / 6}};
  if (degree == 2) {
    const double a = (5 - std::sqrt(5.0)) / 20, b = (5 + 3 * std::sqrt(5.0)) / 20;
    return {Shape::Tetrahedron,
            degree,
            {{a, a, a}, {b, a, a}, {a, b, a}, {a, a, b}},
            {1.0 / 24, 1.0 / 24, 1.0 / 24, 1.0 / 24}};
  }
  return collapsed_tetrahedron_rule(degree);
}

QuadratureRule make_rule(Shape shape, int degree) {
  switch (shape) {
    case Shape::Point: return {Shape::Point, degree, {{0, 0, 0}}, {1}};
    case Shape::Segment:
    case Shape::Quadrilateral:
    case Shape::Hexahedron: return tensor_rule(shape, degree);
    case Shape::Triangle: return triangle_rule(degree);
    case Shape::Tetrahedron: return tetrahedron_rule(degree);
  }
  fail("no quadrature rule on a ", to_string(shape));
}

// In the enumeration's order, so that rules[int(shape)] holds the shape's rules.
constexpr Shape kShapes[] = {Shape::Point,         Shape::Segment,     Shape::Triangle,
                             Shape::Quadrilateral, Shape::Tetrahedron, Shape::Hexahedron};

std::vector<std::vector<QuadratureRule>> make_all_rules() {
  std::vector<std::vector<QuadratureRule>> rules;
  for (const Shape shape : kShapes) {
    rules.emplace_back();
    for (int degree = 0; degree <= kMaxQuadratureDegree; ++degree) {
      rules.back().push_back(make_rule(shape, degree));
    }
  }
  return rules;
}

}  // namespace

const QuadratureRule& quadrature(Shape shape, int degree) {
  require(degree >= 0 && degree <= kMaxQuadratureDegree, "no quadrature rule of degree ", degree, " on a ",
          to_string(shape), ": degrees 0 to ", kMaxQuadratureDegree, " are available");
  // All rules are built together on first use (about ten milliseconds); initialising a local static is
  // thread-safe.
  static const std::vector<std::vector<QuadratureRule>> rules = make_all_rules();
  const int index = static_cast<int>(shape);
  require(index >= 0 && index < static_cast<int>(rules.size()), "no quadrature rule of degree ", degree, " on a ",
          to_string(shape));
  return rules[index][degree];
}

}  // namespace pc

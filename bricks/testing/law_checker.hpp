#pragma once
// A harness that checks a constitutive law alone, for the project's tests and for users' own laws:
//
//   struct Quadratic {  // p(r) = r_+^2
//     static constexpr bool dissipative = true;
//     template <class S> S operator()(const S& r) const { return r < 0.0 ? S(0.0) : r * r; }
//   };
//   TEST(MyLaws, Quadratic) {
//     auto report = pc::check_scalar_law(Quadratic{});
//     EXPECT_TRUE(report.ok()) << report;
//   }
//
// Checked, each as the options set:
//  - the law's parameter values lie in the ranges it declares (a law that declares none passes);
//  - its Dual derivatives against central finite differences at random arguments away from kinks, and at
//    each kink against right-sided finite differences (the library's laws take the right-sided derivative);
//  - its `affine` claim: f(x) = f(0) + f'(0) x at random x;
//  - its `dissipative` claim: p(r) r >= 0 (scalar laws), p(r) . r >= 0 (friction laws), monotone in phi
//    (foundation laws), at random arguments of magnitudes dissipation_scales;
//  - finite values and derivatives at extreme arguments (both signs of each magnitude, and zero).
// Friction laws are checked in 2D and 3D. The derivative checks use three finite-difference steps
// (h, h / 10, h / 100) and keep the best match, so that curvature or round-off does not fake a failure;
// a wrong derivative matches at none of them.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "assembly/dual.hpp"
#include "assembly/error.hpp"
#include "bricks/laws/law_parameters.hpp"
#include "bricks/laws/law_traits.hpp"

namespace pc {

struct LawCheckOptions {
  std::string name = "law";  // names the law in the report
  int samples = 40;
  unsigned seed = 2024;
  double low = -2, high = 2;  // random arguments: r (each component), or phi for foundation laws
  double pressure_high = 2;   // random normal pressures from [0, pressure_high]
  // Scalar laws: arguments where the law has a kink. Friction and foundation laws: pressures where it has
  // one. Random arguments keep kink_clearance away from them (and friction velocities from |r| = 0).
  std::vector<double> kinks = {0};
  double kink_clearance = 1e-3;
  bool derivatives = true;  // false for parameters too extreme for finite differences to resolve
  double fd_step = 1e-6;    // relative to max(1, |x|)
  double tolerance = 1e-6;  // on max |dual - fd| / max(|dual|, |fd|) over the Jacobian's entries
  double affine_tolerance = 1e-12;
  std::vector<double> dissipation_scales = {1e-3, 1, 1e3, 1e6};
  std::vector<double> extremes = {1e-300, 1e-12, 1e12, 1e150};
};

struct LawCheckReport {
  std::string law;
  int checks = 0;
  double max_derivative_error = 0;
  std::vector<std::string> failures;
  bool ok() const { return failures.empty(); }
};

inline std::ostream& operator<<(std::ostream& out, const LawCheckReport& report) {
  out << report.law << ": " << report.checks << " checks, max derivative error " << report.max_derivative_error;
  constexpr int kShown = 10;
  for (int i = 0; i < int(report.failures.size()) && i < kShown; ++i) out << "\n  - " << report.failures[i];
  if (int(report.failures.size()) > kShown) out << "\n  ... and " << report.failures.size() - kShown << " more";
  return out;
}

namespace law_check {

inline constexpr int kMaxInputs = 4;   // friction in 3D: r and the pressure
inline constexpr int kMaxOutputs = 3;  // friction in 3D
using CheckDual = Dual<kMaxInputs>;
using Point = std::array<double, kMaxInputs>;
using Values = std::array<double, kMaxOutputs>;
using Jacobian = std::array<Point, kMaxOutputs>;  // [output][input]

// A law seen as a map of n inputs to m outputs; evaluate(const S* x, S* out) is generic in the scalar.
template <class Evaluate>
struct LawMap {
  Evaluate evaluate;
  int n;
  int m;
  std::string what;  // e.g. "friction law (3D)", prefixes failure messages

  Values values(const Point& x) const {
    Values out{};
    evaluate(x.data(), out.data());
    return out;
  }
  // The loops are bounded by the arrays' sizes as well as by n and m (which make_map keeps within
  // them): GCC 12 at -O3 cannot see n <= kMaxInputs through the struct and reports -Warray-bounds.
  Jacobian jacobian(const Point& x, Values* value = nullptr) const {
    std::array<CheckDual, kMaxInputs> xd{};
    for (int i = 0; i < kMaxInputs && i < n; ++i) xd[i] = CheckDual::variable(x[i], i);
    std::array<CheckDual, kMaxOutputs> out{};
    evaluate(xd.data(), out.data());
    Jacobian J{};
    for (int k = 0; k < kMaxOutputs && k < m; ++k) {
      if (value) (*value)[k] = out[k].v;
      for (int i = 0; i < kMaxInputs && i < n; ++i) J[k][i] = out[k].d[i];
    }
    return J;
  }
};

template <class Evaluate>
LawMap<Evaluate> make_map(Evaluate evaluate, int n, int m, std::string what) {
  require(n >= 1 && n <= kMaxInputs && m >= 1 && m <= kMaxOutputs, "law check: a law of ", n, " inputs and ", m,
          " outputs (at most ", kMaxInputs, " and ", kMaxOutputs, ")");
  return {std::move(evaluate), n, m, std::move(what)};
}

inline std::string format(const double* x, int n) {
  std::ostringstream out;
  out.precision(10);
  out << "(";
  for (int i = 0; i < n; ++i) out << (i ? ", " : "") << x[i];
  out << ")";
  return out.str();
}

// Finite-difference Jacobian with steps h = step_scale * step * max(1, |x_i|): central, except in input
// `right_sided` (-1: none), which uses the second-order right-sided (-3 f(x) + 4 f(x + h) - f(x + 2h)) / 2h.
template <class Map>
Jacobian finite_differences(const Map& f, const Point& x, int right_sided, double step, double step_scale) {
  Jacobian J{};
  for (int i = 0; i < f.n; ++i) {
    const double h = step * step_scale * std::max(1.0, std::abs(x[i]));
    Point a = x, b = x;
    if (i == right_sided) {
      a[i] += h;
      b[i] += 2 * h;
      const Values f0 = f.values(x), fa = f.values(a), fb = f.values(b);
      for (int k = 0; k < f.m; ++k) J[k][i] = (-3 * f0[k] + 4 * fa[k] - fb[k]) / (2 * h);
    } else {
      a[i] += h;
      b[i] -= h;
      const Values fa = f.values(a), fb = f.values(b);
      for (int k = 0; k < f.m; ++k) J[k][i] = (fa[k] - fb[k]) / (2 * h);
    }
  }
  return J;
}

// max |dual - fd| over max(|dual|, |fd|, floor): relative to the Jacobian at the point, and absolute (in
// units of floor) where the Jacobian vanishes and only finite-difference noise is left.
template <class Map>
double relative_error(const Map& f, const Jacobian& dual, const Jacobian& fd, double floor) {
  double difference = 0, size = std::max(floor, std::numeric_limits<double>::min());
  for (int k = 0; k < f.m; ++k)
    for (int i = 0; i < f.n; ++i) {
      if (!std::isfinite(dual[k][i]) || !std::isfinite(fd[k][i])) return std::numeric_limits<double>::infinity();
      difference = std::max(difference, std::abs(dual[k][i] - fd[k][i]));
      size = std::max({size, std::abs(dual[k][i]), std::abs(fd[k][i])});
    }
  return difference / size;
}

inline std::string format_jacobian(const Jacobian& J, int n, int m) {
  std::string s = "[";
  for (int k = 0; k < m; ++k) s += (k ? ", " : "") + format(J[k].data(), n);
  return s + "]";
}

// Compares the Dual Jacobian with finite differences at x. derivative_scale is the largest derivative seen
// so far (updated here); entries below 1e-6 of it are compared absolutely.
template <class Map>
void check_derivative(const Map& f, const Point& x, int right_sided, const LawCheckOptions& options,
                      double& derivative_scale, LawCheckReport& report) {
  const Jacobian dual = f.jacobian(x);
  for (int k = 0; k < f.m; ++k)
    for (int i = 0; i < f.n; ++i)
      if (std::isfinite(dual[k][i])) derivative_scale = std::max(derivative_scale, std::abs(dual[k][i]));
  const double floor = 1e-6 * derivative_scale;
  double best = std::numeric_limits<double>::infinity();
  for (const double step_scale : {1.0, 0.1, 0.01})
    best = std::min(best, relative_error(f, dual, finite_differences(f, x, right_sided, options.fd_step, step_scale),
                                         floor));
  ++report.checks;
  report.max_derivative_error = std::max(report.max_derivative_error, best);
  if (best <= options.tolerance) return;
  const Jacobian fd = finite_differences(f, x, right_sided, options.fd_step, 1.0);
  report.failures.push_back(message(f.what, " at ", format(x.data(), f.n), ": Dual derivative ",
                                    format_jacobian(dual, f.n, f.m), " differs from ",
                                    right_sided >= 0 ? "right-sided " : "", "finite differences ",
                                    format_jacobian(fd, f.n, f.m), " by ", best, " (relative)"));
}

// f(x) = f(0) + J(0) x.
template <class Map>
void check_affine(const Map& f, const Point& x, const LawCheckOptions& options, LawCheckReport& report) {
  Values f0{};
  const Jacobian J = f.jacobian(Point{}, &f0);
  const Values fx = f.values(x);
  ++report.checks;
  for (int k = 0; k < f.m; ++k) {
    double predicted = f0[k], size = std::abs(f0[k]);
    for (int i = 0; i < f.n; ++i) {
      predicted += J[k][i] * x[i];
      size = std::max(size, std::abs(J[k][i] * x[i]));
    }
    size = std::max({size, std::abs(fx[k]), std::numeric_limits<double>::min()});
    if (!(std::abs(fx[k] - predicted) <= options.affine_tolerance * size)) {
      report.failures.push_back(message(f.what, " claims affine, but output ", k, " at ", format(x.data(), f.n),
                                        " is ", fx[k], " while f(0) + f'(0) x = ", predicted));
      return;
    }
  }
}

template <class Map>
void check_finite(const Map& f, const Point& x, LawCheckReport& report) {
  Values value{};
  const Jacobian J = f.jacobian(x, &value);
  ++report.checks;
  for (int k = 0; k < f.m; ++k) {
    bool finite = std::isfinite(value[k]);
    for (int i = 0; i < f.n; ++i) finite = finite && std::isfinite(J[k][i]);
    if (!finite) {
      report.failures.push_back(message(f.what, " at ", format(x.data(), f.n), ": value ", value[k],
                                        " or its derivative ", format(J[k].data(), f.n), " is not finite"));
      return;
    }
  }
}

// The law's values lie in the ranges it declares for them (a law that declares none passes).
template <class Law>
void check_declared_ranges(const Law& law, LawCheckReport& report) {
  if constexpr (DeclaresParameters<Law>) {
    const ParameterValues values = law_values(law);
    for (const ParameterDeclaration& d : parameter_declarations<Law>()) {
      try {
        check_parameter(d, values.at(d.name), "law check");
      } catch (const Error& e) {
        report.failures.push_back(message("the law's parameters are outside their declared ranges: ", e.what()));
      }
    }
  }
}

inline bool near_any(double x, const std::vector<double>& points, double clearance) {
  for (double p : points)
    if (std::abs(x - p) < clearance) return true;
  return false;
}

// Draws from [low, high] until the value keeps clearance from the points (a bounded number of tries).
inline double draw_away(std::mt19937& rng, double low, double high, const std::vector<double>& points,
                        double clearance) {
  std::uniform_real_distribution<double> uniform(low, high);
  double x = uniform(rng);
  for (int attempt = 0; attempt < 100 && near_any(x, points, clearance); ++attempt) x = uniform(rng);
  return x;
}

// Both signs of each extreme magnitude, and zero.
inline std::vector<double> signed_extremes(const LawCheckOptions& options) {
  std::vector<double> values = {0.0};
  for (double e : options.extremes) {
    values.push_back(e);
    values.push_back(-e);
  }
  return values;
}

}  // namespace law_check

// A scalar law p(r) (normal laws): `template <class S> S operator()(const S& r) const`.
template <class Law>
LawCheckReport check_scalar_law(const Law& law, const LawCheckOptions& options = {}) {
  using namespace law_check;
  LawCheckReport report;
  report.law = options.name;
  check_declared_ranges(law, report);
  double derivative_scale = 0;  // largest derivative seen, for check_derivative
  const auto f = make_map([&law](const auto* x, auto* out) { out[0] = law(x[0]); }, 1, 1, options.name);
  std::mt19937 rng(options.seed);
  for (int s = 0; s < options.samples; ++s) {
    const Point x = {draw_away(rng, options.low, options.high, options.kinks, options.kink_clearance)};
    if (options.derivatives) check_derivative(f, x, -1, options, derivative_scale, report);
    if constexpr (law_affine<Law>) check_affine(f, x, options, report);
  }
  if (options.derivatives)
    for (double kink : options.kinks) check_derivative(f, Point{kink}, 0, options, derivative_scale, report);
  if constexpr (law_dissipative<Law>) {
    std::uniform_real_distribution<double> unit(-1, 1);
    for (double scale : options.dissipation_scales)
      for (int s = 0; s < options.samples; ++s) {
        const double r = scale * unit(rng);
        const double p = f.values(Point{r})[0];
        ++report.checks;
        if (!(p * r >= 0))
          report.failures.push_back(message(options.name, " claims dissipative, but p(", r, ") * ", r, " = ", p * r));
      }
  }
  for (double r : signed_extremes(options)) check_finite(f, Point{r}, report);
  return report;
}

// A friction law p_tau(r, p_nu): `template <class S> void operator()(const S* r, int dim, const S& p, S* out)`.
template <class Law>
LawCheckReport check_friction_law(const Law& law, const LawCheckOptions& options = {}) {
  using namespace law_check;
  LawCheckReport report;
  report.law = options.name;
  check_declared_ranges(law, report);
  double derivative_scale = 0;  // largest derivative seen, for check_derivative
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> component(options.low, options.high), unit(-1, 1);
  for (const int dim : {2, 3}) {
    const auto f = make_map([&law, dim](const auto* x, auto* out) { law(x, dim, x[dim], out); }, dim + 1, dim,
                            message(options.name, " (", dim, "D; inputs r, p_nu)"));
    // Random r away from r = 0 and random pressures away from the kinks.
    auto random_point = [&](double pressure) {
      Point x{};
      double norm2 = 0;
      do {
        norm2 = 0;
        for (int d = 0; d < dim; ++d) {
          x[d] = component(rng);
          norm2 += x[d] * x[d];
        }
      } while (norm2 < options.kink_clearance * options.kink_clearance);
      x[dim] = pressure;
      return x;
    };
    for (int s = 0; s < options.samples; ++s) {
      const Point x =
          random_point(draw_away(rng, 0, options.pressure_high, options.kinks, options.kink_clearance));
      if (options.derivatives) check_derivative(f, x, -1, options, derivative_scale, report);
      if constexpr (law_affine<Law>) check_affine(f, x, options, report);
    }
    if (options.derivatives) {
      for (double kink : options.kinks) check_derivative(f, random_point(kink), dim, options, derivative_scale, report);
      Point stick{};  // r = 0: a regularized law is smooth there
      stick[dim] = draw_away(rng, 0, options.pressure_high, options.kinks, options.kink_clearance);
      check_derivative(f, stick, -1, options, derivative_scale, report);
    }
    if constexpr (law_dissipative<Law>) {
      for (double scale : options.dissipation_scales)
        for (int s = 0; s < options.samples; ++s) {
          Point x{};
          for (int d = 0; d < dim; ++d) x[d] = scale * unit(rng);
          x[dim] = scale * std::abs(unit(rng));
          const Values p = f.values(x);
          double power = 0;
          for (int d = 0; d < dim; ++d) power += p[d] * x[d];
          ++report.checks;
          if (!(power >= 0))
            report.failures.push_back(message(f.what, " claims dissipative, but p . r = ", power, " at ",
                                              format(x.data(), dim + 1)));
        }
    }
    // Extreme velocities along an axis, along a diagonal, and mixing the largest and smallest magnitudes,
    // at zero and extreme pressures.
    std::vector<double> pressures = {0.0};
    for (double e : options.extremes) pressures.push_back(e);
    const double largest = *std::max_element(options.extremes.begin(), options.extremes.end());
    const double smallest = *std::min_element(options.extremes.begin(), options.extremes.end());
    for (double p : pressures) {
      for (double e : signed_extremes(options)) {
        Point axis{}, diagonal{};
        axis[0] = e;
        for (int d = 0; d < dim; ++d) diagonal[d] = d % 2 ? -e : e;
        axis[dim] = diagonal[dim] = p;
        check_finite(f, axis, report);
        check_finite(f, diagonal, report);
      }
      Point mixed{};
      mixed[0] = largest;
      mixed[1] = smallest;
      mixed[dim] = p;
      check_finite(f, mixed, report);
    }
  }
  return report;
}

// A foundation law D.n(phi, p_nu): `template <class S> S operator()(const S& phi, const S& pressure) const`.
template <class Law>
LawCheckReport check_foundation_law(const Law& law, const LawCheckOptions& options = {}) {
  using namespace law_check;
  LawCheckReport report;
  report.law = options.name;
  check_declared_ranges(law, report);
  double derivative_scale = 0;  // largest derivative seen, for check_derivative
  const auto f = make_map([&law](const auto* x, auto* out) { out[0] = law(x[0], x[1]); }, 2, 1,
                          message(options.name, " (inputs phi, p_nu)"));
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> potential(options.low, options.high), unit(-1, 1);
  auto random_pressure = [&] {
    return draw_away(rng, 0, options.pressure_high, options.kinks, options.kink_clearance);
  };
  for (int s = 0; s < options.samples; ++s) {
    const Point x = {potential(rng), random_pressure()};
    if (options.derivatives) check_derivative(f, x, -1, options, derivative_scale, report);
    if constexpr (law_affine<Law>) check_affine(f, x, options, report);
  }
  if (options.derivatives)
    for (double kink : options.kinks)
      check_derivative(f, Point{potential(rng), kink}, 1, options, derivative_scale, report);
  if constexpr (law_dissipative<Law>) {
    for (double scale : options.dissipation_scales)
      for (int s = 0; s < options.samples; ++s) {
        const double a = scale * unit(rng), b = scale * unit(rng), p = scale * std::abs(unit(rng));
        const double change = (f.values(Point{a, p})[0] - f.values(Point{b, p})[0]) * (a - b);
        ++report.checks;
        if (!(change >= 0))
          report.failures.push_back(message(f.what, " claims dissipative (monotone in phi), but (D(", a, ") - D(", b,
                                            ")) (", a, " - ", b, ") = ", change, " at p_nu = ", p));
      }
  }
  for (double phi : signed_extremes(options))
    for (double p : signed_extremes(options)) check_finite(f, Point{phi, p}, report);
  return report;
}

}  // namespace pc

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
//    each kink against the limit of right-sided difference quotients (the library's laws take the
//    right-sided derivative there), which may converge at any rate (see check_kink);
//  - its `affine` claim: f(x) = f(0) + f'(0) x at random x;
//  - its `dissipative` claim: p(r) r >= 0 (scalar laws), p(r) . r >= 0 (friction laws), monotone in phi
//    (foundation laws), at random arguments of magnitudes dissipation_scales;
//  - finite values and derivatives at extreme arguments (both signs of each magnitude, and zero);
//  - the limits a friction law's class has, along rays r = s d (d an axis or a diagonal, both signs) at
//    pressures 0, 1 and the extremes, over the magnitudes s of extremes and dissipation_scales, from
//    1e-300 to 1e150:
//      dissipative laws: p(s d) . d >= 0 at every s, the extremes included;
//      `monotone` laws: p(s d) . d non-decreasing in s (to round-off), and (p(a) - p(b)) . (a - b) >= 0 at
//        random pairs;
//      saturating laws (declared `bounded`, or |p| changing by less than saturation_tolerance between
//        s = 1e3 and 1e6): no collapse, |p(s d)| >= (1 - saturation_tolerance) |p(1e3 d)| for s > 1e3 --
//        what catches an (r / eps)^2 that overflows to inf and turns mu p into 0 at |r| = 1e150.
//    Nothing is asked of a law of no class (e.g. a velocity-weakening law declares dissipative only).
//    Scalar laws that are dissipative: p(r) r >= 0 at the extremes too.
// Friction laws are checked in 2D and 3D. Away from kinks the derivative checks use central differences
// at three steps (h, h / 10, h / 100), each also halved and Richardson-extrapolated, and keep the best
// match, so that curvature or round-off does not fake a failure; a wrong derivative matches at none of
// them. At a kink, where a C^1 law such as r_+^1.5 has an unbounded second derivative and no fixed step
// resolves it, the right-sided quotients over eleven decades of h must converge to the reported
// derivative: their error must not grow as h shrinks, and must end below kink_tolerance of the scale or
// still be falling steadily (a wrong derivative levels off at its error).
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
  bool derivatives = true;       // false for parameters too extreme for finite differences to resolve
  double fd_step = 1e-6;         // relative to max(1, |x|)
  double tolerance = 1e-6;       // on max |dual - fd| / max(|dual|, |fd|) over the Jacobian's entries
  double kink_tolerance = 1e-4;  // at a kink: on the right-sided quotients' last error over the scale
  double affine_tolerance = 1e-12;
  std::vector<double> dissipation_scales = {1e-3, 1, 1e3, 1e6};
  std::vector<double> extremes = {1e-300, 1e-12, 1e12, 1e150};
  // Friction laws that saturate: beyond |r| = 1e3 the force may not fall below its value there by more
  // than this (relative); a law saturates when it declares `bounded` or changes by less than this between
  // |r| = 1e3 and 1e6.
  double saturation_tolerance = 1e-6;
};

struct LawCheckReport {
  std::string law;
  int checks = 0;
  // Worst relative error of a derivative: the best finite-difference match away from kinks, and at a kink
  // the right-sided quotients' error at the smallest usable step over the scale (r_+^1.25 reports about
  // 3e-3 there and passes, its error still falling steadily).
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
template <class Evaluate> struct LawMap {
  Evaluate evaluate;
  int n;
  int m;
  std::string what;  // e.g. "friction law (3D)", prefixes failure messages

  int inputs() const { return std::min(n, kMaxInputs); }
  int outputs() const { return std::min(m, kMaxOutputs); }
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

template <class Evaluate> LawMap<Evaluate> make_map(Evaluate evaluate, int n, int m, std::string what) {
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

// Central finite differences of every input but `skip` (-1: none), with steps h_i = step * max(1, |x_i|):
// (f(x + h e_i) - f(x - h e_i)) / 2h, truncation error O(h^2).
template <class Map> Jacobian central_differences(const Map& f, const Point& x, int skip, double step) {
  Jacobian J{};
  for (int i = 0; i < f.inputs(); ++i) {
    if (i == skip) continue;
    Point a = x, b = x;
    a[i] += step * std::max(1.0, std::abs(x[i]));
    b[i] -= step * std::max(1.0, std::abs(x[i]));
    const double h2 = a[i] - b[i];  // the step actually taken, twice
    const Values fa = f.values(a), fb = f.values(b);
    for (int k = 0; k < f.outputs(); ++k) J[k][i] = (fa[k] - fb[k]) / h2;
  }
  return J;
}

// Richardson's extrapolation of central differences at h and h / 2: (4 D(h / 2) - D(h)) / 3, whose
// truncation error is O(h^4) where the law is smooth.
inline Jacobian richardson(const Jacobian& coarse, const Jacobian& fine) {
  Jacobian J{};
  for (int k = 0; k < kMaxOutputs; ++k)
    for (int i = 0; i < kMaxInputs; ++i) J[k][i] = (4 * fine[k][i] - coarse[k][i]) / 3;
  return J;
}

// max |dual - fd| over max(|dual|, |fd|, floor), input `skip` left out: relative to the Jacobian at the
// point, and absolute (in units of floor) where the Jacobian vanishes and only finite-difference noise is
// left.
template <class Map>
double relative_error(const Map& f, const Jacobian& dual, const Jacobian& fd, double floor, int skip) {
  double difference = 0, size = std::max(floor, std::numeric_limits<double>::min());
  for (int k = 0; k < f.outputs(); ++k)
    for (int i = 0; i < f.inputs(); ++i) {
      if (i == skip) continue;
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

// The Dual Jacobian at x, with derivative_scale (the largest derivative seen so far) updated.
template <class Map> Jacobian dual_jacobian(const Map& f, const Point& x, double& derivative_scale) {
  const Jacobian dual = f.jacobian(x);
  for (int k = 0; k < f.outputs(); ++k)
    for (int i = 0; i < f.inputs(); ++i)
      if (std::isfinite(dual[k][i])) derivative_scale = std::max(derivative_scale, std::abs(dual[k][i]));
  return dual;
}

// Where the law is smooth (every input but `skip`): the Dual Jacobian against central differences at the
// steps fd_step * {1, 0.1, 0.01} and their Richardson extrapolations to h / 2, keeping the best match.
// A correct derivative matches one of them to the finite differences' accuracy (truncation shrinks with
// h, round-off grows as eps_mach |f| / h, and the best step lies between); a wrong one matches none.
// Entries below 1e-6 of the largest derivative seen are compared absolutely.
template <class Map>
void check_derivative(const Map& f, const Point& x, int skip, const LawCheckOptions& options, double& derivative_scale,
                      LawCheckReport& report) {
  if (skip >= 0 && f.inputs() == 1) return;
  const Jacobian dual = dual_jacobian(f, x, derivative_scale);
  const double floor = 1e-6 * derivative_scale;
  double best = std::numeric_limits<double>::infinity();
  for (const double step_scale : {1.0, 0.1, 0.01}) {
    const double h = options.fd_step * step_scale;
    const Jacobian coarse = central_differences(f, x, skip, h), fine = central_differences(f, x, skip, h / 2);
    for (const Jacobian& fd : {coarse, fine, richardson(coarse, fine)})
      best = std::min(best, relative_error(f, dual, fd, floor, skip));
  }
  ++report.checks;
  report.max_derivative_error = std::max(report.max_derivative_error, best);
  if (best <= options.tolerance) return;
  const Jacobian fd = central_differences(f, x, skip, options.fd_step);
  report.failures.push_back(message(f.what, " at ", format(x.data(), f.n), ": Dual derivative ",
                                    format_jacobian(dual, f.n, f.m), " differs from finite differences ",
                                    format_jacobian(fd, f.n, f.m), " by ", best, " (relative, at best)"));
}

// At a kink in input i, only the right-sided derivative exists: it is the limit of the right-sided
// quotients q(h) = (f(x + h e_i) - f(x)) / h as h -> 0, approached at a rate the law decides (h^(m - 1)
// for r_+^m, 1 < m < 2, whose second derivative is unbounded there). The quotients are taken at
// h = 10^-2 ... 10^-12 (times max(1, |x_i|)); with e(h) = max_k |q_k(h) - dual_k| less the round-off
// 4 eps_mach max |f| / h, and steps whose round-off exceeds kink_tolerance * scale left out (unless they
// match), the derivative
// passes when
//  - the errors do not grow from one decade of h to the next (beyond 1% and kink_tolerance * scale / 10),
//  - and they end small, e(h_last) <= kink_tolerance * scale, or still fall steadily: by at least a factor
//    10^0.05 per decade over the last three decades, at rates within a factor 2 of one another (a wrong
//    derivative levels off at its error).
// scale = max(|dual_i|, |q(10^-2)|, 1e-6 * the largest derivative seen). The other inputs are checked
// like smooth ones.
template <class Map>
void check_kink(const Map& f, const Point& x, int i, const LawCheckOptions& options, double& derivative_scale,
                LawCheckReport& report) {
  check_derivative(f, x, i, options, derivative_scale, report);
  const Jacobian dual = dual_jacobian(f, x, derivative_scale);
  const Values f0 = f.values(x);
  constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
  struct Step {
    double h, error, round_off;
    Values quotient;
  };
  std::vector<Step> steps;
  for (int decade = 2; decade <= 12; ++decade) {
    Point a = x;
    a[i] += std::pow(10.0, -decade) * std::max(1.0, std::abs(x[i]));
    Step step{a[i] - x[i], 0, 0, {}};  // the step actually taken
    const Values fa = f.values(a);
    for (int k = 0; k < f.outputs(); ++k) {
      step.quotient[k] = (fa[k] - f0[k]) / step.h;
      step.error = std::max(step.error, std::abs(step.quotient[k] - dual[k][i]));
      step.round_off = std::max(step.round_off, 4 * kEpsilon * std::max(std::abs(f0[k]), std::abs(fa[k])) / step.h);
      if (!std::isfinite(step.quotient[k]) || !std::isfinite(dual[k][i]))
        step.error = std::numeric_limits<double>::infinity();
    }
    steps.push_back(step);
  }
  double scale = 1e-6 * derivative_scale;
  for (int k = 0; k < f.outputs(); ++k) scale = std::max({scale, std::abs(dual[k][i]), std::abs(steps[0].quotient[k])});
  if (!std::isfinite(scale)) scale = std::numeric_limits<double>::infinity();
  scale = std::max(scale, std::numeric_limits<double>::min());
  const double tolerance = options.kink_tolerance * scale;
  std::vector<double> errors;     // beyond round-off, at the steps round-off leaves usable
  for (const Step& step : steps)  // a quotient that matches is usable whatever its round-off
    if (step.round_off <= tolerance || step.error <= tolerance)
      errors.push_back(std::max(0.0, step.error - step.round_off));
  ++report.checks;
  auto fail = [&](const std::string& why) {
    Values quotient{};
    for (int k = 0; k < f.outputs(); ++k) quotient[k] = steps.back().quotient[k];
    Point column{};
    for (int k = 0; k < f.outputs(); ++k) column[k] = dual[k][i];
    report.failures.push_back(message(f.what, " at the kink ", format(x.data(), f.n), ": Dual derivative in input ", i,
                                      " ", format(column.data(), f.m), " is not the limit of the right-sided ",
                                      "difference quotients (", format(quotient.data(), f.m),
                                      " at h = ", steps.back().h, "): ", why));
  };
  if (errors.size() < 4) return fail(message("round-off leaves ", errors.size(), " of ", steps.size(), " steps"));
  for (size_t j = 0; j + 1 < errors.size(); ++j)
    if (!(errors[j + 1] <= 1.01 * errors[j] + 0.1 * tolerance))
      return fail(message("their error grows from ", errors[j], " to ", errors[j + 1], " as h shrinks"));
  report.max_derivative_error = std::max(report.max_derivative_error, errors.back() / scale);
  if (errors.back() <= tolerance) return;
  // Still falling steadily over the last three decades?
  double slowest = std::numeric_limits<double>::infinity(), fastest = 0;
  for (size_t j = errors.size() - 4; j + 1 < errors.size(); ++j) {
    const double rate = errors[j + 1] > 0 ? std::log10(errors[j] / errors[j + 1]) : 16.0;
    slowest = std::min(slowest, rate);
    fastest = std::max(fastest, rate);
  }
  if (slowest >= 0.05 && fastest <= 2 * slowest) return;
  fail(message("their error levels off at ", errors.back(), " (", errors.back() / scale, " of the scale ", scale, ")"));
}

// f(x) = f(0) + J(0) x.
template <class Map>
void check_affine(const Map& f, const Point& x, const LawCheckOptions& options, LawCheckReport& report) {
  Values f0{};
  const Jacobian J = f.jacobian(Point{}, &f0);
  const Values fx = f.values(x);
  ++report.checks;
  for (int k = 0; k < f.outputs(); ++k) {
    double predicted = f0[k], size = std::abs(f0[k]);
    for (int i = 0; i < f.inputs(); ++i) {
      predicted += J[k][i] * x[i];
      size = std::max(size, std::abs(J[k][i] * x[i]));
    }
    size = std::max({size, std::abs(fx[k]), std::numeric_limits<double>::min()});
    if (!(std::abs(fx[k] - predicted) <= options.affine_tolerance * size)) {
      report.failures.push_back(message(f.what, " claims affine, but output ", k, " at ", format(x.data(), f.n), " is ",
                                        fx[k], " while f(0) + f'(0) x = ", predicted));
      return;
    }
  }
}

template <class Map> void check_finite(const Map& f, const Point& x, LawCheckReport& report) {
  Values value{};
  const Jacobian J = f.jacobian(x, &value);
  ++report.checks;
  for (int k = 0; k < f.outputs(); ++k) {
    bool finite = std::isfinite(value[k]);
    for (int i = 0; i < f.inputs(); ++i) finite = finite && std::isfinite(J[k][i]);
    if (!finite) {
      report.failures.push_back(message(f.what, " at ", format(x.data(), f.n), ": value ", value[k],
                                        " or its derivative ", format(J[k].data(), f.n), " is not finite"));
      return;
    }
  }
}

// The law's values lie in the ranges it declares for them (a law that declares none passes).
template <class Law> void check_declared_ranges(const Law& law, LawCheckReport& report) {
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

// A friction law along rays r = s d: the limits of its class (see the header). f maps (r, p_nu) to p_tau.
template <class Law, class Map>
void check_rays(const Map& f, int dim, const LawCheckOptions& options, LawCheckReport& report) {
  constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
  constexpr double kReference = 1e3, kFar = 1e6;  // where saturation is judged
  std::vector<double> magnitudes = {kReference, kFar};
  for (double e : options.extremes) magnitudes.push_back(std::abs(e));
  for (double e : options.dissipation_scales) magnitudes.push_back(std::abs(e));
  std::sort(magnitudes.begin(), magnitudes.end());
  magnitudes.erase(std::unique(magnitudes.begin(), magnitudes.end()), magnitudes.end());
  magnitudes.erase(std::remove(magnitudes.begin(), magnitudes.end(), 0.0), magnitudes.end());
  std::vector<double> pressures = {0.0, 1.0};
  for (double e : options.extremes) pressures.push_back(std::abs(e));
  for (const double pressure : pressures)
    for (const bool diagonal : {false, true})
      for (const double sign : {1.0, -1.0}) {
        Point direction{};  // unit length
        for (int d = 0; d < dim; ++d)
          direction[d] = diagonal ? sign * (d % 2 ? -1.0 : 1.0) / std::sqrt(double(dim)) : (d == 0 ? sign : 0.0);
        const std::string ray =
            message(f.what, " along r = s ", format(direction.data(), dim), " at p_nu = ", pressure);
        std::vector<double> along, size;  // p . d and |p| at each magnitude
        for (double s : magnitudes) {
          Point x{};
          for (int d = 0; d < dim; ++d) x[d] = s * direction[d];
          x[dim] = pressure;
          const Values p = f.values(x);
          double dot = 0, largest = 0, norm2 = 0;  // |p| scaled by its largest component: no overflow
          for (int d = 0; d < dim; ++d) {
            dot += p[d] * direction[d];
            largest = std::max(largest, std::abs(p[d]));
          }
          for (int d = 0; d < dim && largest > 0; ++d) norm2 += (p[d] / largest) * (p[d] / largest);
          along.push_back(dot);
          size.push_back(largest > 0 ? largest * std::sqrt(norm2) : largest);
        }
        auto at = [&](double s) {
          return size[std::find(magnitudes.begin(), magnitudes.end(), s) - magnitudes.begin()];
        };
        ++report.checks;
        if constexpr (law_dissipative<Law>)
          for (size_t j = 0; j < magnitudes.size(); ++j)
            if (!(along[j] >= 0)) {
              report.failures.push_back(message(ray, ": claims dissipative, but p . r = ", along[j] * magnitudes[j],
                                                " at s = ", magnitudes[j]));
              break;
            }
        if constexpr (law_monotone<Law>)
          for (size_t j = 0; j + 1 < magnitudes.size(); ++j)
            if (!(along[j + 1] >= along[j] - 8 * kEpsilon * std::max(size[j], size[j + 1]))) {
              report.failures.push_back(message(ray, ": claims monotone, but p . d falls from ", along[j], " at s = ",
                                                magnitudes[j], " to ", along[j + 1], " at s = ", magnitudes[j + 1]));
              break;
            }
        const double reference = at(kReference);
        const bool saturates =
            law_bounded<Law> || std::abs(at(kFar) - reference) <= options.saturation_tolerance * reference;
        if (saturates && reference > 0)
          for (size_t j = 0; j < magnitudes.size(); ++j)
            if (magnitudes[j] > kReference && !(size[j] >= (1 - options.saturation_tolerance) * reference)) {
              report.failures.push_back(message(ray, ": saturates at |p| = ", reference, " (s = ", kReference,
                                                "), but collapses to ", size[j], " at s = ", magnitudes[j]));
              break;
            }
      }
}

}  // namespace law_check

// A scalar law p(r) (normal laws): `template <class S> S operator()(const S& r) const`.
template <class Law> LawCheckReport check_scalar_law(const Law& law, const LawCheckOptions& options = {}) {
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
    for (double kink : options.kinks) check_kink(f, Point{kink}, 0, options, derivative_scale, report);
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
  for (double r : signed_extremes(options)) {
    check_finite(f, Point{r}, report);
    if constexpr (law_dissipative<Law>) {
      const double p = f.values(Point{r})[0];
      ++report.checks;
      if (!(p * r >= 0))
        report.failures.push_back(message(options.name, " claims dissipative, but p(", r, ") * ", r, " = ", p * r,
                                          " at an extreme argument"));
    }
  }
  return report;
}

// A friction law p_tau(r, p_nu): `template <class S> void operator()(const S* r, int dim, const S& p, S* out)`.
template <class Law> LawCheckReport check_friction_law(const Law& law, const LawCheckOptions& options = {}) {
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
      const Point x = random_point(draw_away(rng, 0, options.pressure_high, options.kinks, options.kink_clearance));
      if (options.derivatives) check_derivative(f, x, -1, options, derivative_scale, report);
      if constexpr (law_affine<Law>) check_affine(f, x, options, report);
    }
    if (options.derivatives) {
      for (double kink : options.kinks) check_kink(f, random_point(kink), dim, options, derivative_scale, report);
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
            report.failures.push_back(
                message(f.what, " claims dissipative, but p . r = ", power, " at ", format(x.data(), dim + 1)));
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
    if constexpr (law_monotone<Law>) {
      for (double scale : options.dissipation_scales)
        for (int s = 0; s < options.samples; ++s) {
          Point a{}, b{};
          for (int d = 0; d < dim; ++d) {
            a[d] = scale * unit(rng);
            b[d] = scale * unit(rng);
          }
          a[dim] = b[dim] = scale * std::abs(unit(rng));
          const Values pa = f.values(a), pb = f.values(b);
          double change = 0, size = 0;
          for (int d = 0; d < dim; ++d) {
            change += (pa[d] - pb[d]) * (a[d] - b[d]);
            size += (std::abs(pa[d]) + std::abs(pb[d])) * std::abs(a[d] - b[d]);
          }
          ++report.checks;
          if (!(change >= -8 * std::numeric_limits<double>::epsilon() * size))
            report.failures.push_back(message(f.what, " claims monotone, but (p(a) - p(b)) . (a - b) = ", change,
                                              " at a = ", format(a.data(), dim + 1),
                                              ", b = ", format(b.data(), dim + 1)));
        }
    }
    check_rays<Law>(f, dim, options, report);
  }
  return report;
}

// A foundation law D.n(phi, p_nu): `template <class S> S operator()(const S& phi, const S& pressure) const`.
template <class Law> LawCheckReport check_foundation_law(const Law& law, const LawCheckOptions& options = {}) {
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
    for (double kink : options.kinks) check_kink(f, Point{potential(rng), kink}, 1, options, derivative_scale, report);
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

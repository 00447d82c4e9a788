#pragma once
// Forward-mode automatic differentiation: a value with N directional derivatives. A point-wise kernel
// written once for a template scalar S runs with S = double for residuals and S = Dual<N> for tangents.
// Functions are found by argument-dependent lookup, so kernels write `using std::sqrt; sqrt(x)`.
#include <array>
#include <cmath>

namespace pc {

template <int N> struct Dual {
  double v = 0;
  std::array<double, N> d{};

  Dual() = default;
  Dual(double value) : v(value) {}  // NOLINT: implicit, so that constants mix with duals
  static Dual variable(double value, int direction) {
    Dual x(value);
    x.d[direction] = 1;
    return x;
  }

  Dual& operator+=(const Dual& b) {
    v += b.v;
    for (int i = 0; i < N; ++i) d[i] += b.d[i];
    return *this;
  }
  Dual& operator-=(const Dual& b) {
    v -= b.v;
    for (int i = 0; i < N; ++i) d[i] -= b.d[i];
    return *this;
  }
  Dual& operator*=(const Dual& b) {
    for (int i = 0; i < N; ++i) d[i] = d[i] * b.v + v * b.d[i];
    v *= b.v;
    return *this;
  }
  Dual& operator/=(const Dual& b) {
    const double inv = 1.0 / b.v;
    for (int i = 0; i < N; ++i) d[i] = (d[i] - v * inv * b.d[i]) * inv;
    v *= inv;
    return *this;
  }
};

inline double value_of(double x) { return x; }
template <int N> double value_of(const Dual<N>& x) { return x.v; }

template <int N> Dual<N> operator+(Dual<N> a, const Dual<N>& b) { return a += b; }
template <int N> Dual<N> operator-(Dual<N> a, const Dual<N>& b) { return a -= b; }
template <int N> Dual<N> operator*(Dual<N> a, const Dual<N>& b) { return a *= b; }
template <int N> Dual<N> operator/(Dual<N> a, const Dual<N>& b) { return a /= b; }
template <int N> Dual<N> operator+(Dual<N> a, double b) {
  a.v += b;
  return a;
}
template <int N> Dual<N> operator+(double a, Dual<N> b) {
  b.v += a;
  return b;
}
template <int N> Dual<N> operator-(Dual<N> a, double b) {
  a.v -= b;
  return a;
}
template <int N> Dual<N> operator-(double a, const Dual<N>& b) { return Dual<N>(a) -= b; }
template <int N> Dual<N> operator*(Dual<N> a, double b) {
  a.v *= b;
  for (double& x : a.d) x *= b;
  return a;
}
template <int N> Dual<N> operator*(double a, Dual<N> b) { return b * a; }
template <int N> Dual<N> operator/(Dual<N> a, double b) { return a * (1.0 / b); }
template <int N> Dual<N> operator/(double a, const Dual<N>& b) { return Dual<N>(a) /= b; }
template <int N> Dual<N> operator-(Dual<N> a) {
  a.v = -a.v;
  for (double& x : a.d) x = -x;
  return a;
}
template <int N> Dual<N> operator+(const Dual<N>& a) { return a; }

// Comparisons look at values only (branches in kernels select a smooth piece).
template <int N> bool operator<(const Dual<N>& a, const Dual<N>& b) { return a.v < b.v; }
template <int N> bool operator>(const Dual<N>& a, const Dual<N>& b) { return a.v > b.v; }
template <int N> bool operator<=(const Dual<N>& a, const Dual<N>& b) { return a.v <= b.v; }
template <int N> bool operator>=(const Dual<N>& a, const Dual<N>& b) { return a.v >= b.v; }
template <int N> bool operator<(const Dual<N>& a, double b) { return a.v < b; }
template <int N> bool operator>(const Dual<N>& a, double b) { return a.v > b; }
template <int N> bool operator<=(const Dual<N>& a, double b) { return a.v <= b; }
template <int N> bool operator>=(const Dual<N>& a, double b) { return a.v >= b; }
template <int N> bool operator<(double a, const Dual<N>& b) { return a < b.v; }
template <int N> bool operator>(double a, const Dual<N>& b) { return a > b.v; }

namespace dual_detail {
// f(a) with derivative df = f'(a.v), by the chain rule.
template <int N> Dual<N> chain(const Dual<N>& a, double f, double df) {
  Dual<N> r(f);
  for (int i = 0; i < N; ++i) r.d[i] = df * a.d[i];
  return r;
}
}  // namespace dual_detail

// f(a) from its value f and slope df at value_of(a), for any scalar: lets a kernel call a function that
// is known only by its value and first derivative (a law behind a virtual interface) and still carry
// exact first derivatives.
inline double chain_rule(double /*a*/, double f, double /*df*/) { return f; }
template <int N> Dual<N> chain_rule(const Dual<N>& a, double f, double df) { return dual_detail::chain(a, f, df); }

template <int N> Dual<N> sqrt(const Dual<N>& a) {
  const double s = std::sqrt(a.v);
  return dual_detail::chain(a, s, s > 0 ? 0.5 / s : 0.0);
}
template <int N> Dual<N> exp(const Dual<N>& a) {
  const double e = std::exp(a.v);
  return dual_detail::chain(a, e, e);
}
template <int N> Dual<N> log(const Dual<N>& a) { return dual_detail::chain(a, std::log(a.v), 1.0 / a.v); }
template <int N> Dual<N> sin(const Dual<N>& a) { return dual_detail::chain(a, std::sin(a.v), std::cos(a.v)); }
template <int N> Dual<N> cos(const Dual<N>& a) { return dual_detail::chain(a, std::cos(a.v), -std::sin(a.v)); }
template <int N> Dual<N> tanh(const Dual<N>& a) {
  const double t = std::tanh(a.v);
  return dual_detail::chain(a, t, 1 - t * t);
}
template <int N> Dual<N> atan(const Dual<N>& a) { return dual_detail::chain(a, std::atan(a.v), 1 / (1 + a.v * a.v)); }
// |a|: the derivative at 0 is taken as 0 (the subgradient of least norm).
template <int N> Dual<N> abs(const Dual<N>& a) {
  return dual_detail::chain(a, std::abs(a.v), a.v > 0 ? 1.0 : (a.v < 0 ? -1.0 : 0.0));
}
// a^p for a real exponent; at a = 0 the derivative is 0 for p > 1 (and p * a^(p-1) otherwise).
template <int N> Dual<N> pow(const Dual<N>& a, double p) {
  const double f = std::pow(a.v, p);
  const double df = (a.v == 0 && p > 1) ? 0.0 : p * std::pow(a.v, p - 1);
  return dual_detail::chain(a, f, df);
}
// max/min pick a branch by value; at a tie the first argument's derivative is kept.
template <int N> Dual<N> max(const Dual<N>& a, const Dual<N>& b) { return a.v >= b.v ? a : b; }
template <int N> Dual<N> min(const Dual<N>& a, const Dual<N>& b) { return a.v <= b.v ? a : b; }

}  // namespace pc

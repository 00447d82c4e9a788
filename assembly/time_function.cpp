#include "assembly/time_function.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "assembly/error.hpp"

namespace pc {
namespace {

void require_finite(double x, const char* what) {
  require(std::isfinite(x), "time function: ", what, " must be finite, got ", x);
}

}  // namespace

TimeFunction TimeFunction::constant(double value) {
  require_finite(value, "the constant's value");
  TimeFunction f;
  f.a_ = value;
  return f;
}

TimeFunction TimeFunction::ramp(double value, double duration) {
  require_finite(value, "the ramp's value");
  require(std::isfinite(duration) && duration > 0, "time function: the ramp's duration must be > 0, got ", duration);
  TimeFunction f;
  f.kind_ = Kind::Ramp;
  f.a_ = value;
  f.b_ = duration;
  return f;
}

TimeFunction TimeFunction::sine(double amplitude, double frequency, double phase, double offset) {
  require_finite(amplitude, "the sine's amplitude");
  require(std::isfinite(frequency) && frequency > 0, "time function: the sine's frequency must be > 0, got ",
          frequency);
  require_finite(phase, "the sine's phase");
  require_finite(offset, "the sine's offset");
  TimeFunction f;
  f.kind_ = Kind::Sine;
  f.a_ = amplitude;
  f.b_ = frequency;
  f.c_ = phase;
  f.d_ = offset;
  return f;
}

TimeFunction TimeFunction::table(std::vector<std::pair<double, double>> points) {
  require(!points.empty(), "time function: a table needs at least one point (t, value)");
  for (size_t i = 0; i < points.size(); ++i) {
    require(std::isfinite(points[i].first) && std::isfinite(points[i].second), "time function: table point ", i,
            " must be finite, got (", points[i].first, ", ", points[i].second, ")");
    require(i == 0 || points[i].first > points[i - 1].first, "time function: table times must increase, point ", i,
            " has t = ", points[i].first, " after t = ", points[i - 1].first);
  }
  TimeFunction f;
  f.kind_ = Kind::Table;
  f.points_ = std::move(points);
  return f;
}

bool TimeFunction::varies() const {
  if (kind_ == Kind::Table)
    return std::any_of(points_.begin(), points_.end(), [&](const auto& p) { return p.second != points_[0].second; });
  if (kind_ == Kind::Constant) return false;
  return a_ != 0;  // a ramp to 0 or a sine of amplitude 0 is a constant
}

double TimeFunction::value(double t) const {
  switch (kind_) {
    case Kind::Constant: return a_;
    case Kind::Ramp: return a_ * std::clamp(t / b_, 0.0, 1.0);
    case Kind::Sine: return d_ + a_ * std::sin(2 * std::numbers::pi * b_ * t + c_);
    case Kind::Table: break;
  }
  if (t <= points_.front().first) return points_.front().second;
  if (t >= points_.back().first) return points_.back().second;
  const auto upper =
      std::upper_bound(points_.begin(), points_.end(), t, [](double time, const auto& p) { return time < p.first; });
  const auto& [t1, v1] = *upper;
  const auto& [t0, v0] = *(upper - 1);
  return v0 + (v1 - v0) * (t - t0) / (t1 - t0);
}

double TimeFunction::integral(double t) const {
  switch (kind_) {
    case Kind::Constant: return a_ * t;
    case Kind::Ramp: {
      // 0 before t = 0 (a value of 0 there), a t^2 / (2 duration) on the ramp, then the held value.
      if (t <= 0) return 0;
      if (t <= b_) return a_ * t * t / (2 * b_);
      return a_ * (b_ / 2 + (t - b_));
    }
    case Kind::Sine: {
      const double w = 2 * std::numbers::pi * b_;
      return d_ * t + a_ * (std::cos(c_) - std::cos(w * t + c_)) / w;
    }
    case Kind::Table: break;
  }
  // Piecewise linear: the trapezoids between the breakpoints (exact), and the constant ends.
  auto area = [&](double from, double to) {  // from <= to
    double sum = 0;
    const auto segment = [&](double a, double b) { sum += (b - a) * (value(a) + value(b)) / 2; };
    double left = from;
    for (const auto& p : points_)
      if (p.first > left && p.first < to) {
        segment(left, p.first);
        left = p.first;
      }
    segment(left, to);
    return sum;
  };
  return t >= 0 ? area(0, t) : -area(t, 0);
}

std::string TimeFunction::describe() const {
  switch (kind_) {
    case Kind::Constant: return message("constant(", a_, ")");
    case Kind::Ramp: return message("ramp(to ", a_, " over ", b_, " s)");
    case Kind::Sine:
      return message("sine(amplitude ", a_, ", frequency ", b_, " Hz, phase ", c_, " rad, offset ", d_, ")");
    case Kind::Table: break;
  }
  return message("table(", points_.size(), " points from t = ", points_.front().first, " to ", points_.back().first,
                 ")");
}

}  // namespace pc

#pragma once
// A scalar function of time, the shape of everything a scene drives: an electrode's voltage V(t), a
// foundation's velocity V_f(t), a load's amplitude. Four kinds, each with a closed-form value and a
// closed-form integral from t = 0 (a moving foundation's displacement is the integral of its velocity,
// exact at every step whatever the step size):
//   constant  c
//   ramp      c min(t / duration, 1)                       (a soft start to c)
//   sine      offset + amplitude sin(2 pi frequency t + phase)   (phase in radians)
//   table     piecewise linear through (t_i, v_i), t_i increasing; constant beyond the ends
// The factories check their arguments and throw pc::Error naming the bad one.
#include <string>
#include <utility>
#include <vector>

namespace pc {

class TimeFunction {
 public:
  enum class Kind { Constant, Ramp, Sine, Table };

  TimeFunction() = default;  // the constant 0
  static TimeFunction constant(double value);
  static TimeFunction ramp(double value, double duration);
  static TimeFunction sine(double amplitude, double frequency, double phase = 0, double offset = 0);
  static TimeFunction table(std::vector<std::pair<double, double>> points);

  double value(double t) const;
  // The integral of value() from 0 to t.
  double integral(double t) const;
  Kind kind() const { return kind_; }
  // Whether the value changes with time (a non-constant kind).
  bool varies() const;
  // E.g. "sine(amplitude 100, frequency 1e+05 Hz, phase 0 rad, offset 0)".
  std::string describe() const;

 private:
  Kind kind_ = Kind::Constant;
  double a_ = 0, b_ = 0, c_ = 0, d_ = 0;  // constant: a; ramp: a, duration b; sine: amplitude a, f b, phase c, offset d
  std::vector<std::pair<double, double>> points_;
};

}  // namespace pc

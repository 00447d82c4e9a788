#pragma once
// The target-error mode's check of a pilots' convergence rate against the theory's
// (models/scene/target_error.hpp): the spatial estimate's in the cells along an axis (the energy norm of
// the gradient error: P1 1, P2 2), the time estimate's in the step attempts (backward Euler 1, BDF2 2).
// A rate below half the theory's (a singular solution, pilots not yet asymptotic, a noisy estimate)
// says the pilots do not tell how the error goes on falling: the mode warns and does not extrapolate far.
#include <string>
#include <vector>

namespace pc {

constexpr double kFarBelowTheory = 0.5;  // a rate below this fraction of the theory's is far below it

struct RateCheck {
  double measured = 0;  // NaN when the errors give none (a zero error, a single resolution)
  double theory = 0;
  bool far_below = false;  // measured < kFarBelowTheory * theory
  std::string problem;     // when far_below, e.g. "P2 bdf2: the spatial rate 0.636 is below half the theory's 2"
};

// The rate r of errors e_i = C n_i^-r at resolutions n_i (cells along an axis or step attempts, the
// inverse of h or of the step), fitted by least squares to log e against log n, against the theory's.
// `what` names the rate in the problem, e.g. "P2 bdf2: the spatial rate".
RateCheck check_rate(const std::string& what, const std::vector<double>& resolutions, const std::vector<double>& errors,
                     double theory);

}  // namespace pc

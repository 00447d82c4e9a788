#include "models/solvers/krylov_solve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace pc {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// GMRES gives up (and J is factorised at once) after this many iterations at least, and at most, however
// cheap a solve is against a factorisation.
constexpr int kMinIterations = 4, kMaxIterations = 200;
constexpr int kMaxBasis = 40;
// At back-off exponent n (a failure of GMRES adds one, a success takes one away), 2^n - 1 direct steps
// follow a failure before the next try.
constexpr int kMaxBackoffExponent = 5;

}  // namespace

KrylovSolve::KrylovSolve(std::string linear_solver, double relative_tolerance)
    : linear_solver_name_(std::move(linear_solver)), relative_tolerance_(relative_tolerance) {}

FactorEstimate KrylovSolve::analyze(const CsrMatrix& J) {
  if (!factors_) factors_ = make_linear_solver(linear_solver_name_);
  if (!factors_->is_analyzed_for(J)) factors_->analyze(J);
  return factors_->factor_estimate();
}

void KrylovSolve::release() {
  factors_.reset();
  renew_ = true;
}

Eigen::VectorXd KrylovSolve::direct_step(const CsrMatrix& J, const Eigen::VectorXd& b, LinearSolveCost& cost) {
  if (!factors_) factors_ = make_linear_solver(linear_solver_name_);
  auto t = Clock::now();
  if (!factors_->is_analyzed_for(J)) {
    factors_->analyze(J);
    cost.analyze_seconds += seconds_since(t);
    t = Clock::now();
  }
  renew_ = true;  // until the factorisation below succeeds
  factors_->factorize(J);
  factorize_seconds_ = seconds_since(t);
  cost.factorize_seconds += factorize_seconds_;
  ++cost.factorizations;
  t = Clock::now();
  Eigen::VectorXd dx = factors_->solve(b);
  cost.solve_seconds += seconds_since(t);
  renew_ = false;
  return dx;
}

KrylovStep KrylovSolve::step(NonlinearProblem& problem, const Eigen::VectorXd& b) {
  KrylovStep result;
  const CsrMatrix& J = problem.jacobian();
  const std::uint64_t version = problem.linear_jacobian_version();
  if (renew_ || !factors_ || direct_steps_left_ > 0 || problem_ != &problem || version_ != version ||
      !factors_->is_analyzed_for(J)) {
    if (direct_steps_left_ > 0) --direct_steps_left_;
    problem_ = &problem;
    version_ = version;
    result.dx = direct_step(J, b, result.cost);
    return result;
  }
  // Half a factorisation's worth of iterations, within [kMinIterations, kMaxIterations]: a failure then
  // costs at most 1.5 factorisations.
  const double affordable = iteration_seconds_ > 0 ? 0.5 * factorize_seconds_ / iteration_seconds_ : kMaxIterations;
  GmresOptions options;
  options.relative_tolerance = relative_tolerance_;
  options.max_iterations = std::clamp(int(std::ceil(affordable)), kMinIterations, kMaxIterations);
  // The basis holds restart vectors of the problem's size: bounded, so that memory stays O(dofs).
  options.restart = std::min(options.max_iterations, kMaxBasis);
  const auto t = Clock::now();
  GmresResult gmres_result = gmres([&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return J * x; },
                                   [&](const Eigen::VectorXd& r) { return factors_->solve(r); }, b, options);
  const double seconds = seconds_since(t);
  result.cost.solve_seconds += seconds;
  result.iterations = gmres_result.iterations;
  iteration_seconds_ = seconds / std::max(gmres_result.iterations, 1);
  if (!gmres_result.converged) {
    // J moved too far from J_ref: the iterations so far are lost, at most half a factorisation's worth.
    // While the contact state keeps moving that fast, GMRES would fail again: the next steps are direct,
    // twice as many after each further failure, so that the path costs little more than a factorisation
    // per iteration where that is the right answer.
    backoff_exponent_ = std::min(backoff_exponent_ + 1, kMaxBackoffExponent);
    direct_steps_left_ = (1 << backoff_exponent_) - 1;
    result.dx = direct_step(J, b, result.cost);
    return result;
  }
  // One success does not make the next likely where GMRES fails often: the back-off shrinks a step at a time.
  backoff_exponent_ = std::max(backoff_exponent_ - 1, 0);
  // The next step renews J_ref when this one's iterations cost more than a factorisation would have.
  renew_ = seconds > factorize_seconds_;
  result.dx = std::move(gmres_result.x);
  return result;
}

}  // namespace pc

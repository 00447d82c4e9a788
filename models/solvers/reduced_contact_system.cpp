#include "models/solvers/reduced_contact_system.hpp"

#include <optional>

namespace pc {

std::unique_ptr<ReducedContactSystem> ReducedContactSystem::reduce(NonlinearProblem& problem, CondensedSolve& condensed,
                                                                   LinearSolveCost& cost) {
  std::unique_ptr<ReducedContactSystem> system(new ReducedContactSystem(problem, condensed));
  if (!problem.assemble_nonlinear_rows(system->nonlinear0_)) return nullptr;
  std::optional<Eigen::VectorXd> r = condensed.reduce(problem, system->b_, cost);
  if (!r) return nullptr;
  system->rho0_ = -*r;  // the reduction of -R(x0)
  system->rho_ = system->rho0_;
  system->nonlinear_ = system->nonlinear0_;
  return system;
}

ReducedContactSystem::ReducedContactSystem(NonlinearProblem& problem, CondensedSolve& condensed)
    : problem_(problem),
      condensed_(condensed),
      contact_(problem.nonlinear_dofs()),
      x0_(problem.free_values()),
      b_(-problem.residual()),
      shift_(Eigen::VectorXd::Zero(Eigen::Index(contact_.size()))) {
  // The contact dofs are sorted and each block is a range of the free values: a block's contact dofs are
  // a range of x_c.
  size_t next = 0;
  for (const ProblemBlock& block : problem.blocks()) {
    const size_t begin = next;
    while (next < contact_.size() && contact_[next] < block.begin + block.size) ++next;
    blocks_.push_back({block.name, int(begin), int(next - begin)});
  }
}

void ReducedContactSystem::assemble() {
  problem_.assemble_nonlinear_rows(nonlinear_);
  rho_ = rho0_ + nonlinear_ - nonlinear0_;
  rho_.noalias() += condensed_.interface_matrix() * shift_;
}

Eigen::VectorXd ReducedContactSystem::free_values() const { return x0_(contact_) + shift_; }

void ReducedContactSystem::set_free_values(const Eigen::VectorXd& x_c) { move_contact_values(x_c - x0_(contact_)); }

void ReducedContactSystem::add_to_free_values(const Eigen::VectorXd& step) { move_contact_values(shift_ + step); }

void ReducedContactSystem::move_contact_values(const Eigen::VectorXd& new_shift) {
  Eigen::VectorXd change = Eigen::VectorXd::Zero(x0_.size());
  change(contact_) = new_shift - shift_;
  problem_.add_to_free_values(change);
  shift_ = new_shift;
}

Eigen::VectorXd ReducedContactSystem::step(const Eigen::VectorXd& rhs, LinearSolveCost& cost) {
  return condensed_.solve_interface(problem_, rhs, cost);
}

void ReducedContactSystem::expand(LinearSolveCost& cost) {
  problem_.set_free_values(x0_ + condensed_.expand(b_, shift_, cost));
}

}  // namespace pc

#include "models/solvers/condensed_solve.hpp"

#include <chrono>
#include <cmath>
#include <optional>

#include "assembly/dense_inverse.hpp"
#include "assembly/error.hpp"

namespace pc {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// S_c counts as singular, and S_c + D is factorised per iteration, when the estimate of its smallest
// singular value, rcond ||S_c||_1, is below this fraction of the size of A's entries in the condensed rows:
// what elimination leaves there is then round-off. (rcond alone is scale-free: a 1 x 1 S_c of pure
// round-off, 1e-17 where A holds ones, would count as perfectly conditioned.)
constexpr double kMinSchurRelativeSize = 1e-13;

// max |A_ij| over the rows of the given dofs.
double largest_entry_in_rows(const CsrMatrix& A, const std::vector<int>& rows) {
  double largest = 0;
  for (int r : rows)
    for (CsrMatrix::InnerIterator it(A, r); it; ++it) largest = std::max(largest, std::abs(it.value()));
  return largest;
}

bool same_entries(const std::vector<Eigen::Triplet<double, int>>& a,
                  const std::vector<Eigen::Triplet<double, int>>& b) {
  if (a.size() != b.size()) return false;
  for (size_t k = 0; k < a.size(); ++k)
    if (a[k].row() != b[k].row() || a[k].col() != b[k].col() || a[k].value() != b[k].value()) return false;
  return true;
}

}  // namespace

CondensedSolve::CondensedSolve(LinearStrategy method, std::string linear_solver, double max_fraction, int max_dofs)
    : method_(method == LinearStrategy::Columns ? method : LinearStrategy::Schur),
      linear_solver_name_(std::move(linear_solver)),
      max_fraction_(max_fraction),
      max_dofs_(max_dofs) {}

bool CondensedSolve::applies(NonlinearProblem& problem) const {
  return applies_in_proportion(problem) && double(problem.nonlinear_dofs().size()) <= double(max_dofs_);
}

bool CondensedSolve::applies_in_proportion(NonlinearProblem& problem) const {
  if (max_fraction_ <= 0 || uncondensable_ == &problem) return false;
  // m = 0 (a linear problem) also gains: the factorisation of A is kept from solve to solve.
  return double(problem.nonlinear_dofs().size()) <= max_fraction_ * double(problem.residual().size());
}

CondensedStep CondensedSolve::step(NonlinearProblem& problem, const Eigen::VectorXd& b) {
  CondensedStep result;
  // The sparse solvers report a singular matrix by throwing (assembly/linear_solver.hpp); this is the one
  // place where that becomes the strategy's answer "does not apply to this problem".
  try {
    result.dx = solve(problem, b, result.cost);
  } catch (const Error&) {
    uncondensable_ = &problem;
  }
  return result;
}

void CondensedSolve::prepare(NonlinearProblem& problem, LinearSolveCost& cost) {
  const std::vector<int>& nonlinear = problem.nonlinear_dofs();
  if (problem_ == &problem && version_ == problem.linear_jacobian_version() && nonlinear_ == nonlinear) return;
  problem_ = nullptr;  // until the factorisation below succeeds
  const CsrMatrix& A = problem.linear_jacobian();
  nonlinear_ = nonlinear;
  position_.assign(A.rows(), -1);
  for (size_t i = 0; i < nonlinear_.size(); ++i) position_[nonlinear_[i]] = int(i);

  auto t = Clock::now();
  if (method_ == LinearStrategy::Schur && !nonlinear_.empty()) {
    linear_.reset();  // a factorisation of a linear problem's A (the initial potential's) is not needed again
    if (!schur_) schur_ = std::make_unique<SchurComplement>();
    if (!schur_->is_analyzed_for(A, nonlinear_)) {
      schur_->analyze(A, nonlinear_);
      cost.analyze_seconds += seconds_since(t);
      t = Clock::now();
    }
    schur_->factorize(A);
    cost.factorize_seconds += seconds_since(t);
    t = Clock::now();
    // Rows of S that vanish (a multiplier's, which only the nonlinear part fills) make it singular: its
    // inverse is then not taken (inverse_if_regular checks the condition estimate and the inverse).
    std::optional<Eigen::MatrixXd> inverse =
        inverse_if_regular(schur_->schur(), kMinSchurRelativeSize * largest_entry_in_rows(A, nonlinear_));
    schur_regular_ = inverse.has_value();
    if (schur_regular_) schur_inverse_ = std::move(*inverse);
    woodbury_valid_ = false;
    cost.condensation_seconds += seconds_since(t);
  } else {
    // Columns, or a linear model (m = 0): A's own factorisation, kept from step to step.
    if (!linear_) linear_ = make_linear_solver(linear_solver_name_);
    if (!linear_->is_analyzed_for(A)) {
      linear_->analyze(A);
      cost.analyze_seconds += seconds_since(t);
      t = Clock::now();
    }
    linear_->factorize(A);
    cost.factorize_seconds += seconds_since(t);
    columns_.assign(nonlinear_.size(), Eigen::VectorXd());
  }
  ++cost.factorizations;
  problem_ = &problem;
  version_ = problem.linear_jacobian_version();
}

Eigen::SparseMatrix<double, Eigen::RowMajor> CondensedSolve::NonlinearPart::on_active() const {
  std::vector<int> index(active.empty() ? 0 : active.back() + 1, -1);
  for (size_t q = 0; q < active.size(); ++q) index[active[q]] = int(q);
  std::vector<Eigen::Triplet<double, int>> on_active;
  on_active.reserve(entries.size());
  for (const auto& e : entries) on_active.emplace_back(index[e.row()], index[e.col()], e.value());
  const auto a = Eigen::Index(active.size());
  Eigen::SparseMatrix<double, Eigen::RowMajor> block(a, a);
  block.setFromTriplets(on_active.begin(), on_active.end());
  return block;
}

Eigen::MatrixXd CondensedSolve::NonlinearPart::whole(int m) const {
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(m, m);
  for (const auto& e : entries) d(e.row(), e.col()) = e.value();
  return d;
}

CondensedSolve::NonlinearPart CondensedSolve::nonlinear_part(NonlinearProblem& problem, LinearSolveCost& cost) {
  // D: the difference J - A on the nonlinear rows and columns (the two share one pattern), and the
  // active dofs where D has a non-zero row or column (for contact, the nodes in compression).
  problem.nonlinear_part(nonlinear_values_);  // the problem's assembly (its Jacobian's time), not ours
  const auto t = Clock::now();
  const CsrMatrix& A = problem.linear_jacobian();
  const int m = static_cast<int>(nonlinear_.size());
  NonlinearPart D;
  std::vector<char> is_active(m, 0);
  size_t value = 0;
  for (int i = 0; i < m; ++i) {
    const int row = nonlinear_[i];
    for (int k = A.outerIndexPtr()[row]; k < A.outerIndexPtr()[row + 1]; ++k) {
      const double d = nonlinear_values_[value++];
      const int j = position_[A.innerIndexPtr()[k]];
      if (j < 0 || d == 0) continue;
      D.entries.emplace_back(i, j, d);
      is_active[i] = is_active[j] = 1;
    }
  }
  for (int i = 0; i < m; ++i)
    if (is_active[i]) D.active.push_back(i);
  cost.condensation_seconds += seconds_since(t);
  return D;
}

Eigen::VectorXd CondensedSolve::solve(NonlinearProblem& problem, const Eigen::VectorXd& b, LinearSolveCost& cost) {
  prepare(problem, cost);
  const NonlinearPart D = nonlinear_part(problem, cost);
  return method_ == LinearStrategy::Schur && !nonlinear_.empty() ? schur_step(D, b, cost) : columns_step(D, b, cost);
}

std::optional<Eigen::VectorXd> CondensedSolve::reduce(NonlinearProblem& problem, const Eigen::VectorXd& b,
                                                      LinearSolveCost& cost) {
  if (method_ != LinearStrategy::Schur || problem.nonlinear_dofs().empty()) return std::nullopt;
  try {
    prepare(problem, cost);
  } catch (const Error&) {
    uncondensable_ = &problem;
    return std::nullopt;
  }
  return timed_reduce(b, cost);
}

Eigen::VectorXd CondensedSolve::timed_reduce(const Eigen::VectorXd& b, LinearSolveCost& cost) {
  const auto t = Clock::now();
  Eigen::VectorXd r = schur_->reduce(b);
  cost.solve_seconds += seconds_since(t);
  return r;
}

Eigen::VectorXd CondensedSolve::solve_interface(NonlinearProblem& problem, const Eigen::VectorXd& r,
                                                LinearSolveCost& cost) {
  return interface_step(nonlinear_part(problem, cost), r, cost);
}

Eigen::VectorXd CondensedSolve::expand(const Eigen::VectorXd& b, const Eigen::VectorXd& x_c, LinearSolveCost& cost) {
  const auto t = Clock::now();
  Eigen::VectorXd dx = schur_->expand(b, x_c);
  cost.solve_seconds += seconds_since(t);
  return dx;
}

// (S_c + D) x_c = r with r = reduce(b), then dx = expand(b, x_c).
Eigen::VectorXd CondensedSolve::schur_step(const NonlinearPart& D, const Eigen::VectorXd& b, LinearSolveCost& cost) {
  return expand(b, interface_step(D, timed_reduce(b, cost), cost), cost);
}

// (S_c + D) x_c = r by Woodbury on S_c^-1 over the active dofs I:
//   x_c = t - S_c^-1[:, I] (1 + D_II S_c^-1[I, I])^-1 D_II t_I,  t = S_c^-1 r.
Eigen::VectorXd CondensedSolve::interface_step(const NonlinearPart& D, const Eigen::VectorXd& r,
                                               LinearSolveCost& cost) {
  const auto t = Clock::now();
  Eigen::VectorXd x_c;
  const std::vector<int>& active = D.active;
  if (!schur_regular_) {
    x_c = (schur_->schur() + D.whole(int(nonlinear_.size()))).partialPivLu().solve(r);
    ++cost.dense_factorizations;
  } else {
    x_c = schur_inverse_ * r;
    if (!active.empty()) {
      const Eigen::SparseMatrix<double, Eigen::RowMajor> Da = D.on_active();
      if (!woodbury_valid_ || active != woodbury_active_ || !same_entries(D.entries, woodbury_d_)) {
        Eigen::MatrixXd woodbury = Da * Eigen::MatrixXd(schur_inverse_(active, active));
        woodbury.diagonal().array() += 1;
        woodbury_lu_.compute(woodbury);
        woodbury_active_ = active;
        woodbury_d_ = D.entries;
        woodbury_valid_ = true;
        ++cost.dense_factorizations;
      }
      const Eigen::VectorXd z = woodbury_lu_.solve(Da * x_c(active));
      // S_c^-1[:, I] z as S_c^-1 times z spread over the nonlinear dofs: a product with S_c^-1 in place,
      // where S_c^-1[:, I] would be a copy of its active columns each iteration.
      Eigen::VectorXd spread = Eigen::VectorXd::Zero(x_c.size());
      spread(active) = z;
      x_c.noalias() -= schur_inverse_ * spread;
    }
  }
  cost.condensation_seconds += seconds_since(t);
  return x_c;
}

// With y = A^-1 b and S = P A^-1 P^T: (1 + S_II D_II) z = y_I, then dx = A^-1 (b - P_I^T D_II z).
Eigen::VectorXd CondensedSolve::columns_step(const NonlinearPart& D, const Eigen::VectorXd& b, LinearSolveCost& cost) {
  const std::vector<int>& active = D.active;
  auto t = Clock::now();
  const Eigen::VectorXd y = linear_->solve(b);
  cost.solve_seconds += seconds_since(t);
  if (active.empty()) return y;

  // Columns of S, computed once per factorisation of A for each dof that becomes active.
  t = Clock::now();
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(b.size());
  for (int j : active) {
    if (columns_[j].size() > 0) continue;
    unit[nonlinear_[j]] = 1;
    const Eigen::VectorXd column = linear_->solve(unit);
    unit[nonlinear_[j]] = 0;
    columns_[j] = column(nonlinear_);
  }
  const int a = static_cast<int>(active.size());
  Eigen::MatrixXd S(a, a);
  for (int q = 0; q < a; ++q) S.col(q) = columns_[active[q]](active);
  std::vector<int> active_dofs(a);
  for (int q = 0; q < a; ++q) active_dofs[q] = nonlinear_[active[q]];
  const Eigen::SparseMatrix<double, Eigen::RowMajor> Da = D.on_active();
  Eigen::MatrixXd woodbury = S * Da;
  woodbury.diagonal().array() += 1;
  const Eigen::VectorXd z = woodbury.partialPivLu().solve(y(active_dofs));
  ++cost.dense_factorizations;
  const Eigen::VectorXd w = Da * z;
  Eigen::VectorXd corrected = b;
  for (int q = 0; q < a; ++q) corrected[active_dofs[q]] -= w[q];
  cost.condensation_seconds += seconds_since(t);
  t = Clock::now();
  Eigen::VectorXd dx = linear_->solve(corrected);
  cost.solve_seconds += seconds_since(t);
  return dx;
}

}  // namespace pc

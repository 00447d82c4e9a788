#include "assembly/schur_complement.hpp"

#include <algorithm>

#include "assembly/error.hpp"

namespace pc {
void SchurComplement::analyze(const CsrMatrix& a, const std::vector<int>& interface) {
  analyzed_ = factorized_ = false;
  require(a.rows() == a.cols() && a.rows() > 0, "Schur complement: the matrix is ", a.rows(), " x ", a.cols(),
          ", not square and non-empty");
  require(a.isCompressed(), "Schur complement: the matrix is not compressed (call makeCompressed())");
  require(!interface.empty() && interface.size() < size_t(a.rows()), "Schur complement: ", interface.size(),
          " interface unknowns of ", a.rows(), "; need at least one, and at least one interior unknown");
  std::vector<char> seen(a.rows(), 0);
  for (int dof : interface) {
    require(dof >= 0 && dof < a.rows(), "Schur complement: interface unknown ", dof, " is not in [0, ", a.rows(), ")");
    require(!seen[dof], "Schur complement: interface unknown ", dof, " is listed twice");
    seen[dof] = 1;
  }
  interface_ = interface;
  scale_ = symmetrizing_row_scale(a);
  listvar_.resize(interface.size());
  for (size_t k = 0; k < interface.size(); ++k) listvar_[k] = interface[k] + 1;
  const auto m = static_cast<MUMPS_INT>(interface.size());
  schur_.resize(m, m);
  mumps_.set_pattern(a, scale_ ? MumpsHandle::Symmetric : MumpsHandle::General);
  // The Schur complement on the host, by rows (for LDL^T its lower triangle, Fortran's view).
  mumps_.icntl(19) = 1;
  mumps_->size_schur = m;
  mumps_->listvar_schur = listvar_.data();
  mumps_->schur = schur_.data();
  mumps_->schur_lld = m;
  // The values too: MUMPS may use them to pair 2x2 pivots (a weighted matching) in the symmetric analysis.
  mumps_.set_values(a, scale_ ? *scale_ : Eigen::VectorXd());
  mumps_.run(MumpsHandle::Analyze, "analysis");
  mumps_.release_values();
  analyzed_ = true;
}

bool SchurComplement::is_analyzed_for(const CsrMatrix& a, const std::vector<int>& interface) const {
  return analyzed_ && interface == interface_ && mumps_.has_pattern(a);
}

void SchurComplement::factorize(const CsrMatrix& a) {
  require(analyzed_ && mumps_.has_pattern(a), "Schur complement: factorize() needs analyze() on this pattern first");
  require(Eigen::Map<const Eigen::VectorXd>(a.valuePtr(), a.nonZeros()).allFinite(),
          "Schur complement: the matrix contains NaN/Inf");
  factorized_ = false;
  // New values may have lost (or gained) the symmetry the analysis was made for: then it is made anew.
  // The test's map of transposed entries (an int per entry) is made for each factorisation and freed
  // before MUMPS factorises, the run's peak of memory: a Schur complement is factorised once per step
  // size, and the map costs a pass over the pattern.
  std::optional<Eigen::VectorXd> scale = symmetrizing_row_scale(a);
  if (bool(scale) != bool(scale_)) analyze(a, std::vector<int>(interface_));
  scale_ = std::move(scale);
  // MUMPS reads the values only here: without iterative refinement or error analysis (ICNTL(10),
  // ICNTL(11) at their default 0) a solve uses the factors alone. They are released again, so that nothing
  // can read the caller's matrix after it changed.
  mumps_.set_values(a, scale_ ? *scale_ : Eigen::VectorXd());
  mumps_->schur = schur_.data();
  struct ReleaseValues {
    MumpsHandle& mumps;
    ~ReleaseValues() { mumps.release_values(); }
  } release_values{mumps_};
  mumps_.run(MumpsHandle::Factorize, "factorization");
  if (scale_) {
    // The Schur complement of diag(s) A is diag(s_c) S, symmetric: MUMPS filled its lower triangle by rows,
    // the upper triangle of column-major storage.
    schur_.triangularView<Eigen::StrictlyLower>() = schur_.transpose().triangularView<Eigen::StrictlyLower>();
    for (size_t k = 0; k < interface_.size(); ++k) schur_.row(k) /= (*scale_)[interface_[k]];
  } else {
    // MUMPS returns the unsymmetric Schur complement "by rows" (Fortran's view): column-major storage
    // thus holds its transpose.
    schur_.transposeInPlace();
  }
  factorized_ = true;
}

// The right-hand side of diag(s) A x = diag(s) b when the factorisation is LDL^T.
Eigen::VectorXd SchurComplement::scaled(const Eigen::VectorXd& b) const {
  if (!scale_ || b.size() != scale_->size()) return b;  // a wrong size is solve_phase's to report
  return scale_->cwiseProduct(b);
}

// ICNTL(26) = 1: forward substitution, giving the reduced right-hand side in REDRHS; = 2: REDRHS holds
// the interface solution, and the backward substitution completes x in RHS.
void SchurComplement::solve_phase(Eigen::VectorXd& rhs, Eigen::VectorXd& reduced, int phase) {
  require(factorized_, "Schur complement: solve needs a successful factorize() first");
  require(rhs.size() == mumps_->n, "Schur complement: the right-hand side has ", rhs.size(), " rows, not ", mumps_->n);
  require(rhs.allFinite(), "Schur complement: the right-hand side contains NaN/Inf");
  mumps_.icntl(26) = phase;
  mumps_->rhs = rhs.data();
  mumps_->nrhs = 1;
  mumps_->lrhs = mumps_->n;
  mumps_->redrhs = reduced.data();
  mumps_->lredrhs = static_cast<MUMPS_INT>(reduced.size());
  mumps_.run(MumpsHandle::Solve, phase == 1 ? "reduction" : "expansion");
}

Eigen::VectorXd SchurComplement::reduce(const Eigen::VectorXd& b) {
  Eigen::VectorXd rhs = scaled(b), reduced(interface_.size());
  solve_phase(rhs, reduced, 1);
  if (scale_)
    for (size_t k = 0; k < interface_.size(); ++k) reduced[k] /= (*scale_)[interface_[k]];
  return reduced;
}

Eigen::VectorXd SchurComplement::expand(const Eigen::VectorXd& b, const Eigen::VectorXd& x_interface) {
  require(x_interface.size() == Eigen::Index(interface_.size()), "Schur complement: the interface solution has ",
          x_interface.size(), " entries, not ", interface_.size());
  Eigen::VectorXd x = scaled(b), reduced = x_interface;
  solve_phase(x, reduced, 2);
  for (size_t k = 0; k < interface_.size(); ++k) x[interface_[k]] = x_interface[k];
  return x;
}

}  // namespace pc

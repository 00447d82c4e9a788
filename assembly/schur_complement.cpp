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
  listvar_.resize(interface.size());
  for (size_t k = 0; k < interface.size(); ++k) listvar_[k] = interface[k] + 1;
  const auto m = static_cast<MUMPS_INT>(interface.size());
  schur_.resize(m, m);
  mumps_.set_pattern(a);
  mumps_.icntl(19) = 1;  // the Schur complement, whole, on the host
  mumps_->size_schur = m;
  mumps_->listvar_schur = listvar_.data();
  mumps_->schur = schur_.data();
  mumps_->schur_lld = m;
  mumps_.run(MumpsHandle::Analyze, "analysis");
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
  // MUMPS only reads the values (its C interface is not const-correct), and only here: without iterative
  // refinement or error analysis (ICNTL(10), ICNTL(11) at their default 0) a solve uses the factors alone.
  // The pointer is cleared again, so that nothing can read the caller's matrix after it changed.
  mumps_->a = const_cast<double*>(a.valuePtr());
  mumps_->schur = schur_.data();
  struct ClearValues {
    DMUMPS_STRUC_C& mumps;
    ~ClearValues() { mumps.a = nullptr; }
  } clear_values{*mumps_};
  mumps_.run(MumpsHandle::Factorize, "factorization");
  // MUMPS returns the unsymmetric Schur complement "by rows" (Fortran's view): column-major storage
  // thus holds its transpose.
  schur_.transposeInPlace();
  factorized_ = true;
}

// ICNTL(26) = 1: forward substitution, giving the reduced right-hand side in REDRHS; = 2: REDRHS holds
// the interface solution, and the backward substitution completes x in RHS.
void SchurComplement::solve_phase(Eigen::VectorXd& rhs, Eigen::VectorXd& reduced, int phase) {
  require(factorized_, "Schur complement: solve needs a successful factorize() first");
  require(rhs.size() == mumps_->n, "Schur complement: the right-hand side has ", rhs.size(), " rows, not ",
          mumps_->n);
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
  Eigen::VectorXd rhs = b, reduced(interface_.size());
  solve_phase(rhs, reduced, 1);
  return reduced;
}

Eigen::VectorXd SchurComplement::expand(const Eigen::VectorXd& b, const Eigen::VectorXd& x_interface) {
  require(x_interface.size() == Eigen::Index(interface_.size()), "Schur complement: the interface solution has ",
          x_interface.size(), " entries, not ", interface_.size());
  Eigen::VectorXd x = b, reduced = x_interface;
  solve_phase(x, reduced, 2);
  for (size_t k = 0; k < interface_.size(); ++k) x[interface_[k]] = x_interface[k];
  return x;
}

}  // namespace pc

#include "assembly/solver_cholmod.hpp"

#include <cmath>
#include <vector>

#include <cholmod.h>

#include "assembly/error.hpp"
#include "assembly/solver_base.hpp"
#include "assembly/sparse.hpp"

namespace pc {
namespace {

// Largest |A(r, c) - A(c, r)| accepted, relative to sqrt(|A(r, r) A(c, c)|), the bound of |A(r, c)| for
// a positive definite matrix: loose enough for the round-off of an assembled symmetric form.
constexpr double kSymmetryTolerance = 1e-10;

class CholmodSolver final : public SolverBase {
 public:
  CholmodSolver() {
    cholmod_start(&common_);
    common_.print = 0;  // we throw instead of printing
    common_.supernodal = CHOLMOD_SUPERNODAL;
  }
  ~CholmodSolver() override {
    cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }
  std::string name() const override { return "cholmod"; }
  // L alone holds the factor (LL^T): a solve reads it twice, as an LU solve reads L and U.
  FactorEstimate factor_estimate() const override { return {2 * common_.lnz, common_.fl, true}; }

 private:
  void analyze_pattern() override {
    cholmod_free_factor(&factor_, &common_);
    cholmod_sparse a = view();
    factor_ = cholmod_analyze(&a, &common_);
    if (common_.status == CHOLMOD_OUT_OF_MEMORY) throw OutOfMemory(message(name(), ": the analysis ran out of memory"));
    require(factor_ != nullptr, name(), ": the analysis failed with status ", common_.status);

    const CsrMatrix& m = matrix();
    mirror_slots_.resize(m.nonZeros());
    diagonal_slots_.resize(m.rows());
    for (int row = 0; row < m.rows(); ++row) {
      diagonal_slots_[row] = find_slot(m, row, row);
      for (int slot = m.outerIndexPtr()[row]; slot < m.outerIndexPtr()[row + 1]; ++slot)
        mirror_slots_[slot] = find_slot(m, m.innerIndexPtr()[slot], row);
    }
  }

  void factorize_values() override {
    require_symmetric();
    cholmod_sparse a = view();
    cholmod_factorize(&a, factor_, &common_);
    if (common_.status == CHOLMOD_NOT_POSDEF || factor_->minor < factor_->n)
      fail(name(), ": the matrix is not positive definite (the factorization broke down at column ", factor_->minor,
           " of the reordered matrix); use umfpack or mumps for indefinite matrices");
    // Positive statuses other than the one above are warnings (a tiny diagonal of L), not failures.
    if (common_.status == CHOLMOD_OUT_OF_MEMORY)
      throw OutOfMemory(message(name(), ": the factorization ran out of memory"));
    require(common_.status >= CHOLMOD_OK, name(), ": the factorization failed with status ", common_.status);
  }

  Eigen::VectorXd solve_factorized(const Eigen::VectorXd& b) const override {
    cholmod_dense rhs{};
    rhs.nrow = rhs.nzmax = rhs.d = static_cast<size_t>(b.size());
    rhs.ncol = 1;
    rhs.x = const_cast<double*>(b.data());  // read only
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* solution = cholmod_solve(CHOLMOD_A, factor_, &rhs, &common_);
    require(solution != nullptr, name(), ": the solve failed with status ", common_.status);
    Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(static_cast<double*>(solution->x), b.size());
    cholmod_free_dense(&solution, &common_);
    return x;
  }

  // matrix() seen by CHOLMOD without a copy. Its CSR arrays, read as compressed columns, describe
  // A^T = A. stype = 1 tells CHOLMOD to read the upper triangle of that view (our lower triangle) and
  // is its fastest input for a permuted supernodal factorization. CHOLMOD does not write to it.
  cholmod_sparse view() const {
    const CsrMatrix& m = matrix();
    cholmod_sparse a{};
    a.nrow = a.ncol = static_cast<size_t>(m.rows());
    a.nzmax = static_cast<size_t>(m.nonZeros());
    a.p = const_cast<int*>(m.outerIndexPtr());
    a.i = const_cast<int*>(m.innerIndexPtr());
    a.x = const_cast<double*>(m.valuePtr());
    a.stype = 1;
    a.itype = CHOLMOD_INT;
    a.xtype = CHOLMOD_REAL;
    a.dtype = CHOLMOD_DOUBLE;
    a.sorted = 1;
    a.packed = 1;
    return a;
  }

  // CHOLMOD reads one triangle only: an unsymmetric matrix (say, Dirichlet rows replaced but columns
  // kept) would be solved as another, symmetric one without any error. One pass over the values.
  void require_symmetric() const {
    const CsrMatrix& m = matrix();
    const double* values = m.valuePtr();
    const auto value_at = [values](int slot) { return slot < 0 ? 0.0 : values[slot]; };
    for (int row = 0; row < m.rows(); ++row)
      for (int slot = m.outerIndexPtr()[row]; slot < m.outerIndexPtr()[row + 1]; ++slot) {
        const int col = m.innerIndexPtr()[slot];
        const double mirror = value_at(mirror_slots_[slot]);
        const double scale = std::sqrt(std::abs(value_at(diagonal_slots_[row]) * value_at(diagonal_slots_[col])));
        if (std::abs(values[slot] - mirror) > kSymmetryTolerance * scale)
          fail(name(), ": the matrix is not symmetric: A(", row, ", ", col, ") = ", values[slot], " but A(", col, ", ",
               row, ") = ", mirror, "; use umfpack or mumps for unsymmetric matrices");
      }
  }

  // solve() is const for callers but CHOLMOD records its status and workspace in the common object.
  mutable cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
  std::vector<int> mirror_slots_;    // slot of A(c, r) for the entry A(r, c) in each slot, or -1
  std::vector<int> diagonal_slots_;  // slot of A(r, r) for each row r, or -1
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() { return std::make_unique<CholmodSolver>(); }

}  // namespace pc

PC_REGISTER(pc::linear_solver_registry(),
            {"cholmod", "SuiteSparse CHOLMOD: symmetric positive definite matrices only", {}, pc::make_cholmod_solver})

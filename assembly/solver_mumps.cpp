#include "assembly/solver_mumps.hpp"

#include <vector>

#include <dmumps_c.h>

#include "assembly/error.hpp"
#include "assembly/solver_base.hpp"

namespace pc {
namespace {

// MUMPS job codes and the Fortran handle of MPI_COMM_WORLD, which the sequential library's MPI stub
// accepts without MPI_Init.
constexpr MUMPS_INT kInitialize = -1;
constexpr MUMPS_INT kTerminate = -2;
constexpr MUMPS_INT kAnalyze = 1;
constexpr MUMPS_INT kFactorize = 2;
constexpr MUMPS_INT kSolve = 3;
constexpr MUMPS_INT kUseCommWorld = -987654;
// INFO(1) for a numerically singular matrix (INFO(2) then counts the pivots eliminated before).
constexpr MUMPS_INT kNumericallySingular = -10;

class MumpsSolver final : public SolverBase {
 public:
  MumpsSolver() {
    mumps_.sym = 0;  // general unsymmetric matrix: LU
    mumps_.par = 1;  // the host process works too
    mumps_.comm_fortran = kUseCommWorld;
    run(kInitialize, "initialization");
    // Initialization set the defaults; silence error, warning and statistics output (we throw instead).
    icntl(1) = -1;
    icntl(2) = -1;
    icntl(3) = -1;
    icntl(4) = 0;
  }
  ~MumpsSolver() override {
    mumps_.job = kTerminate;
    dmumps_c(&mumps_);
  }
  std::string name() const override { return "mumps"; }

 private:
  // MUMPS reads the matrix as 1-based coordinates; CSR order is a valid coordinate order, so the values
  // array of matrix() serves as is.
  void analyze_pattern() override {
    const CsrMatrix& a = matrix();
    rows_.resize(a.nonZeros());
    cols_.resize(a.nonZeros());
    for (int row = 0; row < a.rows(); ++row)
      for (int slot = a.outerIndexPtr()[row]; slot < a.outerIndexPtr()[row + 1]; ++slot) {
        rows_[slot] = row + 1;
        cols_[slot] = a.innerIndexPtr()[slot] + 1;
      }
    mumps_.n = static_cast<MUMPS_INT>(a.rows());
    mumps_.nnz = a.nonZeros();
    mumps_.irn = rows_.data();
    mumps_.jcn = cols_.data();
    mumps_.a = nullptr;  // no values: the analysis depends on the pattern only, as analyze() promises
    run(kAnalyze, "analysis");
  }

  void factorize_values() override {
    // MUMPS only reads the values; its C interface is not const-correct.
    mumps_.a = const_cast<double*>(matrix().valuePtr());
    run(kFactorize, "factorization");
  }

  // The right-hand side array is overwritten with the solution.
  Eigen::VectorXd solve_factorized(const Eigen::VectorXd& b) const override {
    Eigen::VectorXd x = b;
    mumps_.rhs = x.data();
    mumps_.nrhs = 1;
    mumps_.lrhs = mumps_.n;
    run(kSolve, "solve");
    return x;
  }

  MUMPS_INT& icntl(int i) { return mumps_.icntl[i - 1]; }  // 1-based, as in the MUMPS manual

  void run(MUMPS_INT job, const char* phase) const {
    mumps_.job = job;
    dmumps_c(&mumps_);
    const MUMPS_INT info1 = mumps_.info[0];
    const MUMPS_INT info2 = mumps_.info[1];
    if (info1 == kNumericallySingular)
      fail(name(), ": the matrix is numerically singular (", phase, " failed with INFO(1) = ", info1,
           ", INFO(2) = ", info2, ")");
    require(info1 >= 0, name(), ": the ", phase, " failed with INFO(1) = ", info1, ", INFO(2) = ", info2,
            " (see the MUMPS manual)");
  }

  // solve() is const for callers but MUMPS writes its statistics into the structure.
  mutable DMUMPS_STRUC_C mumps_{};
  std::vector<MUMPS_INT> rows_;
  std::vector<MUMPS_INT> cols_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_mumps_solver() { return std::make_unique<MumpsSolver>(); }

}  // namespace pc

#include "assembly/linear_solver.hpp"

#include <algorithm>
#include <cmath>

#include "assembly/error.hpp"
#include "assembly/processes.hpp"
#include "assembly/solver_base.hpp"

namespace pc {
namespace {

// Round-off leaves a relative residual of at most about 1e-16 times the condition number: this bound only
// trips on condition numbers beyond ~1e13, where double precision has nothing left to say.
constexpr double kMaxRelativeResidual = 1e-3;

// Index of the first NaN or Inf among values[0, count), or -1.
Eigen::Index first_non_finite(const double* values, Eigen::Index count) {
  const double* found = std::find_if(values, values + count, [](double v) { return !std::isfinite(v); });
  return found == values + count ? -1 : found - values;
}

int row_of_slot(const CsrMatrix& matrix, Eigen::Index slot) {
  const int* outer = matrix.outerIndexPtr();
  return static_cast<int>(std::upper_bound(outer, outer + matrix.rows() + 1, slot) - outer - 1);
}

void require_compressed(const std::string& solver, const CsrMatrix& matrix) {
  // The back ends read the CSR arrays directly; an uncompressed matrix has gaps in them.
  require(matrix.isCompressed(), solver, ": the matrix is not compressed (call makeCompressed())");
}

void require_finite(const std::string& solver, const char* what, const Eigen::VectorXd& vector) {
  const Eigen::Index row = first_non_finite(vector.data(), vector.size());
  require(row < 0, solver, ": the ", what, " contains NaN/Inf at row ", row);
}

}  // namespace

void SolverBase::analyze(const CsrMatrix& matrix) {
  analyzed_ = factorized_ = false;
  require(matrix.rows() == matrix.cols(), name(), ": the matrix is ", matrix.rows(), " x ", matrix.cols(),
          ", not square");
  require(matrix.rows() > 0, name(), ": the matrix is empty (0 x 0)");
  require_compressed(name(), matrix);
  matrix_ = matrix;
  analyze_pattern();
  analyzed_ = true;
}

void SolverBase::factorize(const CsrMatrix& matrix) {
  require(analyzed_, name(), ": factorize() needs a successful analyze() first");
  require(matrix.rows() == matrix_.rows() && matrix.cols() == matrix_.cols(), name(), ": factorize() got a ",
          matrix.rows(), " x ", matrix.cols(), " matrix but analyze() a ", matrix_.rows(), " x ", matrix_.cols(),
          " one");
  require_compressed(name(), matrix);
  require(matrix.nonZeros() == matrix_.nonZeros(), name(), ": factorize() got a matrix with ", matrix.nonZeros(),
          " stored entries but analyze() one with ", matrix_.nonZeros(), "; call analyze() again for a new pattern");
  const int differing_row = first_differing_row(matrix, matrix_);
  require(differing_row < 0, name(), ": factorize() got the size and entry count given to analyze() but ",
          "another pattern (from row ", differing_row, "); call analyze() again for a new pattern");
  if (const Eigen::Index slot = first_non_finite(matrix.valuePtr(), matrix.nonZeros()); slot >= 0)
    fail(name(), ": the matrix contains NaN/Inf at row ", row_of_slot(matrix, slot), " (column ",
         matrix.innerIndexPtr()[slot], ")");

  factorized_ = false;
  std::copy_n(matrix.valuePtr(), matrix.nonZeros(), matrix_.valuePtr());
  factorize_values();
  factorized_ = true;
}

Eigen::VectorXd SolverBase::solve(const Eigen::VectorXd& b) const {
  require(factorized_, name(), ": solve() needs a successful factorize() first");
  require(b.size() == matrix_.rows(), name(), ": the right-hand side has ", b.size(), " rows but the matrix ",
          matrix_.rows());
  require_finite(name(), "right-hand side", b);
  Eigen::VectorXd x = solve_factorized(b);
  // The back ends only report exactly zero pivots. A numerically singular matrix (a body free to move)
  // still yields a "solution", huge and missing b, or NaN: one product with the matrix catches it.
  Eigen::VectorXd product = matrix_ * x;
  if (takes_shares()) processes::sum({product.data(), size_t(product.size())});  // the shares' products
  const double residual = (product - b).norm();
  if (!(residual <= kMaxRelativeResidual * b.norm()))  // written so that NaN fails too
    fail(name(), ": the solution misses the right-hand side (relative residual ", residual / b.norm(),
         "): the matrix is numerically singular (a body free to move? missing Dirichlet conditions?)");
  return x;
}

bool SolverBase::is_analyzed_for(const CsrMatrix& matrix) const {
  return analyzed_ && matrix.isCompressed() && same_pattern(matrix, matrix_);
}

Eigen::VectorXd LinearSolver::solve_once(const CsrMatrix& matrix, const Eigen::VectorXd& b) {
  if (!is_analyzed_for(matrix)) analyze(matrix);
  factorize(matrix);
  return solve(b);
}

Registry<LinearSolverFactory>& linear_solver_registry() {
  static Registry<LinearSolverFactory> registry("linear solver", "solver.linear");
  return registry;
}

std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name) {
  return linear_solver_registry().at(name, "linear solver").create();
}

std::unique_ptr<LinearSolver> make_model_solver(const std::string& name) {
  std::unique_ptr<LinearSolver> solver = make_linear_solver(name);
  require(!processes::distributed() || solver->takes_shares(), "solver.linear = '", name, "' factorises a matrix of ",
          "one process, but this run is distributed over ", processes::count(), " processes; use 'mumps'");
  return solver;
}

std::vector<std::string> linear_solver_names() { return linear_solver_registry().names(); }

}  // namespace pc

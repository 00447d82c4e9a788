#include "assembly/solver_eigen_lu.hpp"

#include <Eigen/SparseLU>

#include "assembly/error.hpp"
#include "assembly/solver_base.hpp"

namespace pc {
namespace {

class EigenLuSolver final : public SolverBase {
 public:
  std::string name() const override { return "eigen-lu"; }

 private:
  using ColumnMajor = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  // SparseLU works on column-major matrices only, hence the copies (SparseLU keeps none of them).
  // analyzePattern() cannot fail (and leaves info() as the last factorization set it).
  void analyze_pattern() override { lu_.analyzePattern(ColumnMajor(matrix())); }

  void factorize_values() override {
    lu_.factorize(ColumnMajor(matrix()));
    // SparseLU's message tells a zero pivot ("... SINGULAR ...") from a memory failure.
    require(lu_.info() == Eigen::Success, name(), ": the factorization failed (SparseLU: ", lu_.lastErrorMessage(),
            ")");
  }

  Eigen::VectorXd solve_factorized(const Eigen::VectorXd& b) const override { return lu_.solve(b); }

  Eigen::SparseLU<ColumnMajor> lu_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_eigen_lu_solver() { return std::make_unique<EigenLuSolver>(); }

}  // namespace pc

PC_REGISTER(pc::linear_solver_registry(),
            {"eigen-lu", "Eigen's SparseLU: the reference, slowest", {}, pc::make_eigen_lu_solver})

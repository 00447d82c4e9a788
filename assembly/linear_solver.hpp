#pragma once
// Sparse direct solvers behind one interface. The work is split the way a Newton loop needs it:
// analyze() once per sparsity pattern (ordering, symbolic factorisation), factorize() whenever the
// values change, solve() for each right-hand side. A singular matrix or a failed factorisation throws
// pc::Error naming the solver and its status; no solver returns garbage silently.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/registry.hpp"
#include "assembly/sparse.hpp"

namespace pc {

// What a symbolic analysis predicts of the factors (a cost model's input): 0 where the back end does not tell.
struct FactorEstimate {
  double entries = 0;      // read by a forward and backward substitution: L and U, or L twice (LL^T, LDL^T)
  double flops = 0;        // of the numeric factorisation
  bool symmetric = false;  // a symmetric factorisation (LL^T, LDL^T), of half the memory of `entries`
  // The solver's own prediction of its in-core working memory, factors included: of all processes and of
  // the largest (MUMPS's INFOG(17) and INFOG(16)); 0 where the back end does not tell.
  double memory_bytes = 0;
  double largest_process_memory_bytes = 0;
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual std::string name() const = 0;
  // Symbolic phase for the pattern of a (square, compressed) matrix.
  virtual void analyze(const CsrMatrix& matrix) = 0;
  // Numeric factorisation; the matrix must have the pattern given to analyze().
  virtual void factorize(const CsrMatrix& matrix) = 0;
  // Solves A x = b with the last factorisation. Throws when x misses b by more than 1e-3 relative,
  // the mark of a numerically singular matrix.
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) const = 0;
  // True when the last analyze() succeeded on exactly this pattern, so that factorize() may follow.
  virtual bool is_analyzed_for(const CsrMatrix& matrix) const = 0;
  // After analyze(): the predicted size and work of the factorisation.
  virtual FactorEstimate factor_estimate() const { return {}; }
  // Whether each process of a distributed run (assembly/processes.hpp) gives its share of the matrix, the
  // solver factorising their sum (MUMPS), rather than a whole matrix of its own.
  virtual bool takes_shares() const { return false; }

  // analyze (when the pattern is new) + factorize + solve, for one-off systems.
  Eigen::VectorXd solve_once(const CsrMatrix& matrix, const Eigen::VectorXd& b);
};

// The solvers a scene can name (solver.linear), each registered in its own file: "eigen-lu" (Eigen's
// SparseLU, the reference), "umfpack", "mumps" (sequential MUMPS, the default of NewtonOptions), "cholmod" (symmetric
// positive definite matrices only).
using LinearSolverFactory = std::unique_ptr<LinearSolver> (*)();
Registry<LinearSolverFactory>& linear_solver_registry();
// Throws on an unknown name, listing the registered ones.
std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name = "umfpack");
// The same, for a model distributed over the processes of the run: a solver that takes their shares,
// or pc::Error naming the solver and the number of processes.
std::unique_ptr<LinearSolver> make_model_solver(const std::string& name);
std::vector<std::string> linear_solver_names();

}  // namespace pc

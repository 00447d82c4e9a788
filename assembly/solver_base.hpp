#pragma once
// Internal to the solver back ends (solver_*.cpp): the argument checks and the analyze -> factorize ->
// solve bookkeeping every back end shares, so that each one only talks to its library.
#include "assembly/linear_solver.hpp"

namespace pc {

class SolverBase : public LinearSolver {
 public:
  SolverBase() = default;
  // Back ends own library handles (factors, MUMPS instances) that must not be shared.
  SolverBase(const SolverBase&) = delete;
  SolverBase& operator=(const SolverBase&) = delete;

  void analyze(const CsrMatrix& matrix) final;
  void factorize(const CsrMatrix& matrix) final;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const final;
  bool is_analyzed_for(const CsrMatrix& matrix) const final;

 protected:
  // The solver's own copy of the matrix last given to analyze() or factorize(). The caller may thus
  // reassemble or destroy its matrix after factorize(); back ends may keep pointers into these arrays,
  // which stay in place from one analyze() to the next (factorize() only overwrites the values).
  const CsrMatrix& matrix() const { return matrix_; }

 private:
  // Called once the checks passed, with matrix() holding the new pattern / the new values.
  virtual void analyze_pattern() = 0;
  virtual void factorize_values() = 0;
  virtual Eigen::VectorXd solve_factorized(const Eigen::VectorXd& b) const = 0;

  CsrMatrix matrix_;
  bool analyzed_ = false;
  bool factorized_ = false;
};

}  // namespace pc

#include "models/solvers/nonlinear_problem.hpp"

#include "assembly/error.hpp"

namespace pc {

void NonlinearProblem::nonlinear_part(std::vector<double>& values) {
  const CsrMatrix& J = jacobian();
  const CsrMatrix& A = linear_jacobian();
  require(J.rows() == A.rows() && J.nonZeros() == A.nonZeros(),
          "nonlinear_part(): the Jacobian and its linear part differ in pattern");
  values.clear();
  for (int row : nonlinear_dofs())
    for (int k = A.outerIndexPtr()[row]; k < A.outerIndexPtr()[row + 1]; ++k)
      values.push_back(J.valuePtr()[k] - A.valuePtr()[k]);
}

}  // namespace pc

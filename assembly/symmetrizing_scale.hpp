#pragma once
// A diagonal row scaling that makes a square matrix symmetric, when there is one: s with
//   s_i A_ij = s_j A_ji   for every entry,
// so that diag(s) A x = diag(s) b can be solved by a symmetric (LDL^T) factorisation, with half the
// entries and half the flops of an LU one. The systems of this field are often of that kind without being
// symmetric as assembled: the Jacobian of the piezoelectric body in (v, phi) is [K C; c C^T -G] with c the
// time scheme's factor of u in v, symmetric once the Gauss law's rows are divided by c. The scale is found
// from the matrix alone, so that any model whose operator is self-adjoint up to the weights of its
// equations gets it, and a nonsymmetric term (a non-associated friction law, a pressure-dependent
// conductance) makes the test fail and the caller keep LU.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "assembly/sparse.hpp"

namespace pc {

// The test for the matrices of one pattern: the slot of each entry's transpose is found once (a solver
// refactorising new values of the same pattern then pays one pass over the values).
class RowSymmetrizer {
 public:
  explicit RowSymmetrizer(const CsrMatrix& pattern);
  // Whether `a` has the size and number of entries of the pattern this was made for (the caller keeps
  // one per analysed pattern; the entries themselves are not compared).
  bool has_pattern(const CsrMatrix& a) const;
  // The scale for the values of `a` (which must have the pattern), or nullopt when the pattern is not
  // symmetric or some entry pair disagrees by more than `tolerance` times the larger of the two scaled
  // rows' largest entries (so that entries that are sums with cancellation, exact only to round-off of
  // their row, do not fail the test). The scale of each connected component is fixed by its lowest row,
  // whose scale is 1; rows without off-diagonal entries keep 1. Signs may differ from row to row (an
  // indefinite symmetric matrix is fine).
  std::optional<Eigen::VectorXd> scale(const CsrMatrix& a, double tolerance = 1e-12) const;
  // Collective (assembly/processes.hpp): the scale of the sum of the processes' shares of a matrix, each
  // process giving its own (made for this pattern), the same scale on every process, or nullopt on every
  // process. Each share's scale, normalised by the value of its lowest row of the largest magnitude, must
  // agree with every other share's on the rows they both hold (to `tolerance`), each connected component
  // of a share normalised on its own; rows that a share holds without a strong pair (at its edge) take
  // the others' value. Each share is then checked with the agreed scale, so that the sum is symmetric
  // with it. On one process, scale(share) normalised so.
  std::optional<Eigen::VectorXd> scale_of_shares(const CsrMatrix& share, double tolerance = 1e-12) const;

 private:
  // scale(), and the component of each row: the row whose scale was set to 1.
  std::optional<Eigen::VectorXd> scale(const CsrMatrix& a, double tolerance, std::vector<int>* component) const;
  // Whether every entry pair of `a` agrees under the scale s, to `tolerance` of the larger scaled row.
  bool symmetric_with(const CsrMatrix& a, const Eigen::VectorXd& s, double tolerance) const;
  // The same, with each row's largest |entry| given (scale() has them already: one pass fewer per
  // factorisation of the full path).
  bool symmetric_with(const CsrMatrix& a, const Eigen::VectorXd& s, double tolerance,
                      const std::vector<double>& row_max) const;

  long rows_ = 0, nonzeros_ = 0;
  std::vector<int> mirror_;  // the slot of (j, i) for the slot of (i, j); empty: the pattern is not symmetric
};

// RowSymmetrizer(a).scale(a, tolerance): for a matrix met once.
std::optional<Eigen::VectorXd> symmetrizing_row_scale(const CsrMatrix& a, double tolerance = 1e-12);

}  // namespace pc

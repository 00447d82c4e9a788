#pragma once
// Static condensation of a sparse matrix onto a few of its unknowns (the interface c; the others are the
// interior i), by MUMPS: the factorisation eliminates the interior and returns the dense Schur complement
//   S = A_cc - A_ci A_ii^-1 A_ic,
// and a solve of A x = b splits into
//   reduce:  r = b_c - A_ci A_ii^-1 b_i        (a forward substitution)
//   a dense solve of the small interface system, which the caller may modify (e.g. S + D for a contact
//   tangent D on c): S' x_c = r
//   expand:  x_i = A_ii^-1 (b_i - A_ic x_c)    (a backward substitution).
// A matrix that a row scaling makes symmetric (assembly/symmetrizing_scale.hpp) is factorised as LDL^T,
// with half the entries and flops, any other as LU; the choice is made on each factorisation's values.
// Only the interior block must be nonsingular: A itself may be singular (a body held by its contact only),
// the modified S' then is not.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "assembly/mumps_handle.hpp"
#include "assembly/sparse.hpp"
#include "assembly/symmetrizing_scale.hpp"

namespace pc {

class SchurComplement {
 public:
  // Symbolic phase for the pattern of `a` with these interface unknowns (0-based, distinct, any order:
  // the Schur complement's rows and columns follow it).
  void analyze(const CsrMatrix& a, const std::vector<int>& interface);
  bool is_analyzed_for(const CsrMatrix& a, const std::vector<int>& interface) const;
  // Numeric phase: factorises A_ii and computes S. The pattern must be the analysed one; `a` is read
  // during the call only (the solves need the factors, not the matrix).
  void factorize(const CsrMatrix& a);

  const std::vector<int>& interface() const { return interface_; }
  // Whether the last analysis is for LDL^T (a row scaling makes the matrix symmetric).
  bool symmetric() const { return bool(scale_); }
  const Eigen::MatrixXd& schur() const { return schur_; }
  Eigen::VectorXd reduce(const Eigen::VectorXd& b);
  // The whole solution: x_interface at the interface, the interior from the backward substitution.
  Eigen::VectorXd expand(const Eigen::VectorXd& b, const Eigen::VectorXd& x_interface);

 private:
  void solve_phase(Eigen::VectorXd& rhs, Eigen::VectorXd& reduced, int phase);
  Eigen::VectorXd scaled(const Eigen::VectorXd& b) const;

  // MUMPS keeps the pattern (its coordinates); the values it reads only while it factorises, from the
  // caller's matrix, so that no copy of the matrix is kept (it would be the largest after the factors).
  MumpsHandle mumps_{"Schur complement (MUMPS)"};
  std::vector<int> interface_;
  std::vector<MUMPS_INT> listvar_;
  Eigen::MatrixXd schur_;
  std::optional<Eigen::VectorXd> scale_;  // the symmetrizing row scale, when the factorisation is LDL^T
  bool analyzed_ = false, factorized_ = false;
};

}  // namespace pc

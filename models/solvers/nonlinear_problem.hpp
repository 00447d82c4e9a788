#pragma once
// What Newton and its linear strategies see of a problem R(x) = 0 (GetFEM's PB with compute_residual and
// compute_tangent_matrix, MFEM's Operator with Mult and GetGradient): its residual and Jacobian on the free
// values x, the part of the Jacobian that does not depend on x (so that a factorisation of it can be kept),
// and the block structure by which convergence is judged. Model is one; a test's hand-written system is
// another, so the solvers never depend on how a problem is assembled.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/sparse.hpp"

namespace pc {

// The free values [begin, begin + size) of x: one unknown of the problem, with its own units (a velocity,
// a potential), so that Newton measures each block's residual against its own scale.
struct ProblemBlock {
  std::string name;
  int begin = 0;
  int size = 0;
};

class NonlinearProblem {
 public:
  virtual ~NonlinearProblem() = default;

  // Residual R(x) at the current free values and, if tangent, its Jacobian J = dR/dx.
  virtual void assemble(bool tangent) = 0;
  virtual const Eigen::VectorXd& residual() const = 0;
  virtual const CsrMatrix& jacobian() const = 0;
  // Seconds spent so far on the Jacobian alone (summed over all calls), in assemble() and in jacobian() or
  // nonlinear_part() where a problem forms them on demand, so that a solver can split its assembly time
  // into residual and Jacobian; 0 for a problem that cannot tell them apart (its whole assembly then counts
  // as the residual's).
  virtual double jacobian_assembly_seconds() const { return 0; }
  // The part A of J that does not depend on x, with J's pattern. Its version changes only when its values
  // do, so a factorisation of A can be kept across iterations and solves.
  virtual const CsrMatrix& linear_jacobian() = 0;
  virtual std::uint64_t linear_jacobian_version() = 0;
  // The free dofs outside whose rows and columns J - A vanishes (sorted).
  virtual const std::vector<int>& nonlinear_dofs() = 0;
  // J - A on the rows of nonlinear_dofs(), in the pattern J and A share: the rows one after the other,
  // each with a value for every slot of that row of linear_jacobian(). This is all a condensed solve
  // reads of J; a problem that sums its nonlinear terms apart (Model) gives it without forming J, and
  // exactly, where the default takes J's values less A's.
  virtual void nonlinear_part(std::vector<double>& values);
  // The nonlinear terms' residual N(x) on the rows of nonlinear_dofs(), in their order, at the current free
  // values, and their tangent for nonlinear_part() at the same values: R(x) = A x + N(x) + c with A the
  // linear part and c constant within the solve. It reads only the nonlinear dofs' values, and assembles
  // nothing else, so Newton can iterate on the contact dofs alone (models/solvers/reduced_contact_system.hpp)
  // with the interior solved once per solve. Returns false for a problem that cannot give it (the default;
  // Newton then iterates on the whole system).
  virtual bool assemble_nonlinear_rows(Eigen::VectorXd& rows) {
    (void)rows;
    return false;
  }

  // The blocks, in order, covering x.
  virtual std::vector<ProblemBlock> blocks() const = 0;
  // Per block, the size of the largest single term the last residual summed: the reference of Newton's
  // relative test, besides the block's first residual.
  virtual std::vector<double> residual_scales() const = 0;
  // Per block, the gross size of the terms the last residual summed, before they cancel (for a linear term
  // K x, the norm of |K| |x|): the residual's round-off floor is a few machine epsilons times it, however
  // small the net terms are. A problem that cannot tell defaults to residual_scales().
  virtual std::vector<double> round_off_scales() const { return residual_scales(); }

  virtual Eigen::VectorXd free_values() const = 0;
  virtual void set_free_values(const Eigen::VectorXd& x) = 0;
  virtual void add_to_free_values(const Eigen::VectorXd& step) = 0;  // x += step

  // Named quantities reported with each solve (e.g. contact nodes in compression).
  virtual std::map<std::string, double> diagnostics() const = 0;
};

}  // namespace pc

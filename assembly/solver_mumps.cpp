#include "assembly/solver_mumps.hpp"

#include "assembly/mumps_handle.hpp"
#include "assembly/solver_base.hpp"

namespace pc {
namespace {

class MumpsSolver final : public SolverBase {
 public:
  std::string name() const override { return "mumps"; }

 private:
  void analyze_pattern() override {
    mumps_.set_pattern(matrix());
    mumps_.run(MumpsHandle::Analyze, "analysis");
    // INFOG(20): entries in the factors, negative in millions; RINFOG(1): flops of the elimination.
    const double entries = mumps_->infog[19];
    estimate_ = {entries < 0 ? -entries * 1e6 : entries, mumps_->rinfog[0]};
  }
  FactorEstimate factor_estimate() const override { return estimate_; }

  void factorize_values() override {
    // MUMPS only reads the values; its C interface is not const-correct.
    mumps_->a = const_cast<double*>(matrix().valuePtr());
    mumps_.run(MumpsHandle::Factorize, "factorization");
  }

  // The right-hand side array is overwritten with the solution.
  Eigen::VectorXd solve_factorized(const Eigen::VectorXd& b) const override {
    Eigen::VectorXd x = b;
    mumps_->rhs = x.data();
    mumps_->nrhs = 1;
    mumps_->lrhs = mumps_->n;
    mumps_.run(MumpsHandle::Solve, "solve");
    return x;
  }

  // solve() is const for callers but MUMPS writes its statistics into the structure.
  mutable MumpsHandle mumps_{"mumps"};
  FactorEstimate estimate_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_mumps_solver() { return std::make_unique<MumpsSolver>(); }

}  // namespace pc

PC_REGISTER(pc::linear_solver_registry(), {"mumps", "MUMPS, sequential, with its own ordering (the default: 2x faster factorisations and 3-6x faster solves than UMFPACK on the shipped scenes)", {}, pc::make_mumps_solver})

#pragma once
// The scales of a model's residual, per unknown, gathered piece by piece while the bricks' contributions
// are added (Model::assemble): the norm on the free dofs of the largest single piece, the scale of the
// forces that balance (Newton's reference), and its gross size, the residual's round-off floor over machine
// epsilon. A linear piece K x is measured by the norm of (|K| |x|)_i = sum_j |K_ij| |x_j| as well: the
// computed product is off by at most a few eps (|K| |x|)_i in row i however much its terms cancel (Oettli
// and Prager's componentwise bound), while its net size K x vanishes where they balance exactly (a uniform
// piezoelectric stress has no net force on an interior node), which leaves a net scale that is itself
// round-off.
#include <map>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/dof_layout.hpp"
#include "assembly/sparse.hpp"

namespace pc {

class ResidualScaling {
 public:
  // Every unknown's scales back to zero, for a new assembly.
  void reset(const std::vector<std::string>& unknowns);
  // A piece of block u with net size `net` and gross size `gross` (>= net for a linear piece's |K| |x|).
  void record(const std::string& u, double net, double gross);
  // `global` is u's free numbering (DofLayout::global_indices, -1 on an eliminated dof): the pieces are
  // measured on the free dofs.
  // Records piece r of u by its norm, with gross size `gross`.
  void measure(const std::string& u, const Eigen::VectorXd& r, std::span<const int> global, double gross);
  // Adds r into `out` and records its norm, in one pass (the residual is bandwidth-bound).
  void add_measured(const std::string& u, const Eigen::VectorXd& r, std::span<const int> global, Eigen::VectorXd& out);
  // Adds the product K x into `out` and records its net and gross sizes, in one pass over K (the
  // residual's largest operand). Distributed, K is this process's share and the rows are summed over the
  // processes.
  void add_measured_product(const std::string& u, const CsrView& K, const Eigen::VectorXd& x,
                            std::span<const int> global, Eigen::VectorXd& out);
  // A brick's own unknown (a multiplier) starts balanced at zero with no force in it, which would leave
  // Newton no scale to measure it by: its residual is in the units of its `like` field's, and takes that
  // block's scale when its own is smaller.
  void at_least_that_of(const std::string& own, const std::string& like);

  // Per unknown, in the layout's order (its blocks').
  std::vector<double> residual_scales(const DofLayout& layout) const;
  std::vector<double> round_off_scales(const DofLayout& layout) const;
  // By unknown, as a residual snapshot keeps them, and put back from one.
  const std::map<std::string, double>& residual_by_unknown() const { return residual_; }
  const std::map<std::string, double>& round_off_by_unknown() const { return round_off_; }
  void restore(std::map<std::string, double> residual, std::map<std::string, double> round_off);

 private:
  std::map<std::string, double> residual_;
  std::map<std::string, double> round_off_;
  std::vector<double> product_rows_, gross_rows_;  // scratch of the products, per row
};

}  // namespace pc

#pragma once
// Numbering of a system's unknowns: several fields (e.g. velocity and potential) stacked one after the
// other, with the dofs fixed by Dirichlet conditions eliminated (they get no global index; their values
// stay in the field vectors, so residuals computed from full field vectors include the lifting), and
// groups of tied dofs sharing one global index (one unknown value over a region, e.g. the potential of a
// floating electrode). Tying by a shared index is exact elimination: the group's residual is the sum of
// its dofs' residuals, a step moves all of them by the same amount, and the matrix stays symmetric.
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace pc {

class DofLayout {
 public:
  // Adds a field of num_dofs dofs, of which `constrained` are eliminated and each group of `tied` shares
  // one global index (groups must be disjoint and free of constrained dofs); returns the field's index.
  int add_field(const std::string& name, int num_dofs, const std::vector<int>& constrained = {},
                const std::vector<std::vector<int>>& tied = {});

  int num_fields() const { return static_cast<int>(names_.size()); }
  const std::string& field_name(int field) const { return names_[field]; }
  int field_index(const std::string& name) const;  // throws naming the known fields
  int size() const { return size_; }               // free dofs of all fields
  int num_free(int field) const { return free_counts_[field]; }
  // Global index of each field dof, -1 where it is constrained; the dofs of a tied group share theirs.
  std::span<const int> global_indices(int field) const { return global_[field]; }

  // global[g(d)] += field_vector[d] over free dofs (a tied group's entries are summed: residuals).
  void add_to_global(int field, const Eigen::VectorXd& field_vector, Eigen::VectorXd& global) const;
  // global[g(d)] = field_vector[d] over free dofs (a tied group holds one value: values).
  void copy_to_global(int field, const Eigen::VectorXd& field_vector, Eigen::VectorXd& global) const;
  // field_vector[d] += scale * global[g(d)] over free dofs (constrained dofs are untouched).
  void add_from_global(int field, const Eigen::VectorXd& global, Eigen::VectorXd& field_vector,
                       double scale = 1.0) const;

 private:
  std::vector<std::string> names_;
  std::vector<std::vector<int>> global_;
  std::vector<int> free_counts_;
  int size_ = 0;
};

}  // namespace pc

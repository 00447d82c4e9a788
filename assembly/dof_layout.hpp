#pragma once
// Numbering of a system's unknowns: several fields (e.g. velocity and potential) stacked one after the
// other, with the dofs fixed by Dirichlet conditions eliminated (they get no global index; their values
// stay in the field vectors, so residuals computed from full field vectors include the lifting).
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace pc {

class DofLayout {
 public:
  // Adds a field of num_dofs dofs, of which `constrained` are eliminated; returns its index.
  int add_field(const std::string& name, int num_dofs, const std::vector<int>& constrained = {});

  int num_fields() const { return static_cast<int>(names_.size()); }
  const std::string& field_name(int field) const { return names_[field]; }
  int field_index(const std::string& name) const;  // throws naming the known fields
  int size() const { return size_; }               // free dofs of all fields
  int num_free(int field) const { return free_counts_[field]; }
  // Global index of each field dof, -1 where it is constrained.
  std::span<const int> global_indices(int field) const { return global_[field]; }

  // global[g(d)] += field_vector[d] over free dofs.
  void add_to_global(int field, const Eigen::VectorXd& field_vector, Eigen::VectorXd& global) const;
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

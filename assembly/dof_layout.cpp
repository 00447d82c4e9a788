#include "assembly/dof_layout.hpp"

#include <algorithm>

#include "assembly/error.hpp"

namespace pc {

int DofLayout::add_field(const std::string& name, int num_dofs, const std::vector<int>& constrained,
                         const std::vector<std::vector<int>>& tied) {
  for (const std::string& n : names_) require(n != name, "DofLayout: field '", name, "' added twice");
  constexpr int kFree = -2, kConstrained = -1;
  std::vector<int> global(num_dofs, kFree);
  for (int d : constrained) {
    require(d >= 0 && d < num_dofs, "DofLayout: constrained dof ", d, " of field '", name, "' out of range [0, ",
            num_dofs, ")");
    global[d] = kConstrained;
  }
  // A tied dof shares the index of its group's leader, the group's smallest dof, numbered first.
  std::vector<int> leader(num_dofs, -1);
  for (const std::vector<int>& group : tied) {
    if (group.empty()) continue;
    const int smallest = *std::min_element(group.begin(), group.end());
    for (int d : group) {
      require(d >= 0 && d < num_dofs, "DofLayout: tied dof ", d, " of field '", name, "' out of range [0, ", num_dofs,
              ")");
      require(global[d] != kConstrained, "DofLayout: dof ", d, " of field '", name, "' is both constrained and tied");
      require(leader[d] < 0, "DofLayout: dof ", d, " of field '", name, "' is in two tied groups");
      leader[d] = smallest;
    }
  }
  int free = 0;
  for (int d = 0; d < num_dofs; ++d) {
    if (global[d] == kConstrained) continue;
    global[d] = leader[d] >= 0 && leader[d] < d ? global[leader[d]] : size_ + free++;
  }
  names_.push_back(name);
  global_.push_back(std::move(global));
  free_counts_.push_back(free);
  size_ += free;
  return num_fields() - 1;
}

int DofLayout::field_index(const std::string& name) const {
  std::string known;
  for (int f = 0; f < num_fields(); ++f) {
    if (names_[f] == name) return f;
    known += (f ? ", " : "") + names_[f];
  }
  fail("DofLayout: unknown field '", name, "' (known: ", known, ")");
}

void DofLayout::add_to_global(int field, const Eigen::VectorXd& field_vector, Eigen::VectorXd& global) const {
  const std::vector<int>& map = global_[field];
  require(field_vector.size() == int(map.size()) && global.size() == size_, "DofLayout: size mismatch for field '",
          names_[field], "'");
  for (int d = 0; d < int(map.size()); ++d)
    if (map[d] >= 0) global[map[d]] += field_vector[d];
}

void DofLayout::copy_to_global(int field, const Eigen::VectorXd& field_vector, Eigen::VectorXd& global) const {
  const std::vector<int>& map = global_[field];
  require(field_vector.size() == int(map.size()) && global.size() == size_, "DofLayout: size mismatch for field '",
          names_[field], "'");
  for (int d = 0; d < int(map.size()); ++d)
    if (map[d] >= 0) global[map[d]] = field_vector[d];
}

void DofLayout::add_from_global(int field, const Eigen::VectorXd& global, Eigen::VectorXd& field_vector,
                                double scale) const {
  const std::vector<int>& map = global_[field];
  require(field_vector.size() == int(map.size()) && global.size() == size_, "DofLayout: size mismatch for field '",
          names_[field], "'");
  for (int d = 0; d < int(map.size()); ++d)
    if (map[d] >= 0) field_vector[d] += scale * global[map[d]];
}

}  // namespace pc

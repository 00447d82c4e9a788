#include "assembly/term.hpp"

#include <algorithm>

#include "assembly/error.hpp"

namespace pc {

Term::Term(std::string name, Integration integration, std::vector<FieldUse> fields, std::vector<int> tests,
           std::vector<Coupling> couplings)
    : name_(std::move(name)),
      integration_(integration),
      fields_(std::move(fields)),
      tests_(std::move(tests)),
      couplings_(std::move(couplings)) {
  const int n = static_cast<int>(fields_.size());
  require(n > 0, "term '", name_, "' names no field");
  for (int a = 0; a < n; ++a) {
    require(!fields_[a].name.empty(), "term '", name_, "': field ", a, " has no name");
    require(!(integration_ == Integration::Faces && fields_[a].gradient), "term '", name_,
            "' is integrated on faces, where gradients are not available, but asks for the gradient of '",
            fields_[a].name, "'");
    for (int b = 0; b < a; ++b)
      require(fields_[a].name != fields_[b].name, "term '", name_, "' names field '", fields_[a].name, "' twice");
  }
  for (int t : tests_) require(t >= 0 && t < n, "term '", name_, "': test field index ", t, " out of range");
  for (const Coupling& c : couplings_) {
    require(test_index(c.test) >= 0, "term '", name_, "': coupling row ", c.test, " is not a test field");
    require(c.trial >= 0 && c.trial < n, "term '", name_, "': coupling column ", c.trial, " out of range");
  }
}

int Term::field_index(const std::string& name) const {
  for (int f = 0; f < int(fields_.size()); ++f)
    if (fields_[f].name == name) return f;
  return -1;
}

int Term::test_index(int field) const {
  const auto it = std::find(tests_.begin(), tests_.end(), field);
  return it == tests_.end() ? -1 : static_cast<int>(it - tests_.begin());
}

}  // namespace pc

#include "bricks/dirichlet_brick.hpp"

#include <cmath>
#include <utility>

#include "assembly/error.hpp"

namespace pc {

DirichletBrick::DirichletBrick(std::string unknown, std::string region, std::vector<int> components, Value value,
                               bool time_dependent)
    : condition_{std::move(unknown), std::move(region), std::move(components), std::move(value)},
      time_dependent_(time_dependent) {
  require(static_cast<bool>(condition_.value), "brick '", name(), "': the value function is empty");
  for (int c : condition_.components)
    require(c >= 0 && c < 3, "brick '", name(), "': component ", c, " is out of range (0 to 2)");
}

DirichletBrick::DirichletBrick(std::string unknown, std::string region, std::vector<int> components, double value)
    : DirichletBrick(
          std::move(unknown), std::move(region), std::move(components),
          [value](const double*, double, double* out) {
            for (int c = 0; c < 3; ++c) out[c] = value;
          },
          false) {
  require(std::isfinite(value), "brick '", name(), "': the prescribed value is ", value);
}

DirichletBrick DirichletBrick::clamp(std::string unknown, std::string region, std::vector<int> components) {
  return DirichletBrick(std::move(unknown), std::move(region), std::move(components), 0.0);
}

std::string DirichletBrick::name() const {
  return "Dirichlet condition on " + condition_.unknown + " over " + condition_.region;
}

}  // namespace pc

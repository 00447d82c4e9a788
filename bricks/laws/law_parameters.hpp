#pragma once
// Checks of law parameters, run by a brick when it is built: each throws pc::Error naming the brick, the
// law, the parameter and its value, so a bad input file is fixed without opening the source.
#include <cmath>
#include <string>

#include "assembly/error.hpp"

namespace pc {

inline void require_finite_parameter(const std::string& brick, const char* law, const char* parameter, double value) {
  require(std::isfinite(value), "brick '", brick, "': ", law, " parameter ", parameter, " = ", value,
          " must be finite");
}

// value finite and value >= lower.
inline void require_parameter_at_least(const std::string& brick, const char* law, const char* parameter, double value,
                                       double lower) {
  require(std::isfinite(value) && value >= lower, "brick '", brick, "': ", law, " parameter ", parameter, " = ",
          value, " must be finite and >= ", lower);
}

// value finite and value > 0.
inline void require_positive_parameter(const std::string& brick, const char* law, const char* parameter,
                                       double value) {
  require(std::isfinite(value) && value > 0, "brick '", brick, "': ", law, " parameter ", parameter, " = ", value,
          " must be finite and > 0");
}

// Runs law.validate(brick) if the law has one (a user's law may not).
template <class Law>
void validate_law(const Law& law, const std::string& brick) {
  if constexpr (requires { law.validate(brick); }) law.validate(brick);
}

}  // namespace pc

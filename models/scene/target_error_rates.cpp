#include "models/scene/target_error_rates.hpp"

#include <cmath>
#include <limits>

#include "assembly/error.hpp"
#include "models/scene/target_error_format.hpp"

namespace pc {

RateCheck check_rate(const std::string& what, const std::vector<double>& resolutions, const std::vector<double>& errors,
                     double theory) {
  require(resolutions.size() == errors.size(), "check_rate: ", resolutions.size(), " resolutions for ", errors.size(),
          " errors");
  RateCheck check;
  check.theory = theory;
  check.measured = std::numeric_limits<double>::quiet_NaN();
  const size_t n = errors.size();
  double mean_x = 0, mean_y = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!(resolutions[i] > 0 && errors[i] > 0)) return check;  // no logarithm: no rate
    mean_x += std::log(resolutions[i]) / double(n);
    mean_y += std::log(errors[i]) / double(n);
  }
  double sxx = 0, sxy = 0;
  for (size_t i = 0; i < n; ++i) {
    const double dx = std::log(resolutions[i]) - mean_x;
    sxx += dx * dx;
    sxy += dx * (std::log(errors[i]) - mean_y);
  }
  if (!(sxx > 0)) return check;  // one resolution: no rate
  check.measured = -sxy / sxx;
  check.far_below = check.measured < kFarBelowTheory * theory;
  if (check.far_below)
    check.problem =
        message(what, " ", three_digits(check.measured), " is below half the theory's ", three_digits(theory));
  return check;
}

}  // namespace pc

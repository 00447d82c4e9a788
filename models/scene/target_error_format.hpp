#pragma once
// How the target-error mode's lines and summary text write numbers (models/scene/target_error.hpp):
// three significant digits, errors as percentages.
#include <cstdio>
#include <string>

namespace pc {

inline std::string three_digits(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

// A relative error as a percentage: 0.106 is "10.6 %".
inline std::string percent(double fraction) { return three_digits(100 * fraction) + " %"; }

}  // namespace pc

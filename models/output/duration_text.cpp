#include "models/output/duration_text.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>

namespace pc {
namespace {

// The value to three significant digits, as "%.3g" prints it.
double three_digits(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return std::strtod(text, nullptr);
}

struct DurationUnit {
  double seconds;
  const char* name;
  double next;  // how many make the next unit (exact, where 1e-3 / 1e-6 is not)
};
constexpr DurationUnit kUnits[] = {
    {1e-6, "us", 1000}, {1e-3, "ms", 1000}, {1, "s", 60}, {60, "min", 60}, {3600, "h", 0}};
constexpr size_t kUnitCount = std::size(kUnits);

}  // namespace

std::string describe_duration(double seconds) {
  if (!std::isfinite(seconds)) return "?";
  if (seconds < 0) return "-" + describe_duration(-seconds);
  if (seconds == 0) return "0 s";
  size_t k = 0;  // the largest unit the duration is at least one of (us below that)
  while (k + 1 < kUnitCount && seconds >= kUnits[k + 1].seconds) ++k;
  double value = three_digits(seconds / kUnits[k].seconds);
  // Rounded up to the next unit's size (59.96 s is 60.0 s): one of the next unit.
  if (k + 1 < kUnitCount && value >= kUnits[k].next) {
    ++k;
    value = 1;
  }
  char text[48];
  std::snprintf(text, sizeof text, "%.3g %s", value, kUnits[k].name);
  return text;
}

}  // namespace pc

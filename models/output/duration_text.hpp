#pragma once
// A duration as the run's lines show it: three significant digits in the unit that suits, us below a
// millisecond, then ms, s, min and h ("281 us", "96.3 ms", "4.21 s", "12.5 min", "2.5 h"). Every line of
// a run that prints a duration (predictions, the time left, a run's wall time, the condensation choice's
// figures) writes it with this function, so that one run's figures read alike.
#include <string>

namespace pc {

// Rounding may carry into the next unit: 59.96 s is "1 min", not "60 s". A non-finite value is "?".
std::string describe_duration(double seconds);

}  // namespace pc

#include "models/scene/target_error_outcome.hpp"

#include <cmath>

#include "assembly/error.hpp"
#include "models/scene/target_error_format.hpp"

namespace pc {

double target_estimate(const FoundationRunResult& r) { return r.space_error_peak() + r.time_error_peak; }

bool target_met(const TargetErrorChoice& choice, const FoundationRunResult& r) {
  return r.completed && target_estimate(r) <= choice.target;  // a NaN estimate does not meet it
}

std::string target_result_line(const TargetErrorChoice& choice, const FoundationRunResult& r) {
  return message("target ", percent(choice.target), ": predicted ",
                 percent(choice.predicted_space + choice.predicted_time), " (space ", percent(choice.predicted_space),
                 " + time ", percent(choice.predicted_time), "), achieved ", percent(target_estimate(r)), " (space ",
                 percent(r.space_error_peak()), " + time ", percent(r.time_error_peak), ") in ",
                 three_digits(r.wall_seconds + choice.pilots_seconds_of(r.foundation)),
                 " s with the pilots: ", target_met(choice, r) ? "met" : "NOT met");
}

std::string target_missed_warning(const TargetErrorChoice& choice, const FoundationRunResult& r) {
  return message("warning: target ", percent(choice.target), " not met: the run's estimate is ",
                 r.completed ? percent(target_estimate(r)) : std::string("unknown (the run stopped)"));
}

}  // namespace pc

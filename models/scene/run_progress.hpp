#pragma once
// A foundation run's progress lines on stdout (models/scene/scene_runner.hpp; the writer process's, unless
// --quiet): the predicted time, a line every output.progress_every steps, and at least one every
// progress_seconds, inside a long step too: no long silence. Every line names its run (print_run_line).
#include <chrono>
#include <string>

#include "models/scene/scene.hpp"
#include "models/solvers/newton.hpp"
#include "models/stepper.hpp"

namespace pc {

// A line of a run's progress on stdout, named by the run it belongs to: "  [conductive] step 3/200 ...",
// "  [phi_f sweep 0.5 V] condensation auto: ..."; `format` as printf's, without the newline.
void print_run_line(const std::string& run, const char* format, ...) __attribute__((format(printf, 2, 3)));

class RunProgress {
 public:
  // A run of `steps` steps of the foundation, started at `start` (both must outlive the progress).
  RunProgress(const Scene& scene, const std::string& foundation, std::chrono::steady_clock::time_point start, int steps)
      : scene_(scene), foundation_(foundation), start_(start), steps_(steps) {}
  // From the start of this process's part of the run on (a resumed run's starts at its checkpoint's time).
  void begin(double first_time);
  // The run's size and predicted time (models/scene/time_estimate.hpp).
  void predicted(const Model& model) const;
  // Inside a long step, a line per Newton iteration once progress_seconds have passed without one.
  void iteration(const NewtonReport& report, int step);
  // After an accepted step.
  void step(const StepRecord& r);

 private:
  static constexpr double progress_seconds = 10;
  double since_last_line() const;

  const Scene& scene_;
  const std::string& foundation_;
  const std::chrono::steady_clock::time_point start_;
  const int steps_;
  double first_time_ = 0;
  std::chrono::steady_clock::time_point last_line_;
};

}  // namespace pc

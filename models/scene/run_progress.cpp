#include "models/scene/run_progress.hpp"

#include <cstdarg>
#include <cstdio>
#include <vector>

#include "models/output/duration_text.hpp"
#include "models/scene/time_estimate.hpp"

namespace pc {
namespace {

std::string eta(double elapsed, double done_fraction) {
  if (done_fraction <= 0) return "?";
  return describe_duration(elapsed * (1 - done_fraction) / done_fraction);
}

// Block residual norms as "1.00e-10 / 2.00e-17".
std::string residual_text(const std::vector<double>& norms) {
  std::string text;
  for (double norm : norms) {
    char part[32];
    std::snprintf(part, sizeof part, "%s%.2e", text.empty() ? "" : " / ", norm);
    text += part;
  }
  return text;
}

}  // namespace

void print_run_line(const std::string& run, const char* format, ...) {
  std::printf("  [%s] ", run.c_str());
  va_list arguments;
  va_start(arguments, format);
  std::vprintf(format, arguments);
  va_end(arguments);
  std::putchar('\n');
}

void RunProgress::begin(double first_time) {
  first_time_ = first_time;
  last_line_ = std::chrono::steady_clock::now();
}

double RunProgress::since_last_line() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - last_line_).count();
}

void RunProgress::predicted(const Model& model) const {
  const TimeEstimate predicted = estimate_run_seconds(model, steps_);
  print_run_line(foundation_, "%d dofs, %d steps: predicted %s (%s)", model_dofs(model), steps_,
                 describe_duration(predicted.seconds).c_str(), predicted.basis);
}

void RunProgress::iteration(const NewtonReport& report, int step) {
  if (since_last_line() < progress_seconds) return;
  last_line_ = std::chrono::steady_clock::now();
  print_run_line(foundation_, "step %d: Newton iteration %d, |R| = %s", step, int(report.history.size()) - 1,
                 residual_text(report.history.back().residual_norms).c_str());
  std::fflush(stdout);
}

void RunProgress::step(const StepRecord& r) {
  if (!(r.step % scene_.output.progress_every == 0 || r.step == 1 || since_last_line() >= progress_seconds)) return;
  last_line_ = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const std::string residuals = residual_text(r.newton.history.back().residual_norms);
  const auto& diagnostics = r.newton.diagnostics;
  print_run_line(
      foundation_, "step %d/%d  t = %.4g s  Newton %d (%s)  |R| = %s  in contact %g, sliding %g  left ~%s", r.step,
      steps_, r.time, r.newton.iterations, to_string(r.newton.outcome).c_str(), residuals.c_str(),
      diagnostics.count("contact_nodes_in_compression") ? diagnostics.at("contact_nodes_in_compression") : 0.0,
      diagnostics.count("contact_nodes_in_slip") ? diagnostics.at("contact_nodes_in_slip") : 0.0,
      eta(elapsed, (r.time - first_time_) / (scene_.end_time - first_time_)).c_str());
  std::fflush(stdout);
}

}  // namespace pc

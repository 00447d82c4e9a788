#include "models/scene/run_checkpoint.hpp"

#include "assembly/error.hpp"

namespace pc {

void save_totals(const FoundationRunResult& r, double wall_seconds, Checkpoint& c) {
  c.numbers["run:assembly_seconds"] = r.assembly_seconds;
  c.numbers["run:jacobian_seconds"] = r.jacobian_seconds;
  c.numbers["run:output_seconds"] = r.output_seconds;
  c.numbers["run:factorize_seconds"] = r.factorize_seconds;
  c.numbers["run:solve_seconds"] = r.solve_seconds;
  c.numbers["run:condensation_seconds"] = r.condensation_seconds;
  c.numbers["run:vtu_seconds"] = r.vtu_seconds;
  c.numbers["run:factorizations"] = r.factorizations;
  c.numbers["run:wall_seconds"] = wall_seconds;
  for (const auto& [field, scale] : r.space_error_scale) c.numbers["run:space_error_scale:" + field] = scale;
  for (const auto& [field, largest] : r.space_error_largest) c.numbers["run:space_error_largest:" + field] = largest;
  c.numbers["run:time_error_peak"] = r.time_error_peak;
}

void restore_totals(const Checkpoint& c, FoundationRunResult& r, double& wall_seconds) {
  r.assembly_seconds = c.number("run:assembly_seconds");
  // A checkpoint of an earlier version has no Jacobian and output times: its part counts as residual and other.
  for (auto [name, value] :
       {std::pair{"run:jacobian_seconds", &r.jacobian_seconds}, std::pair{"run:output_seconds", &r.output_seconds}})
    *value = c.numbers.count(name) ? c.numbers.at(name) : 0.0;
  r.factorize_seconds = c.number("run:factorize_seconds");
  r.solve_seconds = c.number("run:solve_seconds");
  r.condensation_seconds = c.number("run:condensation_seconds");
  // A checkpoint of a build that did not time its VTU output has none.
  r.vtu_seconds = c.numbers.count("run:vtu_seconds") ? c.number("run:vtu_seconds") : 0.0;
  r.factorizations = int(c.number("run:factorizations"));
  wall_seconds = c.number("run:wall_seconds");
  for (const auto& [prefix, values] : {std::pair{std::string("run:space_error_scale:"), &r.space_error_scale},
                                       std::pair{std::string("run:space_error_largest:"), &r.space_error_largest}})
    for (const auto& [key, value] : c.numbers)
      if (key.starts_with(prefix)) (*values)[key.substr(prefix.size())] = value;
  if (c.numbers.count("run:time_error_peak")) r.time_error_peak = c.number("run:time_error_peak");
}

void save_series(const ResultSeries& series, Checkpoint& c) {
  const auto written = series.written();
  Eigen::VectorXd steps(Eigen::Index(written.size())), times(Eigen::Index(written.size()));
  for (size_t i = 0; i < written.size(); ++i) {
    steps[Eigen::Index(i)] = written[i].first;
    times[Eigen::Index(i)] = written[i].second;
  }
  c.vectors["series:steps"] = steps;
  c.vectors["series:times"] = times;
}

std::vector<std::pair<int, double>> restore_series(const Checkpoint& c) {
  const Eigen::VectorXd& steps = c.vector("series:steps");
  const Eigen::VectorXd& times = c.vector("series:times");
  require(steps.size() == times.size(), "checkpoint: the VTU series' steps and times differ in number");
  std::vector<std::pair<int, double>> written;
  for (Eigen::Index i = 0; i < steps.size(); ++i) written.emplace_back(int(steps[i]), times[i]);
  return written;
}

}  // namespace pc

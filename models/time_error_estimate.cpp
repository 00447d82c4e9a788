#include "models/time_error_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "assembly/error.hpp"

namespace pc {
namespace {

constexpr size_t kept_solutions = 3;  // enough for the third divided difference (order-2 schemes)

// q! f[t_0, ..., t_q] from the solutions at times[0..q] (latest first): the q-th derivative at t_n to
// first order, or nothing if fewer than q + 1 solutions are known.
std::optional<Eigen::VectorXd> derivative(int q, const std::vector<double>& times,
                                          const std::vector<const Eigen::VectorXd*>& values) {
  if (q < 1 || values.size() < size_t(q + 1)) return std::nullopt;
  std::vector<Eigen::VectorXd> table;
  for (int i = 0; i <= q; ++i) table.push_back(*values[size_t(i)]);
  double factorial = 1;
  for (int level = 1; level <= q; ++level) {
    factorial *= level;
    for (int i = 0; i + level <= q; ++i)
      table[size_t(i)] = (table[size_t(i)] - table[size_t(i + 1)]) / (times[size_t(i)] - times[size_t(i + level)]);
  }
  return factorial * table[0];
}

// A first-order step's y'' from the divided difference of computed solutions is biased by the local
// error the last step left in y_{n-1}: with y_n - y(t_n) = c k^2 y'' per step, the difference reads
// y'' (1 + 2c (k - k1) / (k + k1)) for steps k after k1. Unbiased, the estimate does not swing with the
// step ratio (which made the controller zig-zag between a small and a large step). Higher orders: 1.
double history_correction(const LocalErrorTerm& term, const std::vector<double>& times) {
  if (term.order != 1 || times.size() < 3) return 1.0;
  const double k = times[0] - times[1], k1 = times[1] - times[2];
  const double c = term.constant / (k * k);
  return 1.0 / (1.0 + 2.0 * c * (k - k1) / (k + k1));
}

}  // namespace

double TimeErrorReport::max_local() const {
  double m = 0;
  for (const FieldTimeError& f : fields) m = std::max(m, f.local);
  return m;
}

double TimeErrorReport::max_global() const {
  double m = 0;
  for (const FieldTimeError& f : fields) m = std::max(m, f.global);
  return m;
}

std::vector<std::string> TimeErrorEstimator::default_fields(const Model& model, const TimeScheme& scheme) {
  const KinematicFields& k = scheme.fields();
  std::vector<std::string> fields{k.displacement};
  if (model.has_field(k.acceleration)) fields.push_back(k.velocity);
  return fields;
}

TimeErrorEstimator::TimeErrorEstimator(const Model& model, const TimeScheme& scheme, std::vector<std::string> fields)
    : fields_(fields.empty() ? default_fields(model, scheme) : std::move(fields)) {
  for (const std::string& f : fields_) {
    require(model.has_field(f), "time error estimate: the model has no field '", f, "'");
    std::vector<char> mask(size_t(model.space(f).num_dofs()), 1);
    if (model.field_kind(f) == FieldKind::Unknown)
      for (int d : model.constrained_dofs(f)) mask[size_t(d)] = 0;
    estimated_dofs_[f] = std::move(mask);
  }
}

double TimeErrorEstimator::rms(const std::string& field, const Eigen::VectorXd& x) const {
  const std::vector<char>& mask = estimated_dofs_.at(field);
  double sum = 0;
  int count = 0;
  for (size_t d = 0; d < mask.size(); ++d)
    if (mask[d]) {
      sum += x[Eigen::Index(d)] * x[Eigen::Index(d)];
      ++count;
    }
  return count > 0 ? std::sqrt(sum / count) : 0.0;
}

TimeErrorHistory TimeErrorEstimator::start(const Model& model) const {
  TimeErrorHistory h;
  h.times = {model.time()};
  for (const std::string& f : fields_) {
    const Eigen::VectorXd& y = model.values(f);
    h.solutions[f] = {y};
    h.sum[f] = Eigen::VectorXd::Zero(y.size());
    h.scale[f] = rms(f, y);
  }
  return h;
}

TimeErrorStep TimeErrorEstimator::evaluate(const Model& model, LocalErrorTerm term,
                                           const TimeErrorHistory& history) const {
  TimeErrorStep step;
  step.time = model.time();
  std::vector<double> times{step.time};
  times.insert(times.end(), history.times.begin(), history.times.end());
  // Which error terms this step can evaluate: its own, and those of earlier steps still waiting.
  std::vector<LocalErrorTerm> waiting = history.pending;
  if (term.order > 0) waiting.push_back(term);
  const auto available = [&](const LocalErrorTerm& t) { return times.size() >= size_t(t.order + 2); };
  step.report.estimated = term.order > 0 && available(term);
  step.report.order = step.report.estimated ? term.order : 0;
  for (const LocalErrorTerm& t : waiting)
    if (!available(t)) step.pending.push_back(t);
  for (const std::string& f : fields_) {
    const Eigen::VectorXd& y = model.values(f);
    std::vector<const Eigen::VectorXd*> values{&y};
    for (const Eigen::VectorXd& old : history.solutions.at(f)) values.push_back(&old);
    std::map<int, Eigen::VectorXd> derivatives;  // by order of the derivative
    Eigen::VectorXd sum = history.sum.at(f), local = Eigen::VectorXd::Zero(y.size());
    for (const LocalErrorTerm& t : waiting) {
      if (!available(t)) continue;
      const int q = t.order + 1;
      if (!derivatives.count(q)) derivatives[q] = *derivative(q, times, values);
      sum += t.constant * derivatives[q];
    }
    if (step.report.estimated) local = history_correction(term, times) * term.constant * derivatives.at(term.order + 1);
    const double scale = std::max(history.scale.at(f), rms(f, y));
    const auto relative = [&](const Eigen::VectorXd& e) { return scale > 0 ? rms(f, e) / scale : 0.0; };
    step.report.fields.push_back({f, relative(local), relative(sum), scale});
    step.solution[f] = y;
    step.sum[f] = std::move(sum);
    step.scale[f] = scale;
  }
  return step;
}

void TimeErrorEstimator::commit(TimeErrorStep&& step, TimeErrorHistory& h) {
  h.times.insert(h.times.begin(), step.time);
  if (h.times.size() > kept_solutions) h.times.resize(kept_solutions);
  for (auto& [f, y] : step.solution) {
    std::vector<Eigen::VectorXd>& kept = h.solutions[f];
    kept.insert(kept.begin(), std::move(y));
    if (kept.size() > kept_solutions) kept.resize(kept_solutions);
  }
  h.sum = std::move(step.sum);
  h.scale = std::move(step.scale);
  h.pending = std::move(step.pending);
}

}  // namespace pc

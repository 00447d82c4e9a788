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

const FieldTimeError* TimeErrorReport::field(const std::string& name) const {
  for (const FieldTimeError& f : fields)
    if (f.field == name) return &f;
  return nullptr;
}

std::vector<std::string> TimeErrorEstimator::default_fields(const Model& model, const TimeScheme& scheme,
                                                            TimeErrorPropagation propagation) {
  const KinematicFields& k = scheme.fields();
  std::vector<std::string> fields{k.displacement};
  const bool inertia = model.has_field(k.acceleration);
  if (inertia || propagation == TimeErrorPropagation::Linearised) fields.push_back(k.velocity);
  if (propagation == TimeErrorPropagation::Linearised)
    for (const std::string& u : model.unknowns())
      if (u != k.velocity && !model.is_brick_unknown(u)) fields.push_back(u);
  return fields;
}

TimeErrorEstimator::TimeErrorEstimator(const Model& model, const TimeScheme& scheme, TimeErrorPropagation propagation,
                                       std::vector<std::string> fields)
    : propagation_(propagation),
      kinematics_(scheme.fields()),
      fields_(fields.empty() ? default_fields(model, scheme, propagation) : std::move(fields)) {
  integrated_ = {kinematics_.displacement};
  if (model.has_field(kinematics_.acceleration)) integrated_.push_back(kinematics_.velocity);
  for (const std::string& f : integrated_)
    require(propagation == TimeErrorPropagation::Linearised ||
                std::find(fields_.begin(), fields_.end(), f) != fields_.end(),
            "time error estimate: a summed estimate reports the integrated field '", f, "'");
  std::vector<std::string> all = fields_;
  all.insert(all.end(), integrated_.begin(), integrated_.end());
  for (const std::string& f : all) {
    require(model.has_field(f), "time error estimate: the model has no field '", f, "'");
    if (propagation == TimeErrorPropagation::Summed)
      require(std::find(integrated_.begin(), integrated_.end(), f) != integrated_.end(), "time error estimate: '", f,
              "' is not integrated in time (an algebraic field), so only the "
              "linearised estimate gives its error");
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
  for (const std::string& f : integrated_) h.solutions[f] = {model.values(f)};
  for (const std::string& f : fields_) {
    h.error[f] = Eigen::VectorXd::Zero(model.values(f).size());
    h.scale[f] = rms(f, model.values(f));
  }
  return h;
}

TimeErrorStep TimeErrorEstimator::evaluate(Model& model, LocalErrorTerm term, const TimeErrorHistory& history,
                                           const TangentSolve* solve) const {
  TimeErrorStep step;
  step.time = model.time();
  std::vector<double> times{step.time};
  times.insert(times.end(), history.times.begin(), history.times.end());
  // Which error terms this step can evaluate: its own, and those of earlier steps still waiting (the
  // ones it cannot wait on, its own included).
  const auto available = [&](const LocalErrorTerm& t) { return times.size() >= size_t(t.order + 2); };
  step.report.estimated = term.order > 0 && available(term);
  step.report.order = step.report.estimated ? term.order : 0;
  for (const LocalErrorTerm& t : history.pending)
    if (!available(t)) step.pending.push_back(t);
  if (term.order > 0 && !step.report.estimated) step.pending.push_back(term);

  // Each integrated field's local error: this step's, and the back-filled one of steps still waiting.
  std::map<std::string, Eigen::VectorXd> local, backfilled;
  for (const std::string& f : integrated_) {
    const Eigen::VectorXd& y = model.values(f);
    std::vector<const Eigen::VectorXd*> values{&y};
    for (const Eigen::VectorXd& old : history.solutions.at(f)) values.push_back(&old);
    std::map<int, Eigen::VectorXd> derivatives;  // by order of the derivative
    backfilled[f] = Eigen::VectorXd::Zero(y.size());
    local[f] = Eigen::VectorXd::Zero(y.size());
    const auto derivative_of_order = [&](int q) -> const Eigen::VectorXd& {
      if (!derivatives.count(q)) derivatives[q] = *derivative(q, times, values);
      return derivatives[q];
    };
    for (const LocalErrorTerm& t : history.pending)
      if (available(t)) backfilled[f] += t.constant * derivative_of_order(t.order + 1);
    if (step.report.estimated)
      local[f] = history_correction(term, times) * term.constant * derivative_of_order(term.order + 1);
  }

  std::map<std::string, Eigen::VectorXd> error, shown_local;
  if (solve) {
    const Propagated p = propagate(model, local, backfilled, history, *solve);
    error = p.error;
    shown_local = p.local;
    step.history_errors = p.history_errors;
  } else {
    for (const std::string& f : fields_) {
      error[f] = history.error.at(f) + local.at(f) + backfilled.at(f);
      shown_local[f] = local.at(f);
    }
  }
  for (const std::string& f : fields_) {
    const Eigen::VectorXd& y = model.values(f);
    const double scale = std::max(history.scale.at(f), rms(f, y));
    const auto relative = [&](const Eigen::VectorXd& e) { return scale > 0 ? rms(f, e) / scale : 0.0; };
    step.report.fields.push_back({f, relative(shown_local.at(f)), relative(error.at(f)), scale});
    step.scale[f] = scale;
  }
  for (const std::string& f : integrated_) step.solution[f] = model.values(f);
  step.error = std::move(error);
  return step;
}

TimeErrorEstimator::Propagated TimeErrorEstimator::propagate(Model& model, const FieldVectors& local,
                                                             const FieldVectors& backfilled,
                                                             const TimeErrorHistory& history,
                                                             const TangentSolve& solve) const {
  const std::string &u = kinematics_.displacement, &v = kinematics_.velocity, &a = kinematics_.acceleration;
  const bool inertia = model.has_field(a);
  std::vector<std::string> affine{u};
  if (inertia) affine.push_back(a);
  std::vector<std::string> history_fields;  // what the affine fields read: u_prev, v_prev, ...
  for (const std::string& f : affine)
    for (const std::string& h : model.affine_history(f))
      if (std::find(history_fields.begin(), history_fields.end(), h) == history_fields.end())
        history_fields.push_back(h);
  const auto coefficient = [&](const std::string& f, const std::string& h) {
    const std::vector<std::string> names = model.affine_history(f);
    const auto it = std::find(names.begin(), names.end(), h);
    return it == names.end() ? 0.0 : model.affine_coefficients(f)[size_t(it - names.begin())];
  };

  // Two perturbations of the history: the errors it carries, and this step's local errors, put where the
  // scheme takes the last value from (u's into u_prev over its coefficient in u, so that u moves by it;
  // v's into v_prev, so that the acceleration moves as if v had).
  FieldVectors carried, injected;
  for (const std::string& h : history_fields) {
    const Eigen::Index n = model.values(h).size();
    const auto it = history.history_errors.find(h);
    carried[h] = it != history.history_errors.end() ? it->second : Eigen::VectorXd::Zero(n);
    injected[h] = Eigen::VectorXd::Zero(n);
  }
  // The first steps' local errors, back-filled now, count with the history's: they are not this step's,
  // whose error alone the step size controls.
  const std::string u_prev = u + "_prev", v_prev = v + "_prev";
  const auto put = [&](FieldVectors& into, const std::string& h, const Eigen::VectorXd& e, double weight) {
    if (into.count(h) && std::isfinite(weight)) into[h] += weight * e;
  };
  const double through_u = 1.0 / coefficient(u, u_prev);
  put(injected, u_prev, local.at(u), through_u);
  put(carried, u_prev, backfilled.at(u), through_u);
  if (inertia) {
    const double through_a = -model.affine_factor(a) / coefficient(a, v_prev);
    put(injected, v_prev, local.at(v), through_a);
    put(carried, v_prev, backfilled.at(v), through_a);
  }

  // The response of the step's solution to a history perturbation P, linearised: J dx = -(dR/dh) P. The
  // derivative is the linear bricks' blocks times P (Model::residual_derivative: exact, no element loop)
  // or, where a brick that is not linear reads the history, a difference of residuals. The converged
  // assembly is then kept whole, to be put back after the perturbed ones (not assembled again).
  std::optional<Model::ResidualSnapshot> converged;
  const DofLayout& layout = model.layout();
  const auto derivative = [&](const FieldVectors& perturbation, double largest_history, double largest_perturbation) {
    Eigen::VectorXd dR;
    if (model.residual_derivative(perturbation, dR)) return dR;
    if (!converged) converged = model.take_residual_snapshot();
    const double eps = 1e-7 * std::max(largest_history, 1e-300) / largest_perturbation;
    FieldVectors kept;
    for (const auto& [h, p] : perturbation) {
      kept[h] = model.values(h);
      model.set_values(h, kept[h] + eps * p);
    }
    model.assemble(false);
    dR = (model.residual() - converged->residual) / eps;
    for (const auto& [h, values] : kept) model.set_values(h, values);
    return dR;
  };
  const auto response = [&](const FieldVectors& perturbation) {
    double largest_history = 0, largest_perturbation = 0;
    for (const auto& [h, p] : perturbation) {
      largest_history = std::max(largest_history, model.values(h).lpNorm<Eigen::Infinity>());
      largest_perturbation = std::max(largest_perturbation, p.lpNorm<Eigen::Infinity>());
    }
    FieldVectors delta;
    for (const std::string& f : model.unknowns()) delta[f] = Eigen::VectorXd::Zero(model.values(f).size());
    if (largest_perturbation > 0) {
      const Eigen::VectorXd dR = derivative(perturbation, largest_history, largest_perturbation);
      const Eigen::VectorXd dx = solve(-dR);
      for (const std::string& f : model.unknowns()) layout.add_from_global(layout.field_index(f), dx, delta[f]);
    }
    for (const std::string& f : affine) {
      Eigen::VectorXd d = model.affine_factor(f) * delta.at(model.affine_base(f));
      for (const auto& [h, p] : perturbation) d += coefficient(f, h) * p;
      delta[f] = std::move(d);
    }
    return delta;
  };
  // The step's own response is needed apart only for a filtered local error (the step size controller's);
  // otherwise one perturbation, the sum, gives the error (the response is linear in it).
  FieldVectors from_history, from_step;
  if (filter_local_errors_) {
    from_history = response(carried);
    from_step = response(injected);
  } else {
    for (auto& [h, p] : carried) p += injected.at(h);
    from_history = response(carried);
    for (const auto& [f, d] : from_history) from_step[f] = Eigen::VectorXd::Zero(d.size());
  }
  if (converged) model.restore_residual(std::move(*converged));  // for what reads the residual after the step

  Propagated out;
  for (const std::string& f : fields_) {
    out.error[f] = from_history.at(f) + from_step.at(f);
    out.local[f] = filter_local_errors_ ? from_step.at(f)
                   : local.count(f)     ? local.at(f)
                                        : Eigen::VectorXd::Zero(from_step.at(f).size());
  }
  // The history shifts as the scheme's does: X_prev2 takes X_prev's error, X_prev takes X_n's.
  for (const std::string& h : history_fields) {
    if (h.ends_with("_prev2")) {
      const std::string last = h.substr(0, h.size() - 1);
      out.history_errors[h] = history.history_errors.count(last) ? history.history_errors.at(last)
                                                                 : Eigen::VectorXd::Zero(model.values(h).size());
    } else if (h.ends_with("_prev")) {
      const std::string x = h.substr(0, h.size() - 5);
      out.history_errors[h] = from_history.count(x) ? Eigen::VectorXd(from_history.at(x) + from_step.at(x))
                                                    : Eigen::VectorXd::Zero(model.values(h).size());
    }
  }
  return out;
}

void TimeErrorEstimator::commit(TimeErrorStep&& step, TimeErrorHistory& h) {
  h.times.insert(h.times.begin(), step.time);
  if (h.times.size() > kept_solutions) h.times.resize(kept_solutions);
  for (auto& [f, y] : step.solution) {
    std::vector<Eigen::VectorXd>& kept = h.solutions[f];
    kept.insert(kept.begin(), std::move(y));
    if (kept.size() > kept_solutions) kept.resize(kept_solutions);
  }
  h.error = std::move(step.error);
  h.history_errors = std::move(step.history_errors);
  h.scale = std::move(step.scale);
  h.pending = std::move(step.pending);
}

}  // namespace pc

#include "models/model_state.hpp"

#include "assembly/error.hpp"

namespace pc {
namespace {

const std::string field_prefix = "field:", affine_prefix = "affine:", scheme_prefix = "scheme:";
const std::string error_prefix = "time_error:";

// The time error estimate's history, under time_error:..., so that a resumed run estimates on exactly.
void save_time_error(const TimeErrorHistory& h, Checkpoint& c) {
  c.vectors[error_prefix + "times"] = Eigen::Map<const Eigen::VectorXd>(h.times.data(), Eigen::Index(h.times.size()));
  Eigen::VectorXd pending(Eigen::Index(2 * h.pending.size()));
  for (size_t i = 0; i < h.pending.size(); ++i) {
    pending[Eigen::Index(2 * i)] = h.pending[i].order;
    pending[Eigen::Index(2 * i + 1)] = h.pending[i].constant;
  }
  c.vectors[error_prefix + "pending"] = pending;
  for (const auto& [field, kept] : h.solutions) {
    for (size_t i = 0; i < kept.size(); ++i) c.vectors[error_prefix + field + ":" + std::to_string(i)] = kept[i];
  }
  for (const auto& [field, error] : h.error) {
    c.vectors[error_prefix + field + ":error"] = error;
    c.numbers[error_prefix + field + ":scale"] = h.scale.at(field);
  }
  for (const auto& [field, error] : h.history_errors) c.vectors[error_prefix + "history:" + field] = error;
}

TimeErrorHistory restore_time_error(const Checkpoint& c) {
  TimeErrorHistory h;
  const auto times = c.vectors.find(error_prefix + "times");
  if (times == c.vectors.end()) return h;  // a run without the estimate
  h.times.assign(times->second.data(), times->second.data() + times->second.size());
  const Eigen::VectorXd& pending = c.vector(error_prefix + "pending");
  for (Eigen::Index i = 0; i + 1 < pending.size(); i += 2) h.pending.push_back({int(pending[i]), pending[i + 1]});
  for (const auto& [key, value] : c.numbers) {
    if (!key.starts_with(error_prefix) || !key.ends_with(":scale")) continue;
    const std::string field = key.substr(error_prefix.size(), key.size() - error_prefix.size() - 6);
    h.scale[field] = value;
    h.error[field] = c.vector(error_prefix + field + ":error");
  }
  // The kept solutions, "time_error:<field>:<i>", and the history fields' errors, "time_error:history:<field>".
  const std::string history_prefix = error_prefix + "history:";
  for (const auto& [key, vector] : c.vectors) {
    if (key.starts_with(history_prefix)) {
      h.history_errors[key.substr(history_prefix.size())] = vector;
      continue;
    }
    if (!key.starts_with(error_prefix) || key.ends_with(":error") || key == error_prefix + "times" ||
        key == error_prefix + "pending")
      continue;
    const std::string rest = key.substr(error_prefix.size());
    const size_t colon = rest.rfind(':');
    if (colon == std::string::npos) continue;
    std::vector<Eigen::VectorXd>& kept = h.solutions[rest.substr(0, colon)];
    const size_t index = std::stoul(rest.substr(colon + 1));
    if (kept.size() <= index) kept.resize(index + 1);
    kept[index] = vector;
  }
  return h;
}

}  // namespace

void save_model_state(const Model& model, const TimeScheme& scheme, Checkpoint& checkpoint) {
  checkpoint.numbers["model:time"] = model.time();
  for (const std::string& name : model.field_names()) {
    if (model.field_kind(name) != FieldKind::Affine) {
      checkpoint.vectors[field_prefix + name] = model.values(name);
      continue;
    }
    const std::vector<double> coefficients = model.affine_coefficients(name);
    Eigen::VectorXd map(Eigen::Index(coefficients.size() + 1));
    map[0] = model.affine_factor(name);
    for (size_t i = 0; i < coefficients.size(); ++i) map[Eigen::Index(i + 1)] = coefficients[i];
    checkpoint.vectors[affine_prefix + name] = map;
  }
  checkpoint.texts["scheme"] = scheme.name();
  for (const auto& [key, value] : scheme.history_state()) checkpoint.numbers[scheme_prefix + key] = value;
}

void restore_model_state(Model& model, TimeScheme& scheme, const Checkpoint& checkpoint) {
  require(checkpoint.text("scheme") == scheme.name(), "the checkpoint is of a run with the time scheme '",
          checkpoint.text("scheme"), "', this run has '", scheme.name(), "'");
  // Everything is checked before anything is changed, so that a refused checkpoint leaves the model as it was.
  for (const std::string& name : model.field_names()) {
    const bool affine = model.field_kind(name) == FieldKind::Affine;
    const auto it = checkpoint.vectors.find((affine ? affine_prefix : field_prefix) + name);
    require(it != checkpoint.vectors.end(), "the checkpoint has no values of the field '", name,
            "': it is of another model");
    const Eigen::Index expected =
        affine ? Eigen::Index(model.affine_coefficients(name).size() + 1) : model.space(name).num_dofs();
    require(it->second.size() == expected, "the checkpoint's field '", name, "' has ", it->second.size(),
            " values, the model's has ", expected, ": it is of another mesh or model");
  }
  for (const std::string& name : model.field_names()) {
    if (model.field_kind(name) != FieldKind::Affine) {
      model.set_values(name, checkpoint.vector(field_prefix + name));
      continue;
    }
    const Eigen::VectorXd& map = checkpoint.vector(affine_prefix + name);
    model.set_affine(name, map[0], std::vector<double>(map.data() + 1, map.data() + map.size()));
  }
  model.set_time(checkpoint.number("model:time"));
  std::map<std::string, double> history;
  for (const auto& [key, value] : checkpoint.numbers)
    if (key.starts_with(scheme_prefix)) history[key.substr(scheme_prefix.size())] = value;
  scheme.restore_history_state(history);
}

void save_stepper_state(const StepperState& s, Checkpoint& c) {
  c.numbers["stepper:time"] = s.time;
  c.numbers["stepper:step_size"] = s.step_size;
  c.numbers["stepper:steps"] = s.steps;
  c.numbers["stepper:successes"] = s.successes;
  c.numbers["stepper:attempts"] = s.attempts;
  c.numbers["stepper:cutbacks"] = s.cutbacks;
  c.numbers["stepper:newton_iterations_total"] = s.newton_iterations_total;
  c.numbers["stepper:newton_iterations_max_per_step"] = s.newton_iterations_max_per_step;
  c.numbers["stepper:rejections"] = s.rejections;
  c.numbers["stepper:last_error"] = s.last_error;
  save_time_error(s.time_error, c);
}

StepperState restore_stepper_state(const Checkpoint& c) {
  StepperState s;
  s.time = c.number("stepper:time");
  s.step_size = c.number("stepper:step_size");
  s.steps = int(c.number("stepper:steps"));
  s.successes = int(c.number("stepper:successes"));
  s.attempts = int(c.number("stepper:attempts"));
  s.cutbacks = int(c.number("stepper:cutbacks"));
  s.newton_iterations_total = int(c.number("stepper:newton_iterations_total"));
  s.newton_iterations_max_per_step = int(c.number("stepper:newton_iterations_max_per_step"));
  // Checkpoints written before adaptive steps existed have neither.
  if (c.numbers.count("stepper:rejections")) s.rejections = int(c.number("stepper:rejections"));
  if (c.numbers.count("stepper:last_error")) s.last_error = c.number("stepper:last_error");
  s.time_error = restore_time_error(c);
  return s;
}

}  // namespace pc

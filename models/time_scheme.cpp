#include "models/time_scheme.hpp"

#include <cmath>

#include "assembly/error.hpp"

namespace pc {
namespace {

std::string history(const std::string& name) { return name + "_prev"; }
std::string history2(const std::string& name) { return name + "_prev2"; }

void require_step(const char* scheme, double k) {
  require(k > 0 && std::isfinite(k), scheme, ": the time step must be positive and finite, got ", k);
}

void require_size(const Model& model, const std::string& field, const Eigen::VectorXd& values, const char* what) {
  require(values.size() == model.space(field).num_dofs(), "time scheme: the initial ", what, " has ", values.size(),
          " values, the space of '", field, "' has ", model.space(field).num_dofs(), " dofs");
}

}  // namespace

// ---- backward Euler ---------------------------------------------------------------------------------

void BackwardEuler::attach(Model& model, bool with_acceleration) {
  const auto space = model.space_ptr(fields_.velocity);
  model.add_data_field(history(fields_.displacement), space);
  model.add_affine_field(fields_.displacement, fields_.velocity, {history(fields_.displacement)});
  acceleration_ = with_acceleration;
  if (with_acceleration) {
    model.add_data_field(history(fields_.velocity), space);
    model.add_affine_field(fields_.acceleration, fields_.velocity, {history(fields_.velocity)});
  }
  freeze_displacement(model);
}

void BackwardEuler::set_initial_state(Model& model, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0) {
  model.set_values(history(fields_.displacement), u0);
  model.set_values(fields_.velocity, v0);
  if (acceleration_) model.set_values(history(fields_.velocity), v0);
  freeze_displacement(model);
}

void BackwardEuler::begin_step(Model& model, double k) {
  require_step("backward Euler", k);
  model.set_affine(fields_.displacement, k, {1.0});
  if (acceleration_) model.set_affine(fields_.acceleration, 1.0 / k, {-1.0 / k});
}

void BackwardEuler::end_step(Model& model, double) {
  model.set_values(history(fields_.displacement), model.values(fields_.displacement));
  if (acceleration_) model.set_values(history(fields_.velocity), model.values(fields_.velocity));
  // Between steps u reads as the committed displacement u_n (until the next begin_step).
  freeze_displacement(model);
}

void BackwardEuler::freeze_displacement(Model& model) {
  model.set_affine(fields_.displacement, 0.0, {1.0});
  if (acceleration_) model.set_affine(fields_.acceleration, 0.0, {0.0});
}

// ---- BDF2 -------------------------------------------------------------------------------------------

double BDF2::max_step_ratio() { return 1.0 + std::sqrt(2.0); }

void BDF2::attach(Model& model, bool with_acceleration) {
  const auto space = model.space_ptr(fields_.velocity);
  const std::string& u = fields_.displacement;
  const std::string& v = fields_.velocity;
  model.add_data_field(history(u), space);
  model.add_data_field(history2(u), space);
  model.add_affine_field(u, v, {history(u), history2(u)});
  acceleration_ = with_acceleration;
  if (with_acceleration) {
    model.add_data_field(history(v), space);
    model.add_data_field(history2(v), space);
    model.add_affine_field(fields_.acceleration, v, {history(v), history2(v)});
  }
  committed_ = 0;
  freeze_displacement(model);
}

void BDF2::set_initial_state(Model& model, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0) {
  const std::string& u = fields_.displacement;
  const std::string& v = fields_.velocity;
  model.set_values(history(u), u0);
  model.set_values(history2(u), u0);  // unused by the start-up step; keeps the history finite and meaningful
  model.set_values(v, v0);
  if (acceleration_) {
    model.set_values(history(v), v0);
    model.set_values(history2(v), v0);
  }
  committed_ = 0;
  previous_step_ = 0;
  freeze_displacement(model);
}

void BDF2::begin_step(Model& model, double k) {
  require_step("BDF2", k);
  const double w = committed_ > 0 ? k / previous_step_ : 0.0;
  euler_step_ = committed_ == 0 || w > max_step_ratio();
  if (euler_step_) {
    model.set_affine(fields_.displacement, k, {1.0, 0.0});
    if (acceleration_) model.set_affine(fields_.acceleration, 1.0 / k, {-1.0 / k, 0.0});
    return;
  }
  const double d = 1.0 + 2.0 * w;
  model.set_affine(fields_.displacement, k * (1.0 + w) / d, {(1.0 + w) * (1.0 + w) / d, -w * w / d});
  if (acceleration_)
    model.set_affine(fields_.acceleration, d / ((1.0 + w) * k), {-(1.0 + w) / k, w * w / ((1.0 + w) * k)});
}

void BDF2::end_step(Model& model, double k) {
  const std::string& u = fields_.displacement;
  const std::string& v = fields_.velocity;
  const Eigen::VectorXd un = model.values(u);
  model.set_values(history2(u), model.values(history(u)));
  model.set_values(history(u), un);
  if (acceleration_) {
    model.set_values(history2(v), model.values(history(v)));
    model.set_values(history(v), model.values(v));
  }
  ++committed_;
  previous_step_ = k;
  freeze_displacement(model);
}

LocalErrorTerm BDF2::local_error_term(double k) const {
  if (euler_step_) return {1, 0.5 * k * k};
  const double k1 = previous_step_;
  return {2, k * k * (k + k1) * (k + k1) / (6.0 * (2.0 * k + k1))};
}

std::map<std::string, double> BDF2::history_state() const {
  return {{"committed_steps", double(committed_)}, {"previous_step", previous_step_}};
}

void BDF2::restore_history_state(const std::map<std::string, double>& state) {
  require(state.count("committed_steps") && state.count("previous_step"),
          "bdf2: the saved state lacks committed_steps or previous_step");
  committed_ = int(state.at("committed_steps"));
  previous_step_ = state.at("previous_step");
}

void BDF2::freeze_displacement(Model& model) {
  model.set_affine(fields_.displacement, 0.0, {1.0, 0.0});
  if (acceleration_) model.set_affine(fields_.acceleration, 0.0, {0.0, 0.0});
}

// ---- theta ------------------------------------------------------------------------------------------

ThetaScheme::ThetaScheme(double theta, KinematicFields fields) : TimeScheme(std::move(fields)), theta_(theta) {
  require(theta > 0 && theta <= 1,
          "theta scheme: theta must be in (0, 1] (1/2: Crank-Nicolson, 1: backward Euler), "
          "got ",
          theta);
}

void ThetaScheme::attach(Model& model, bool with_acceleration) {
  const auto space = model.space_ptr(fields_.velocity);
  const std::string& u = fields_.displacement;
  const std::string& v = fields_.velocity;
  model.add_data_field(history(u), space);
  model.add_data_field(history(v), space);
  model.add_affine_field(u, v, {history(u), history(v)});
  acceleration_ = with_acceleration;
  if (with_acceleration) {
    const std::string& a = fields_.acceleration;
    model.add_data_field(history(a), space);
    model.add_affine_field(a, v, {history(v), history(a)});
  }
  started_ = false;
  freeze_displacement(model);
}

void ThetaScheme::set_initial_state(Model& model, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0) {
  model.set_values(history(fields_.displacement), u0);
  model.set_values(fields_.velocity, v0);
  model.set_values(history(fields_.velocity), v0);
  if (acceleration_) model.set_values(history(fields_.acceleration), Eigen::VectorXd::Zero(v0.size()));
  started_ = false;
  freeze_displacement(model);
}

void ThetaScheme::set_consistent_initial_state(Model& model, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0,
                                               const Eigen::VectorXd& a0) {
  require(acceleration_ == (a0.size() > 0), "theta scheme: ",
          acceleration_ ? "a model with inertia needs the initial acceleration a0"
                        : "a model without inertia has no acceleration; give no a0");
  if (acceleration_) require_size(model, fields_.velocity, a0, "acceleration");
  set_initial_state(model, u0, v0);
  if (acceleration_) model.set_values(history(fields_.acceleration), a0);
  started_ = true;
  freeze_displacement(model);
}

void ThetaScheme::begin_step(Model& model, double k) {
  require_step("theta scheme", k);
  euler_step_ = !started_ || theta_ == 1.0;
  const double theta = euler_step_ ? 1.0 : theta_;
  model.set_affine(fields_.displacement, theta * k, {1.0, (1.0 - theta) * k});
  if (acceleration_)
    model.set_affine(fields_.acceleration, 1.0 / (theta * k), {-1.0 / (theta * k), -(1.0 - theta) / theta});
}

void ThetaScheme::end_step(Model& model, double) {
  const std::string& u = fields_.displacement;
  const std::string& v = fields_.velocity;
  const Eigen::VectorXd un = model.values(u);
  if (acceleration_) {
    const Eigen::VectorXd an = model.values(fields_.acceleration);
    model.set_values(history(fields_.acceleration), an);
  }
  model.set_values(history(u), un);
  model.set_values(history(v), model.values(v));
  started_ = true;
  freeze_displacement(model);
}

LocalErrorTerm ThetaScheme::local_error_term(double k) const {
  const double theta = euler_step_ ? 1.0 : theta_;
  if (theta == 0.5) return {2, -k * k * k / 12.0};
  return {1, (theta - 0.5) * k * k};
}

std::map<std::string, double> ThetaScheme::history_state() const { return {{"started", started_ ? 1.0 : 0.0}}; }

void ThetaScheme::restore_history_state(const std::map<std::string, double>& state) {
  require(state.count("started"), "theta: the saved state lacks 'started'");
  started_ = state.at("started") != 0;
}

void ThetaScheme::freeze_displacement(Model& model) {
  model.set_affine(fields_.displacement, 0.0, {1.0, 0.0});
  // The committed acceleration a_n is kept as history: a reads it.
  if (acceleration_) model.set_affine(fields_.acceleration, 0.0, {0.0, 1.0});
}

// ---- by name ----------------------------------------------------------------------------------------

Registry<TimeSchemeFactory>& time_scheme_registry() {
  static Registry<TimeSchemeFactory> registry("time scheme", "time.scheme");
  return registry;
}

std::unique_ptr<TimeScheme> make_time_scheme(const Choice& choice, KinematicFields fields) {
  const auto& entry = time_scheme_registry().at(choice.name, "time.scheme");
  return entry.create(checked_values(entry.parameters, choice.parameters, "time scheme '" + choice.name + "'"),
                      std::move(fields));
}

}  // namespace pc

PC_REGISTER(pc::time_scheme_registry(),
            {"backward_euler",
             "u_n = u_{n-1} + k v_n: first order, strongly damping (the paper's)",
             {},
             [](const pc::ParameterValues&, pc::KinematicFields f) {
               return std::unique_ptr<pc::TimeScheme>(std::make_unique<pc::BackwardEuler>(std::move(f)));
             }})
PC_REGISTER(pc::time_scheme_registry(),
            {"bdf2",
             "variable-step BDF2: second order, L-stable (first step backward Euler)",
             {},
             [](const pc::ParameterValues&, pc::KinematicFields f) {
               return std::unique_ptr<pc::TimeScheme>(std::make_unique<pc::BDF2>(std::move(f)));
             }})
PC_REGISTER(pc::time_scheme_registry(),
            {"theta",
             "theta method: second order at theta = 1/2 (Crank-Nicolson), first order and damping above",
             {{"theta", "1", "implicitness: 1/2 Crank-Nicolson, 1 backward Euler", 0.5, pc::Range::left_open(0, 1)}},
             [](const pc::ParameterValues& p, pc::KinematicFields f) {
               return std::unique_ptr<pc::TimeScheme>(std::make_unique<pc::ThetaScheme>(p.at("theta"), std::move(f)));
             }})

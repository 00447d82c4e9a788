#include "models/time_scheme.hpp"

#include <cmath>

#include "assembly/error.hpp"

namespace pc {
namespace {
std::string history(const std::string& name) { return name + "_prev"; }
}  // namespace

void BackwardEuler::attach(Model& model, bool with_acceleration) {
  const auto space = model.space_ptr(fields_.velocity);
  model.add_data_field(history(fields_.displacement), space);
  model.add_affine_field(fields_.displacement, fields_.velocity, {history(fields_.displacement)});
  acceleration_ = with_acceleration;
  if (with_acceleration) {
    model.add_data_field(history(fields_.velocity), space);
    model.add_affine_field(fields_.acceleration, fields_.velocity, {history(fields_.velocity)});
  }
}

void BackwardEuler::set_initial_state(Model& model, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0) {
  model.set_values(history(fields_.displacement), u0);
  model.set_values(fields_.velocity, v0);
  if (acceleration_) model.set_values(history(fields_.velocity), v0);
}

void BackwardEuler::begin_step(Model& model, double k) {
  require(k > 0 && std::isfinite(k), "backward Euler: the time step must be positive and finite, got ", k);
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

}  // namespace pc

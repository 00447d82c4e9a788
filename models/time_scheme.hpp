#pragma once
// Time schemes in the velocity form of the paper: the unknown is the velocity v_n; the displacement
// u_n and the acceleration a_n are affine fields of it whose factors and history coefficients the scheme
// sets before each step. Bricks are written against u, v, a and never see the scheme, so a new scheme
// changes no brick.
#include <string>

#include "models/model.hpp"

namespace pc {

// The names a scheme works with. History data fields are created by attach().
struct KinematicFields {
  std::string velocity = "v";
  std::string displacement = "u";
  std::string acceleration = "a";  // only created when the model has inertia
};

class TimeScheme {
 public:
  virtual ~TimeScheme() = default;
  virtual std::string name() const = 0;
  // Order of accuracy in time.
  virtual int order() const = 0;
  // Adds the affine fields (displacement, and acceleration if with_acceleration) and their history.
  virtual void attach(Model& model, bool with_acceleration) = 0;
  // Sets the initial displacement and velocity (zero by default).
  virtual void set_initial_state(Model& model, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0) = 0;
  // Before solving the step of size k: sets the affine maps.
  virtual void begin_step(Model& model, double k) = 0;
  // After the step converged: shifts the history; until the next begin_step, u reads as u_n.
  virtual void end_step(Model& model, double k) = 0;
  // Makes u equal its history value u_{n} exactly (factor 0), e.g. to solve for the initial potential.
  virtual void freeze_displacement(Model& model) = 0;
  const KinematicFields& fields() const { return fields_; }

 protected:
  explicit TimeScheme(KinematicFields fields) : fields_(std::move(fields)) {}
  KinematicFields fields_;
};

// The paper's scheme: u_n = u_{n-1} + k v_n, a_n = (v_n - v_{n-1}) / k. First order.
class BackwardEuler : public TimeScheme {
 public:
  explicit BackwardEuler(KinematicFields fields = {}) : TimeScheme(std::move(fields)) {}
  std::string name() const override { return "backward_euler"; }
  int order() const override { return 1; }
  void attach(Model& model, bool with_acceleration) override;
  void set_initial_state(Model& model, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0) override;
  void begin_step(Model& model, double k) override;
  void end_step(Model& model, double k) override;
  void freeze_displacement(Model& model) override;

 private:
  bool acceleration_ = false;
};

}  // namespace pc

#pragma once
// Time schemes in the velocity form of the paper: the unknown is the velocity v_n; the displacement
// u_n and the acceleration a_n are affine fields of it whose factors and history coefficients the scheme
// sets before each step. Bricks are written against u, v, a and never see the scheme, so a new scheme
// changes no brick. Every scheme enforces the equations at t_n (the step's end).
//
// Between steps (after attach, set_initial_state, end_step and freeze_displacement) u reads as the
// committed displacement u_n; the acceleration reads 0 (backward Euler, BDF2) or the committed a_n
// (theta scheme, which keeps it as history).
//
//   scheme          u_n                                              a_n (with inertia)                   order
//   backward_euler  u_{n-1} + k v_n                                  (v_n - v_{n-1}) / k                  1
//   bdf2            (4 u_{n-1} - u_{n-2}) / 3 + (2k/3) v_n           (3 v_n - 4 v_{n-1} + v_{n-2}) / 2k   2
//   theta           u_{n-1} + k (theta v_n + (1 - theta) v_{n-1})    (v_n - v_{n-1}) / (theta k)          2 if theta =
//   1/2
//                                                                      - (1 - theta) / theta a_{n-1}        else 1
// (bdf2 as written for a constant step; see BDF2 for the variable-step form.)
//
// Contact and other stiff, nonsmooth laws (measured on the paper's scene, coarse mesh): backward Euler,
// the paper's scheme, is the robust choice. Its u_n - u_{n-1} = k v_n stops a node the step its velocity
// vanishes; BDF2's u keeps drifting by (u_{n-1} - u_{n-2})/3, decaying by 1/3 a step, so it needs steps
// that resolve the contact's transitions (10 and 20 steps: u_y at the corner off by 80 % and 16 %, 40
// steps: within 2e-4 of backward Euler). Crank-Nicolson does not damp the stiff modes of the contact
// dampers: its relative error (3e-5 at 20 steps, 1e-4 at 160) does not decrease with k there, and Newton
// needs ~3 iterations a step instead of ~1.3.
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "assembly/registry.hpp"
#include "models/model.hpp"

namespace pc {

// The names a scheme works with. History data fields are created by attach(), named after these
// ("u_prev", "u_prev2", "v_prev", "v_prev2", "a_prev").
struct KinematicFields {
  std::string velocity = "v";
  std::string displacement = "u";
  std::string acceleration = "a";  // only created when the model has inertia
};

// The leading term of a step's local error: y_n - y(t_n) = constant * y^(order + 1)(t_n) + ..., y any
// field the step integrates (u from v, v from a) or follows (an algebraic field such as phi), with the
// history taken as exact. order 0: the scheme gives none (no estimate is made).
struct LocalErrorTerm {
  int order = 0;
  double constant = 0;
};

class TimeScheme {
 public:
  virtual ~TimeScheme() = default;
  virtual std::string name() const = 0;
  // Order of accuracy in time.
  virtual int order() const = 0;
  // Adds the affine fields (displacement, and acceleration if with_acceleration) and their history.
  // Afterwards u reads as its history (zero until set_initial_state).
  virtual void attach(Model& model, bool with_acceleration) = 0;
  // Sets the initial displacement and velocity (zero by default) and restarts the scheme: its next step
  // is its start-up step. Afterwards u reads as u0.
  virtual void set_initial_state(Model& model, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0) = 0;
  // Before solving the step of size k: sets the affine maps. Changes no history, so that a failed step
  // can be retried with another k.
  virtual void begin_step(Model& model, double k) = 0;
  // After the step of size k converged: shifts the history; until the next begin_step, u reads as u_n.
  virtual void end_step(Model& model, double k) = 0;
  // Makes u equal its history value u_{n} exactly (factor 0), e.g. to solve for the initial potential.
  virtual void freeze_displacement(Model& model) = 0;
  // What the scheme knows beyond the model's history fields (e.g. BDF2's last step size), by name, so
  // that a checkpoint restores a run exactly: restore_history_state(history_state()) changes nothing.
  virtual std::map<std::string, double> history_state() const { return {}; }
  virtual void restore_history_state(const std::map<std::string, double>& state) { (void)state; }
  // The local error term of the step of size k begun last (after begin_step(model, k)): what the time
  // error estimate (models/time_error_estimate.hpp) scales the solution's divided differences by.
  virtual LocalErrorTerm local_error_term(double k) const {
    (void)k;
    return {};
  }
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
  LocalErrorTerm local_error_term(double k) const override { return {1, 0.5 * k * k}; }  // k^2/2 y''

 private:
  bool acceleration_ = false;
};

// Two-step backward differentiation: u and a are the derivatives at t_n of the quadratics through the
// last three displacements and velocities. Second order, L-stable (damps the unresolved high
// frequencies as backward Euler does, with far less damping of the resolved ones).
//
// Variable step: with w = k_n / k_{n-1} the ratio of this step to the last accepted one,
//   u_n = (1+w)^2/(1+2w) u_{n-1} - w^2/(1+2w) u_{n-2} + k (1+w)/(1+2w) v_n,
//   a_n = [ (1+2w)/(1+w) v_n - (1+w) v_{n-1} + w^2/(1+w) v_{n-2} ] / k,
// which is the constant-step formula for w = 1 and stays second order across the stepper's cut-backs
// (w = 1/2) and regrowths (w = 2). Variable-step BDF2 is zero-stable for w < 1 + sqrt(2); a larger
// growth is taken as one backward Euler step (a restart), as is the first step after attach or
// set_initial_state (start-up: no u_{-1} exists). One first-order step keeps the global second order.
class BDF2 : public TimeScheme {
 public:
  explicit BDF2(KinematicFields fields = {}) : TimeScheme(std::move(fields)) {}
  std::string name() const override { return "bdf2"; }
  int order() const override { return 2; }
  void attach(Model& model, bool with_acceleration) override;
  void set_initial_state(Model& model, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0) override;
  void begin_step(Model& model, double k) override;
  void end_step(Model& model, double k) override;
  void freeze_displacement(Model& model) override;
  // True when the step begun last was the backward Euler start-up (or restart) step.
  bool last_step_was_backward_euler() const { return euler_step_; }
  // The largest step ratio k_n / k_{n-1} taken with the BDF2 formula (1 + sqrt 2: zero-stability).
  static double max_step_ratio();
  // k^2 (k + k_{n-1})^2 / (6 (2k + k_{n-1})) y^(3), which is 2/9 k^3 y^(3) at a constant step; k^2/2 y''
  // for a backward Euler step.
  LocalErrorTerm local_error_term(double k) const override;
  std::map<std::string, double> history_state() const override;
  void restore_history_state(const std::map<std::string, double>& state) override;

 private:
  bool acceleration_ = false;
  int committed_ = 0;  // steps since the start (only "at least one" matters)
  double previous_step_ = 0;
  bool euler_step_ = false;
};

// GetFEM's theta-method for second-order problems, the equations enforced at t_n:
//   u_n = u_{n-1} + k (theta v_n + (1 - theta) v_{n-1}),
//   v_n = v_{n-1} + k (theta a_n + (1 - theta) a_{n-1})  =>  a_n = (v_n - v_{n-1})/(theta k) - (1-theta)/theta a_{n-1}.
// theta = 1/2 is Crank-Nicolson (the trapezoidal rule on (u, v): second order, A-stable, energy
// conserving, but not damping the unresolved frequencies); theta = 1 is backward Euler, step for step;
// theta in (1/2, 1) is first order with some damping; theta < 1/2 is only conditionally stable, and the
// acceleration's recursion (factor -(1-theta)/theta) amplifies. Without inertia only u's map applies.
//
// Start-up. The scheme needs a_{n-1} (and, without inertia, a v_{n-1} consistent with the equations,
// e.g. C v = f - K u with viscosity). set_initial_state gives only u_0 and v_0, so the first step is
// backward Euler: its a_1 = (v_1 - v_0)/k (resp. v_1) satisfies the equations at t_1 and becomes the
// history; the step's O(k^2) local error keeps the global second order of Crank-Nicolson.
// set_consistent_initial_state takes a_0 (with inertia) and starts with a theta step instead; the
// caller vouches that (u_0, v_0, a_0) satisfy the equations at the start time.
// Any step size sequence is allowed (a one-step method); a_prev carries over a change of k.
class ThetaScheme : public TimeScheme {
 public:
  explicit ThetaScheme(double theta = 0.5, KinematicFields fields = {});
  std::string name() const override { return "theta"; }
  int order() const override { return theta_ == 0.5 ? 2 : 1; }
  double theta() const { return theta_; }
  void attach(Model& model, bool with_acceleration) override;
  void set_initial_state(Model& model, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0) override;
  // a0 must be given with inertia and be empty without.
  void set_consistent_initial_state(Model& model, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0,
                                    const Eigen::VectorXd& a0 = {});
  void begin_step(Model& model, double k) override;
  void end_step(Model& model, double k) override;
  void freeze_displacement(Model& model) override;
  bool last_step_was_backward_euler() const { return euler_step_; }
  // -k^3/12 y^(3) at theta = 1/2 (the trapezoidal rule), (theta - 1/2) k^2 y'' otherwise.
  LocalErrorTerm local_error_term(double k) const override;
  std::map<std::string, double> history_state() const override;
  void restore_history_state(const std::map<std::string, double>& state) override;

 private:
  double theta_;
  bool acceleration_ = false;
  bool started_ = false;  // history holds a consistent v_{n-1} (and a_{n-1})
  bool euler_step_ = false;
};

// The schemes a scene can name (time.scheme, parameters in time): backward_euler (the paper's), bdf2,
// theta (with theta).
using TimeSchemeFactory = std::function<std::unique_ptr<TimeScheme>(const ParameterValues&, KinematicFields)>;
Registry<TimeSchemeFactory>& time_scheme_registry();

// A scheme by name ({"theta", {{"theta", 0.5}}}); throws pc::Error naming the known schemes, or the
// parameter out of its range.
std::unique_ptr<TimeScheme> make_time_scheme(const Choice& choice = {"backward_euler", {}},
                                             KinematicFields fields = {});

}  // namespace pc

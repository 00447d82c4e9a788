#pragma once
// The time discretisation's error, estimated after every accepted step.
//
// Local error. A step's local error in an integrated field (the displacement; the velocity too when the
// model has inertia) is the scheme's leading term (TimeScheme::local_error_term, C y^(p+1)) with y^(p+1)
// the divided difference of the last p + 2 solutions, unbiased for a change of step size. The first steps
// of a run, too early for a divided difference (one under backward Euler, two under BDF2), report 0 and
// are taken in at the first step that can, with its derivative.
//
// Global error, two ways (TimeErrorPropagation):
//  - Linearised (the default): the error is carried through every step by the step's own linearisation.
//    The history (u_prev, v_prev, ...) is perturbed by the errors it carries and, apart, by the step's
//    local errors; the response of the solution, J dx = -(dR/dh) P, is one derivative of the residual and
//    one solve with the tangent Newton has (NewtonSolver::solve_tangent) for each. The derivative is the
//    linear bricks' blocks times P (Model::residual_derivative: exact, no element loop) or, where a brick
//    that is not linear reads the history (a normal compliance reads u), a difference of residuals. What a damped mode
//    forgets is forgotten, stiff modes (a contact damper's, a fast viscous one's) are filtered out of the local error
//    as in Shampine's filtered estimates, and the algebraic fields (the potential, the velocity of a model without
//    inertia) get their induced error. Cost per step: one derivative and one solve (two of each with the filtered local
//    error adaptive steps need).
//  - Summed: the local errors added up, as vectors, for the integrated fields only: no solve, but an
//    overestimate where the dynamics damp the error (many times over on a stiff contact scene) and
//    nothing for the algebraic fields.
// Errors are RMS over a field's estimated dofs (an unknown's free dofs; all of an affine field's), relative
// to the largest RMS the field has had in the run, so that a field passing through zero does not read as
// infinitely wrong.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/model.hpp"
#include "models/time_scheme.hpp"

namespace pc {

enum class TimeErrorPropagation { Linearised, Summed };

using FieldVectors = std::map<std::string, Eigen::VectorXd>;

// What the estimate keeps between steps (in StepperState, so that a checkpoint continues it exactly).
struct TimeErrorHistory {
  std::vector<double> times;                                      // of the kept solutions, latest first
  std::map<std::string, std::vector<Eigen::VectorXd>> solutions;  // per integrated field, latest first (up to 3)
  FieldVectors error;                                             // per reported field: its estimated error
  FieldVectors history_errors;          // linearised: the errors of the scheme's history fields (u_prev, ...)
  std::map<std::string, double> scale;  // per reported field: its largest RMS so far
  std::vector<LocalErrorTerm> pending;  // accepted steps whose local error awaits enough history
};

struct FieldTimeError {
  std::string field;
  double local = 0;   // the last step's local error (relative RMS; linearised: its filtered response)
  double global = 0;  // the estimated error at the step's time (relative RMS)
  double scale = 0;   // what both are relative to: the largest RMS of the field so far
};

struct TimeErrorReport {
  bool estimated = false;  // whether the last step's local error could be estimated
  int order = 0;           // the order of the last step's error term (1 or 2; 0: no estimate)
  std::vector<FieldTimeError> fields;
  double max_local() const;
  double max_global() const;
  const FieldTimeError* field(const std::string& name) const;  // nullptr if not reported
};

// One accepted (or candidate) step's estimate: the report and what commit() adds to the history.
struct TimeErrorStep {
  TimeErrorReport report;
  double time = 0;
  FieldVectors solution, error, history_errors;
  std::map<std::string, double> scale;
  std::vector<LocalErrorTerm> pending;
};

class TimeErrorEstimator {
 public:
  // J dx = rhs with the tangent of the step just solved.
  using TangentSolve = std::function<Eigen::VectorXd(const Eigen::VectorXd& rhs)>;

  // Reports `fields` or, when none are given, the default ones (default_fields).
  TimeErrorEstimator(const Model& model, const TimeScheme& scheme, TimeErrorPropagation propagation,
                     std::vector<std::string> fields = {});
  const std::vector<std::string>& fields() const { return fields_; }
  TimeErrorPropagation propagation() const { return propagation_; }
  // Linearised: whether the reported local error is the step's own filtered response (one more residual
  // difference and solve per step; what adaptive steps control) or, by default, the raw local error of the
  // integrated fields (0 for the algebraic ones).
  void set_filter_local_errors(bool filter) { filter_local_errors_ = filter; }
  // The displacement, the velocity with inertia and, linearised, every other unknown no brick brought
  // (a brick's multiplier is left out).
  static std::vector<std::string> default_fields(const Model& model, const TimeScheme& scheme,
                                                 TimeErrorPropagation propagation);
  // The norm of the estimate: RMS of x over the field's estimated dofs.
  double rms(const std::string& field, const Eigen::VectorXd& x) const;

  // A history that starts at the model's current time and values (the initial state, taken as exact).
  TimeErrorHistory start(const Model& model) const;
  // The estimate for the step just solved (the model at t_n, before the scheme's end_step), whose error
  // term is `term`. The history is not changed, so that a rejected step leaves no trace; linearised,
  // `solve` is required, and where the derivative needs a difference of residuals the model is perturbed
  // and restored (its converged residual put back as it was).
  TimeErrorStep evaluate(Model& model, LocalErrorTerm term, const TimeErrorHistory& history,
                         const TangentSolve* solve) const;
  // Takes the step into the history.
  static void commit(TimeErrorStep&& step, TimeErrorHistory& history);

 private:
  struct Propagated {
    FieldVectors error, local, history_errors;
  };
  Propagated propagate(Model& model, const FieldVectors& local, const FieldVectors& backfilled,
                       const TimeErrorHistory& history, const TangentSolve& solve) const;

  TimeErrorPropagation propagation_;
  bool filter_local_errors_ = false;
  KinematicFields kinematics_;
  std::vector<std::string> fields_;                          // reported
  std::vector<std::string> integrated_;                      // with a local error of their own: u, and v with inertia
  std::map<std::string, std::vector<char>> estimated_dofs_;  // per field: 1 where the dof is estimated
};

}  // namespace pc

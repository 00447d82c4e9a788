#pragma once
// The time discretisation's error, estimated after every accepted step for the price of a few vector
// operations, without another solve: the local error of step n is the scheme's leading term
// (TimeScheme::local_error_term, C y^(p+1)) with y^(p+1) taken from the divided difference of the last
// p + 2 solutions, and the global error estimate at t_n is the sum of the local errors (as vectors: what
// a non-dissipative error propagation would make of them; a damped system forgets faster, so there it
// is an overestimate). Each field's errors are RMS over its estimated dofs (an unknown's free dofs; all
// dofs of an affine or data field), relative to the largest RMS the field has had in the run, so that a
// field passing through zero does not read as infinitely wrong.
//
// The first steps of a run, too early for a divided difference (one step under backward Euler, two under
// BDF2), report a local error of 0 and are added to the global estimate at the first step that has the
// history, with that step's derivative.
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/model.hpp"
#include "models/time_scheme.hpp"

namespace pc {

// What the estimate keeps between steps (in StepperState, so that a checkpoint continues it exactly).
struct TimeErrorHistory {
  std::vector<double> times;                                     // of the kept solutions, latest first
  std::map<std::string, std::vector<Eigen::VectorXd>> solutions;  // per field, latest first (up to 3)
  std::map<std::string, Eigen::VectorXd> sum;                     // per field: the sum of the local errors
  std::map<std::string, double> scale;                            // per field: its largest RMS so far
  std::vector<LocalErrorTerm> pending;  // accepted steps whose local error awaits enough history
};

struct FieldTimeError {
  std::string field;
  double local = 0;   // the last step's local error (relative RMS)
  double global = 0;  // the estimated error at the step's time (relative RMS)
  double scale = 0;   // what both are relative to: the largest RMS of the field so far
};

struct TimeErrorReport {
  bool estimated = false;  // whether the last step's local error could be estimated
  int order = 0;           // the order of the last step's error term (1 or 2; 0: no estimate)
  std::vector<FieldTimeError> fields;
  double max_local() const;
  double max_global() const;
};

// One accepted (or candidate) step's estimate: the report and what commit() adds to the history.
struct TimeErrorStep {
  TimeErrorReport report;
  double time = 0;
  std::map<std::string, Eigen::VectorXd> solution, sum;
  std::map<std::string, double> scale;
  std::vector<LocalErrorTerm> pending;
};

class TimeErrorEstimator {
 public:
  // Estimates `fields`, or when none are given the scheme's velocity and displacement and every other
  // unknown that no brick brought (a brick's multiplier is not a solution to difference).
  TimeErrorEstimator(const Model& model, const TimeScheme& scheme, std::vector<std::string> fields = {});
  const std::vector<std::string>& fields() const { return fields_; }
  static std::vector<std::string> default_fields(const Model& model, const TimeScheme& scheme);
  // The norm of the estimate: RMS of x over the field's estimated dofs.
  double rms(const std::string& field, const Eigen::VectorXd& x) const;

  // A history that starts at the model's current time and values (the initial state).
  TimeErrorHistory start(const Model& model) const;
  // The estimate for the step just solved (the model at t_n, before the scheme's end_step), whose error
  // term is `term`; the history is not changed, so that a rejected step leaves no trace.
  TimeErrorStep evaluate(const Model& model, LocalErrorTerm term, const TimeErrorHistory& history) const;
  // Takes the step into the history.
  static void commit(TimeErrorStep&& step, TimeErrorHistory& history);

 private:
  std::vector<std::string> fields_;
  std::map<std::string, std::vector<char>> estimated_dofs_;  // per field: 1 where the dof is estimated
};

}  // namespace pc

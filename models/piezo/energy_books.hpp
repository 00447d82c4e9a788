#pragma once
// The energy books of a run under backward Euler, kept step by step from each brick's own residual (the
// model keeps them: Model::keep_brick_residuals). Testing the step's equations with the step's motion
// (k v_n for the velocity's rows, phi_n times the change of the potential's rows) splits the discrete
// balance brick by brick into exact identities:
//   inertia        k v_n . M a_n            = change of 1/2 v.M v     + 1/2 dv.M dv
//   elasticity     k v_n . B u_n            = change of 1/2 u.B u     + 1/2 du.B du
//   permittivity   phi_n . P dphi           = change of 1/2 phi.P phi + 1/2 dphi.P dphi
//   coupling       k v_n . C^T phi_n  + phi_n . (-C du) = 0
//   viscosity, dashpots, contact: k v_n . R_b, their dissipation (contact: on a foundation at rest)
//   conductive foundation, charges: phi_n . dR_b
//   tractions, body forces: -k v_n . R_b, the work done on the body
// and the sum of all is the work of the reactions, k v_n . R_v + phi_n . dR_phi on the constrained dofs:
// the electrodes' sum of V_n dQ_n (and supports that move). The 1/2 d.d terms are the scheme's numerical
// dissipation, first order in k. The books balance to round-off at every step; `balance` is what is left.
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/piezo/piezo_contact_recipe.hpp"

namespace pc {

struct EnergyBalance {
  // Stored, at the step's time.
  double kinetic = 0, elastic = 0, electric = 0;
  // Accumulated since t = 0.
  double numerical_dissipation = 0, viscous_dissipation = 0, contact_dissipation = 0, coupling = 0,
         other = 0,  // the conductive foundation and any brick of another kind (a user's)
      external_work = 0, boundary_work = 0;
  // stored - stored(0) + the dissipations + coupling + other - external_work - boundary_work: what is left
  // is the work of the residual on the free dofs, Newton's tolerance times the scale (not a modelling term).
  double balance = 0;
  double stored() const { return kinetic + elastic + electric; }
  // The largest single entry of the books, the scale of the balance's round-off.
  double scale() const;
};

class EnergyBooks {
 public:
  // The built model's bricks are read by kind; their residuals are kept from now on. `initial_kinetic` is
  // 1/2 v0.M v0 (0 for a body at rest). Backward Euler only: the identities are its own.
  EnergyBooks(PiezoContactModel& built, double initial_kinetic = 0);
  // At the initial state: after the initial potential's solve (its assembly gives the stored energies), or
  // for a mechanical model that has not assembled, at rest with u = 0.
  void start(const Model& model);
  // After each accepted step.
  const EnergyBalance& record(const Model& model);
  const EnergyBalance& totals() const { return totals_; }
  // history.csv columns, and their values in that order.
  static std::vector<std::string> columns();
  std::vector<double> row() const;
  // What the next record() reads of this one, for a checkpoint.
  std::map<std::string, Eigen::VectorXd> state() const;
  void restore(const std::map<std::string, Eigen::VectorXd>& state);

 private:
  enum class Kind { Inertia, Elasticity, Permittivity, Coupling, Dissipative, Contact, External, Other, None };
  std::vector<Kind> kinds_;
  bool electric_ = false;
  double initial_kinetic_ = 0, initial_stored_ = 0;
  double time_ = 0;
  Eigen::VectorXd v_, u_, phi_;                 // at the last record
  std::vector<char> tests_phi_;                 // per brick: its terms test phi (it has potential rows)
  std::vector<Eigen::VectorXd> phi_residuals_;  // those bricks' potential rows at the last record (else empty)
  Eigen::VectorXd phi_total_;                   // the whole potential residual at the last record
  EnergyBalance totals_;
};

}  // namespace pc

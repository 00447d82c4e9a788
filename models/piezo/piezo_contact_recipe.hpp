#pragma once
// The paper's model as a recipe: from a description of what a scene contains, stack exactly the bricks it
// requires and nothing else (MOOSE's rule: the input is the scene).
//   no E and beta        -> a purely mechanical model: no potential unknown, no electric bricks;
//   rho = 0              -> quasi-static: no inertia brick and no acceleration field;
//   A empty or zero      -> no viscosity brick;
//   no contact region    -> no contact bricks; friction "none" -> no friction brick;
//   foundation "insulated" (or no potential) -> no foundation brick (D.nu = 0 on the contact boundary).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "bricks/source_bricks.hpp"
#include "models/model.hpp"
#include "models/time_scheme.hpp"

namespace pc {

struct NormalLawSpec {
  std::string type = "linear_damped";  // linear_damped: c_nu max(r,0); power_damped: c_nu max(r,0)^m;
                                       // normal_compliance: c_nu max(u_nu - gap, 0)^m (displacement)
  double c_nu = 0, m = 1, gap = 0;
};

struct FrictionLawSpec {
  std::string type = "viscous";  // none | viscous: c_tau v_tau | coulomb: mu |sigma_nu| v_tau / sqrt(|v_tau|^2 + eps^2)
                                 // | tresca: g v_tau / sqrt(|v_tau|^2 + eps^2)
  double c_tau = 0, mu = 0, g = 0, eps = 1e-9;
};

struct FoundationSpec {
  std::string type = "insulated";  // insulated | conductive: k_e (phi - phi_f) |
                                   // pressure_activated: k_e s(p) (phi - phi_f), s(p) = p+^2 / (p+^2 + p_ref^2)
  double k_e = 0, phi_f = 0, p_ref = 1;
};

struct SurfaceLoad {
  std::string region;
  Load load;
  LoadTime time = LoadTime::Varying;
};

struct PiezoContactSpec {
  std::shared_ptr<const Mesh> mesh;
  int order = 1;
  std::string body = "all";
  double rho = 0;
  Eigen::MatrixXd A, B, E, beta;
  std::vector<std::string> clamped;   // v = 0 (u = u0 stays)
  std::vector<std::string> grounded;  // phi = 0
  std::vector<SurfaceLoad> tractions;
  Load body_force;                    // optional
  Load volume_charge;                 // optional
  std::vector<SurfaceLoad> surface_charges;
  std::string contact;                // face region; empty: no contact
  NormalLawSpec normal;
  FrictionLawSpec friction;
  FoundationSpec foundation;
  double slip_threshold = 0;          // |v_tau| above which a contact node counts as sliding
  TimeSchemeSpec scheme;              // backward_euler (the paper's) | bdf2 | theta (with scheme.theta)
  // Called after the recipe's bricks and before finalize(): a user's own bricks (e.g. a new law).
  std::function<void(Model&)> extra_bricks;
};

struct PiezoContactModel {
  std::unique_ptr<Model> model;
  std::unique_ptr<TimeScheme> scheme;  // the one spec.scheme names, attached
  bool electric = false;
  // Contact pressure p_nu at a node from the normal law's argument there (velocity or displacement)
  // and the outward normal; zero without contact.
  std::function<double(const double* argument, const double* normal, int dim)> contact_pressure;
  std::string contact_argument;  // the field the normal law reads ("v" or "u")
  std::array<double, 3> contact_normal{};
};

// Validates the spec (tensor shapes and definiteness, regions, law parameters) with messages naming the
// offending item, builds and finalizes the model.
PiezoContactModel build_piezo_contact_model(const PiezoContactSpec& spec);

}  // namespace pc

#pragma once
// The paper's model as a recipe: from a description of what a scene contains, stack exactly the bricks it
// requires and nothing else (MOOSE's rule: the input is the scene).
//   no E and beta        -> a purely mechanical model: no potential unknown, no electric bricks;
//   rho = 0              -> quasi-static: no inertia brick and no acceleration field;
//   A empty or zero      -> no viscosity brick;
//   no contact region    -> no contact bricks; friction "none" -> no friction brick;
//   foundation "insulated" (or no potential) -> no foundation brick (D.nu = 0 on the contact boundary).
// The contact laws are chosen by their registered names (bricks/law_registry.hpp) and their parameters
// become model constants (c_nu, c_tau, k_e, phi_f, ...): change one with Model::set_constant and only the
// bricks that read it are rebuilt.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/parameters.hpp"
#include "bricks/contact_status.hpp"
#include "bricks/foundation_motion.hpp"
#include "bricks/normal_pressure.hpp"
#include "bricks/source_bricks.hpp"
#include "models/model.hpp"
#include "models/piezo/electrodes.hpp"
#include "models/time_scheme.hpp"

namespace pc {

struct SurfaceLoad {
  std::string region;
  Load load;
  LoadTime time = LoadTime::Varying;
};

struct RegisteredBrick {
  Choice brick;
  std::string region;
};

struct PiezoContactSpec {
  std::shared_ptr<const Mesh> mesh;
  int order = 1;
  std::string body = "all";
  double rho = 0;
  Eigen::MatrixXd A, B, E, beta;
  std::vector<std::string> clamped;   // v = 0 (u = u0 stays)
  std::vector<std::string> grounded;  // phi = 0
  std::vector<Electrode> electrodes;  // phi = V(t), each with its charge and current (electrodes.hpp)
  std::vector<SurfaceLoad> tractions;
  Load body_force;     // optional
  Load volume_charge;  // optional
  std::vector<SurfaceLoad> surface_charges;
  std::string contact;  // face region; empty: no contact
  // The foundation's velocity V_f(t) (null: at rest): the contact laws read the body's motion relative to it.
  std::shared_ptr<const FoundationMotion> foundation_motion;
  // Registered law names with their parameters (bricks/law_registry.hpp); parameters left out take
  // their declared defaults, and a required one must be given.
  Choice normal{"linear_damped", {}};
  Choice friction{"none", {}};
  Choice foundation{"insulated", {}};
  double slip_threshold = 0;            // |v_tau| above which a contact node counts as sliding
  Choice scheme{"backward_euler", {}};  // a registered time scheme: backward_euler | bdf2 | theta
  // Registered bricks (bricks/brick_registry.hpp) to add over their regions, their parameters written into
  // the model's constants.
  std::vector<RegisteredBrick> bricks;
  // Called after the recipe's bricks and before finalize(): a user's own bricks (e.g. a new law).
  std::function<void(Model&)> extra_bricks;
};

struct PiezoContactModel {
  std::unique_ptr<Model> model;
  std::unique_ptr<TimeScheme> scheme;  // the one spec.scheme names, attached
  bool electric = false;
  // The contact surface's normal brick (null without contact): what the output reads p_nu from, with the
  // field its law reads, at the surface's nodes and their own normals.
  std::shared_ptr<const NormalContactBrick> normal;
  std::string contact_argument;  // "v", or "u" for a law that reads the displacement
  ContactNodes contact_nodes;
  // The normal and friction bricks' indices in the model; their residuals are kept (contact_resultant.hpp).
  std::vector<int> contact_bricks;
};

// Validates the spec (tensor shapes and definiteness, regions, law names and parameters) with messages
// naming the offending item, builds and finalizes the model.
PiezoContactModel build_piezo_contact_model(const PiezoContactSpec& spec);

}  // namespace pc

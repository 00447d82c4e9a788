#pragma once
// The contact surface at its Lagrange nodes, and its status for the Newton report and the output: how
// many nodes are pressed onto the foundation (p_nu > 0) and, of those, how many slide (|v_tau| above a
// threshold) or stick. Fields are read at the nodes' own dof values (exact: a clamped node reads exact
// zeros) and split against each node's normal, the mean of the outward normals of the surface's faces
// around it, so a curved contact surface from gmsh is split along its own normal at every node.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/fe_space.hpp"
#include "bricks/normal_pressure.hpp"

namespace pc {

struct ContactNodes {
  std::vector<int> scalar_dofs;                // sorted, of the space the nodes were taken from
  std::vector<std::array<double, 3>> normals;  // unit, one per node
};

// The space's nodes on a face region with their normals.
ContactNodes contact_nodes(const FESpace& space, const std::string& face_region);

struct ContactStatus {
  int nodes = 0;       // nodes of the region
  int in_contact = 0;  // p_nu > 0
  int sliding = 0;     // in contact and |v_tau| > slip_threshold
  int sticking() const { return in_contact - sliding; }
};

// The normal law's contact pressure p_nu at each node at time t, from the values of the field the law reads
// (velocity, or displacement for a compliance law), in the nodes' space numbering, relative to the normal
// brick's foundation motion.
std::vector<double> pressure_at_contact_nodes(const NormalPressure& normal, const FESpace& space,
                                              const ContactNodes& nodes, const Eigen::VectorXd& argument, double t);
// The 0.2.0 name: two functions had it (the runner's own spread the values onto the mesh nodes).
[[deprecated("renamed pressure_at_contact_nodes (bricks/contact_status.hpp)")]] inline std::vector<double>
nodal_contact_pressure(const NormalPressure& normal, const FESpace& space, const ContactNodes& nodes,
                       const Eigen::VectorXd& argument, double t) {
  return pressure_at_contact_nodes(normal, space, nodes, argument, t);
}
// |v_tau - V_f,tau(t)| at each node: the slip relative to the foundation (motion null: at rest).
std::vector<double> nodal_slip_speed(const FESpace& space, const ContactNodes& nodes, const Eigen::VectorXd& velocity,
                                     const FoundationMotion* motion, double t);

// What each contact node does: separated (p_nu = 0), sticking (pressed, slip at most the threshold) or
// slipping; the numbers are the VTU array contact_state's values.
enum class ContactState { Separated = 0, Sticking = 1, Slipping = 2 };
std::vector<ContactState> nodal_contact_state(const std::vector<double>& pressure, const std::vector<double>& slip,
                                              double slip_threshold);

ContactStatus contact_status(const NormalPressure& normal, const FESpace& space, const ContactNodes& nodes,
                             const Eigen::VectorXd& argument, const Eigen::VectorXd& velocity, double slip_threshold,
                             double t);

}  // namespace pc

#pragma once
// The contact boundary's output fields: the normal law's pressure p_nu, the slip relative to the
// foundation and the contact state (separated, sticking, slipping) at the contact nodes, the law evaluated
// once per output, and any of them spread onto the mesh nodes as VTU point data (zero off the boundary).
#include <vector>

#include <Eigen/Core>

#include "assembly/fe_space.hpp"
#include "bricks/contact_status.hpp"
#include "bricks/normal_pressure.hpp"

namespace pc {

struct ContactOutputFields {
  std::vector<double> pressure;     // p_nu at each contact node, in ContactNodes order
  std::vector<double> slip;         // |v_tau - V_f,tau(t)| at each contact node
  std::vector<ContactState> state;  // from pressure and slip against the slip threshold
};

// Fields at the nodes at time t: argument is the field the normal law reads (v, or u for a compliance law).
ContactOutputFields contact_output_fields(const NormalPressure& normal, const FESpace& space, const ContactNodes& nodes,
                                          const Eigen::VectorXd& argument, const Eigen::VectorXd& velocity,
                                          double slip_threshold, double t);

// Values at the contact nodes on the mesh nodes (zero elsewhere; empty values: all zero). Mesh vertices
// are the first dofs of each cell; a P2 space's other nodes are not mesh nodes and are left out.
std::vector<double> on_mesh_nodes(const FESpace& space, const ContactNodes& nodes, const std::vector<double>& values);
std::vector<double> on_mesh_nodes(const FESpace& space, const ContactNodes& nodes,
                                  const std::vector<ContactState>& state);

}  // namespace pc

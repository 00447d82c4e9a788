#include "models/output/contact_output_fields.hpp"

namespace pc {

ContactOutputFields contact_output_fields(const NormalPressure& normal, const FESpace& space, const ContactNodes& nodes,
                                          const Eigen::VectorXd& argument, const Eigen::VectorXd& velocity,
                                          double slip_threshold, double t) {
  ContactOutputFields fields;
  fields.pressure = pressure_at_contact_nodes(normal, space, nodes, argument, t);
  fields.slip = nodal_slip_speed(space, nodes, velocity, normal.motion(), t);
  fields.state = nodal_contact_state(fields.pressure, fields.slip, slip_threshold);
  return fields;
}

std::vector<double> on_mesh_nodes(const FESpace& space, const ContactNodes& nodes, const std::vector<double>& values) {
  const Mesh& mesh = space.mesh();
  std::vector<double> on_mesh(mesh.num_nodes(), 0.0);
  std::vector<int> vertex_of_dof(space.num_scalar_dofs(), -1);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto dofs = space.cell_scalar_dofs(c);
    const auto vertices = mesh.cell(c);
    for (size_t k = 0; k < vertices.size(); ++k) vertex_of_dof[dofs[k]] = vertices[k];
  }
  for (size_t i = 0; i < values.size(); ++i)
    if (const int vertex = vertex_of_dof[nodes.scalar_dofs[i]]; vertex >= 0) on_mesh[vertex] = values[i];
  return on_mesh;
}

std::vector<double> on_mesh_nodes(const FESpace& space, const ContactNodes& nodes,
                                  const std::vector<ContactState>& state) {
  std::vector<double> values;
  values.reserve(state.size());
  for (ContactState s : state) values.push_back(double(s));
  return on_mesh_nodes(space, nodes, values);
}

}  // namespace pc

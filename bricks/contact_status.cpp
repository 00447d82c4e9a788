#include "bricks/contact_status.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "assembly/error.hpp"

namespace pc {
namespace {

std::array<double, 3> node_vector(const FESpace& space, const Eigen::VectorXd& values, int scalar_dof) {
  std::array<double, 3> r{};
  for (int d = 0; d < space.num_components(); ++d) r[d] = values[space.dof(scalar_dof, d)];
  return r;
}

}  // namespace

ContactNodes contact_nodes(const FESpace& space, const std::string& face_region) {
  const Mesh& mesh = space.mesh();
  const int dim = mesh.dim();
  std::map<int, std::array<double, 3>> sums;
  for (const FaceRef& f : mesh.face_region(face_region)) {
    if (!space.has_cell(f.cell)) continue;
    const std::array<double, 3> n = mesh.face_normal(f);
    const auto cell_dofs = space.cell_scalar_dofs(f.cell);
    for (int local : space.element().face_dofs(f.local_face)) {
      std::array<double, 3>& sum = sums[cell_dofs[local]];
      for (int d = 0; d < dim; ++d) sum[d] += n[d];
    }
  }
  ContactNodes nodes;
  for (auto& [dof, sum] : sums) {
    double norm = 0;
    for (int d = 0; d < dim; ++d) norm += sum[d] * sum[d];
    norm = std::sqrt(norm);
    require(norm > 0, "contact region '", face_region, "': the outward normals of the faces at node ", dof,
            " cancel (a face region folded onto itself?)");
    for (int d = 0; d < dim; ++d) sum[d] /= norm;
    nodes.scalar_dofs.push_back(dof);
    nodes.normals.push_back(sum);
  }
  return nodes;
}

std::vector<double> pressure_at_contact_nodes(const NormalPressure& normal, const FESpace& space,
                                              const ContactNodes& nodes, const Eigen::VectorXd& argument, double t) {
  std::vector<double> pressure;
  for (size_t i = 0; i < nodes.scalar_dofs.size(); ++i) {
    const auto r = node_vector(space, argument, nodes.scalar_dofs[i]);
    pressure.push_back(normal.at(r.data(), nodes.normals[i].data(), space.num_components(), t));
  }
  return pressure;
}

std::vector<double> nodal_slip_speed(const FESpace& space, const ContactNodes& nodes, const Eigen::VectorXd& velocity,
                                     const FoundationMotion* motion, double t) {
  const int dim = space.num_components();
  std::vector<double> speed;
  for (size_t i = 0; i < nodes.scalar_dofs.size(); ++i) {
    const auto v = node_vector(space, velocity, nodes.scalar_dofs[i]);
    const auto slip = relative_to_foundation(v.data(), motion, false, t, dim);
    double v_tau[3] = {}, slip2 = 0;
    tangential_part(slip.data(), nodes.normals[i].data(), dim, v_tau);
    for (int d = 0; d < dim; ++d) slip2 += v_tau[d] * v_tau[d];
    speed.push_back(std::sqrt(slip2));
  }
  return speed;
}

std::vector<ContactState> nodal_contact_state(const std::vector<double>& pressure, const std::vector<double>& slip,
                                              double slip_threshold) {
  require(pressure.size() == slip.size(), "nodal_contact_state: ", pressure.size(), " pressures but ", slip.size(),
          " slip speeds");
  std::vector<ContactState> state(pressure.size(), ContactState::Separated);
  for (size_t i = 0; i < pressure.size(); ++i)
    if (pressure[i] > 0) state[i] = slip[i] > slip_threshold ? ContactState::Slipping : ContactState::Sticking;
  return state;
}

ContactStatus contact_status(const NormalPressure& normal, const FESpace& space, const ContactNodes& nodes,
                             const Eigen::VectorXd& argument, const Eigen::VectorXd& velocity, double slip_threshold,
                             double t) {
  const std::vector<double> pressure = pressure_at_contact_nodes(normal, space, nodes, argument, t);
  const std::vector<double> slip = nodal_slip_speed(space, nodes, velocity, normal.motion(), t);
  ContactStatus status;
  status.nodes = int(pressure.size());
  for (ContactState s : nodal_contact_state(pressure, slip, slip_threshold)) {
    if (s == ContactState::Separated) continue;
    ++status.in_contact;
    if (s == ContactState::Slipping) ++status.sliding;
  }
  return status;
}

}  // namespace pc

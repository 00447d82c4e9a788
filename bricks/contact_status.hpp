#pragma once
// Contact status for the Newton report: how many nodes of the contact surface are pressed onto the
// foundation (p_nu > 0) and, of those, how many slide (|v_tau| > a threshold) or stick. Evaluated on the
// nodal values of the fields (dofs of a Lagrange space are point values), against a given outward normal,
// so it is exact for a flat contact surface such as the paper's and costs one pass over the region's dofs.
//
//   model.add_diagnostic("contact nodes", [&](const Model& m) {
//     return contact_status(law, m.space("v"), "contact", m.values("v"), m.values("v"), {0, -1, 0}, 1e-8).in_contact;
//   });
#include <array>
#include <cmath>
#include <string>

#include <Eigen/Core>

#include "assembly/fe_space.hpp"
#include "bricks/contact_kinematics.hpp"

namespace pc {

struct ContactStatus {
  int nodes = 0;       // nodes of the region
  int in_contact = 0;  // p_nu > 0
  int sliding = 0;     // in contact and |v_tau| > slip_threshold
  int sticking() const { return in_contact - sliding; }
};

// argument: values of the field the normal law reads (velocity, or displacement for a compliance law);
// velocity: values of the velocity. Both in `space`'s numbering.
template <class NormalLaw>
ContactStatus contact_status(const NormalLaw& law, const FESpace& space, const std::string& region,
                             const Eigen::VectorXd& argument, const Eigen::VectorXd& velocity,
                             const std::array<double, 3>& normal, double slip_threshold) {
  const int dim = space.num_components();
  ContactStatus status;
  for (const int node : space.scalar_dofs_on(region)) {
    ++status.nodes;
    double r[3] = {}, v[3] = {}, v_tau[3] = {};
    for (int d = 0; d < dim; ++d) {
      r[d] = argument[space.dof(node, d)];
      v[d] = velocity[space.dof(node, d)];
    }
    if (!(contact_pressure(law, r, normal.data(), dim) > 0)) continue;
    ++status.in_contact;
    tangential_part(v, normal.data(), dim, v_tau);
    double slip2 = 0;
    for (int d = 0; d < dim; ++d) slip2 += v_tau[d] * v_tau[d];
    if (std::sqrt(slip2) > slip_threshold) ++status.sliding;
  }
  return status;
}

}  // namespace pc

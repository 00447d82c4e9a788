#include "models/piezo/contact_resultant.hpp"

namespace pc {

ContactResultant contact_resultant(const PiezoContactModel& built) {
  ContactResultant r;
  const Model& m = *built.model;
  const FESpace& space = m.space("v");
  const Eigen::VectorXd& v = m.values("v");
  for (int b : built.contact_bricks) {
    const Eigen::VectorXd& residual = m.brick_residual(b, "v");
    for (int node = 0; node < space.num_scalar_dofs(); ++node)
      for (int d = 0; d < space.num_components(); ++d) r.force[d] -= residual[space.dof(node, d)];
    r.power -= residual.dot(v);
  }
  return r;
}

}  // namespace pc

#include "models/scene/time_estimate.hpp"

#include <cmath>
#include <string>

#include "models/model.hpp"

namespace pc {

TimeEstimate estimate_run_seconds(int dim, double dofs, int steps) {
  const double per_step = dim == 3 ? 9.5e-3 * std::pow(dofs / 2308.0, 1.95) : 4.8e-3 * std::pow(dofs / 3843.0, 1.15);
  return {per_step * steps, dim == 3 ? "3D cost model: an order of magnitude" : "2D cost model: within a factor of 2"};
}

int model_dofs(const Model& model) {
  int dofs = 0;
  for (const std::string& u : model.unknowns()) dofs += model.space(u).num_dofs();
  return dofs;
}

TimeEstimate estimate_run_seconds(const Model& model, int steps) {
  return estimate_run_seconds(model.mesh().dim(), model_dofs(model), steps);
}

}  // namespace pc

#include "models/scene/time_estimate.hpp"

#include <cmath>

namespace pc {

TimeEstimate estimate_run_seconds(int dim, double dofs, int steps) {
  const double per_step = dim == 3 ? 9.5e-3 * std::pow(dofs / 2308.0, 1.95) : 4.8e-3 * std::pow(dofs / 3843.0, 1.15);
  return {per_step * steps, dim == 3 ? "3D cost model: an order of magnitude" : "2D cost model: within a factor of 2"};
}

}  // namespace pc

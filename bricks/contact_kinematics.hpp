#pragma once
// Kinematics on the contact surface, shared by the contact bricks: the split of a vector r against the
// body's outward unit normal n into r_nu = r . n and r_tau = r - r_nu n.
#include <memory>
#include <string>

#include "bricks/foundation_motion.hpp"

namespace pc {

// What the contact bricks read: the model names of the body's fields, and the foundation's motion.
struct ContactFields {
  std::string velocity = "v";
  std::string displacement = "u";  // an affine field of the velocity (u = k v + u_prev)
  std::string potential = "phi";
  // Null: the foundation is at rest. Otherwise the laws read v - V_f(t) and u - U_f(t) (foundation_motion.hpp).
  std::shared_ptr<const FoundationMotion> motion = nullptr;
};

template <class S> S normal_part(const S* r, const double* n, int dim) {
  S r_nu = r[0] * n[0];
  for (int d = 1; d < dim; ++d) r_nu += r[d] * n[d];
  return r_nu;
}

template <class S> void tangential_part(const S* r, const double* n, int dim, S* out) {
  const S r_nu = normal_part(r, n, dim);
  for (int d = 0; d < dim; ++d) out[d] = r[d] - r_nu * n[d];
}

}  // namespace pc

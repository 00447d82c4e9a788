#pragma once
// A rigid foundation that moves: its velocity V_f(t), one time function per component, and its
// displacement U_f(t) = integral of V_f from 0 (exact, so a normal-compliance gap to the moved foundation
// carries no time-integration error). The contact laws read the body's motion relative to it:
//   damped normal laws   r = (v - V_f) . n        friction   v_tau - V_f,tau
//   compliance laws      r = (u - U_f) . n        (the gap to the moved foundation)
// A foundation at rest is a null motion (ContactFields::motion), and the laws read v and u as before.
#include <array>
#include <memory>

#include "assembly/time_function.hpp"

namespace pc {

struct FoundationMotion {
  std::array<TimeFunction, 3> velocity;  // components x, y, z (z unused in 2D)

  bool moves() const {
    for (const TimeFunction& f : velocity)
      if (f.varies() || f.value(0) != 0) return true;
    return false;
  }
  void velocity_at(double t, double* out) const {
    for (int d = 0; d < 3; ++d) out[d] = velocity[d].value(t);
  }
  void displacement_at(double t, double* out) const {
    for (int d = 0; d < 3; ++d) out[d] = velocity[d].integral(t);
  }
};

// Whether a motion (null: none) makes the contact terms depend on the time.
inline bool foundation_moves(const FoundationMotion* motion) { return motion && motion->moves(); }

// The argument a contact law reads at a point, relative to the foundation: value - V_f(t) for a law of
// the velocity, value - U_f(t) for one of the displacement; the value itself for a foundation at rest.
template <class S>
std::array<S, 3> relative_to_foundation(const S* value, const FoundationMotion* motion, bool displacement, double t,
                                        int dim) {
  std::array<S, 3> r{};
  double m[3] = {0, 0, 0};
  if (motion) {
    if (displacement)
      motion->displacement_at(t, m);
    else
      motion->velocity_at(t, m);
  }
  for (int d = 0; d < dim; ++d) r[d] = value[d] - m[d];
  return r;
}

}  // namespace pc

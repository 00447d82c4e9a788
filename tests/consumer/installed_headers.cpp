// A consumer's translation unit: the installed harness headers with every built-in law, compiled by ctest
// with the consumer's flags only (-std=c++20 -O2 / -O3 -Wall -Wextra -Werror, no -Wno-* of the project's
// own build). GCC 12 once reported -Warray-bounds here at -O3 (law_checker.hpp's Jacobian loops).
#include "bricks/laws/direction.hpp"
#include "bricks/laws/foundation_laws.hpp"
#include "bricks/laws/friction_laws.hpp"
#include "bricks/laws/normal_laws.hpp"
#include "bricks/testing/brick_checker.hpp"
#include "bricks/testing/law_checker.hpp"

bool consumer_checks_the_built_in_laws() {
  bool ok = true;
  ok &= pc::check_scalar_law(pc::LinearDampedResponse{1e12}).ok();
  ok &= pc::check_scalar_law(pc::PowerDampedResponse{1e12, 1.5}).ok();
  ok &= pc::check_scalar_law(pc::NormalCompliance{1e9, 2.0, 0.1}, {.kinks = {0.1}}).ok();
  ok &= pc::check_friction_law(pc::ViscousFriction{0.3}).ok();
  ok &= pc::check_friction_law(pc::RegularizedCoulomb{0.3, 1e-2}).ok();
  ok &= pc::check_friction_law(pc::RegularizedTresca{5.0, 1e-2}).ok();
  ok &= pc::check_foundation_law(pc::LinearConductance{1.0, -48.0}).ok();
  ok &= pc::check_foundation_law(pc::PressureActivatedConductance{1.0, -48.0, 1.0}).ok();
  return ok;
}

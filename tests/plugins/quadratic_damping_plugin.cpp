// A plugin as a user writes one: a normal law that is not built in, registered with its parameters, and a
// whole brick (the library's dashpot over the plugin's own constant).
// Built by piezocontact_add_plugin() (tests/CMakeLists.txt); loaded by the scenes of plugins_test.cpp.
#include <array>

#include "bricks/boundary_dashpot_brick.hpp"
#include "bricks/brick_registry.hpp"
#include "bricks/law_registry.hpp"
#include "bricks/laws/normal_laws.hpp"

namespace {

// p_nu = c_nu max(v_nu, 0)^2
struct QuadraticDamping {
  double c_nu = 0;
  static constexpr bool dissipative = true;
  static constexpr auto parameters() {
    return std::array{pc::law_parameter("c_nu", &QuadraticDamping::c_nu, "Pa s^2/m^2", "quadratic damping coefficient",
                                        pc::Range::at_least(0), pc::Required::yes)};
  }
  template <class S> S operator()(const S& r) const { return r < 0.0 ? S(0.0) : c_nu * r * r; }
};

}  // namespace

PC_REGISTER_NORMAL_LAW(QuadraticDamping, "quadratic_damped", "p_nu = c_nu max(v_nu, 0)^2 (a test plugin's law)")
PC_REGISTER_BRICK("plugin_dashpot", "c_plugin v . w on a face region (a test plugin's brick)",
                  {{"c_plugin", "Pa s/m", "dashpot coefficient", std::nullopt, pc::Range::at_least(0)}},
                  [](const std::string& region) -> std::shared_ptr<pc::Brick> {
                    return std::make_shared<pc::BoundaryDashpotBrick>(region, "c_plugin");
                  })

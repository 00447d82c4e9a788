#pragma once
// The friction term of paper (16): integral over Gamma_C of p_tau(v_tau) . w_tau, i.e. the flux
// f0 = P p_tau(v_tau) with P = I - n n^T (w_tau = P w), tested with v's test function. A law that reads the
// normal pressure (Coulomb) gets p_nu from the brick's normal law, evaluated on v (or on u for a
// compliance law), and Dual carries the coupling into the tangent:
//   FrictionBrick<ViscousFriction> viscous(ViscousFriction{0.3});
//   FrictionBrick<RegularizedCoulomb, LinearDampedResponse> coulomb({0.2, 1e-4}, {1e12});
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "assembly/pointwise_term.hpp"
#include "bricks/brick.hpp"
#include "bricks/contact_kinematics.hpp"
#include "bricks/laws/law_parameters.hpp"
#include "bricks/laws/law_traits.hpp"

namespace pc {

// Stands for the normal law of a friction law that does not read the pressure.
struct NoNormalLaw {};

// Field 0 is the tested velocity; `pressure_argument` is the field the normal law reads.
template <class Law, class NormalLaw>
struct FrictionKernel {
  Law law;
  NormalLaw normal;
  int pressure_argument;

  template <class S>
  void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    const int dim = in.dim;
    S v_tau[3]{}, p_tau[3]{};
    tangential_part(in.value[0].data(), in.normal, dim, v_tau);
    S p_nu(0.0);
    if constexpr (law_uses_normal_pressure<Law>)
      p_nu = contact_pressure(normal, in.value[pressure_argument].data(), in.normal, dim);
    law(v_tau, dim, p_nu, p_tau);
    tangential_part(p_tau, in.normal, dim, out.f0[0].data());
  }
};

template <class Law, class NormalLaw = void>
class FrictionBrick : public Brick {
  static constexpr bool kReadsPressure = law_uses_normal_pressure<Law>;
  static_assert(kReadsPressure != std::is_void_v<NormalLaw>,
                "a friction law that reads the normal pressure needs a NormalLaw, and only such a law takes one");
  using Normal = std::conditional_t<kReadsPressure, NormalLaw, NoNormalLaw>;
  using Kernel = FrictionKernel<Law, Normal>;

 public:
  explicit FrictionBrick(Law law, std::string region = "contact", ContactFields names = {})
    requires(!law_uses_normal_pressure<Law>)
      : FrictionBrick(std::move(law), Normal{}, std::move(region), std::move(names)) {}

  FrictionBrick(Law law, Normal normal, std::string region = "contact", ContactFields names = {})
      : region_(std::move(region)) {
    validate_law(law, name());
    validate_law(normal, name());
    std::vector<FieldUse> fields = {{names.velocity}};
    std::vector<Coupling> couplings = {{0, 0}};
    int pressure_argument = 0;
    if (kReadsPressure && law_uses_displacement<Normal>) {
      fields.push_back({names.displacement});
      couplings.push_back({0, 1});
      pressure_argument = 1;
    }
    term_ = std::make_shared<PointwiseTerm<Kernel>>(name(), Integration::Faces, std::move(fields),
                                                     std::vector<int>{0}, std::move(couplings),
                                                     Kernel{std::move(law), std::move(normal), pressure_argument});
  }

  std::string name() const override { return "friction on " + region_; }
  std::vector<BrickTerm> terms() const override { return {{term_, region_}}; }
  bool linear() const override { return law_affine<Law>; }
  // P J P with J = dp_tau/dv_tau is symmetric when J is; the pressure coupling p_tau' (dp_nu/dv) is not.
  bool symmetric() const override { return law_symmetric<Law> && !kReadsPressure; }
  const Law& law() const { return term_->kernel().law; }

 private:
  std::string region_;
  std::shared_ptr<const PointwiseTerm<Kernel>> term_;
};

}  // namespace pc

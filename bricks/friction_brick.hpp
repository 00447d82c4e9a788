#pragma once
// The friction term of paper (16): integral over Gamma_C of p_tau(v_tau) . w_tau, i.e. the flux
// f0 = P p_tau(v_tau) with P = I - n n^T (w_tau = P w), tested with v's test function. A law of Coulomb
// type reads the contact pressure of the normal brick it is paired with (the normal law is given once),
// evaluated on v (or on u for a compliance law); Dual carries that coupling into the tangent:
//
//   auto normal = std::make_shared<NormalResponseBrick<LinearDampedResponse>>("bottom");
//   auto coulomb = std::make_shared<FrictionBrick<RegularizedCoulomb>>("bottom", normal);   // mu, eps
//   auto viscous = std::make_shared<FrictionBrick<ViscousFriction>>("bottom");              // c_tau
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "assembly/pointwise_term.hpp"
#include "bricks/paired_law_brick.hpp"

namespace pc {

// Field 0 is the tested velocity; `pressure_argument` is the field the paired normal law reads.
template <class Law> struct FrictionKernel {
  std::shared_ptr<const Law> law;
  std::shared_ptr<const NormalPressure> normal;  // null for a law that reads no pressure
  int pressure_argument;
  std::shared_ptr<const FoundationMotion> motion = nullptr;  // null: the foundation is at rest

  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    const int dim = in.dim;
    S v_tau[3]{}, p_tau[3]{};
    const auto slip = relative_to_foundation(in.value[0].data(), motion.get(), false, in.time, dim);
    tangential_part(slip.data(), in.normal, dim, v_tau);
    S p_nu(0.0);
    if constexpr (law_uses_normal_pressure<Law>)
      p_nu = normal->at(in.value[pressure_argument].data(), in.normal, dim, in.time);
    (*law)(v_tau, dim, p_nu, p_tau);
    tangential_part(p_tau, in.normal, dim, out.f0[0].data());
  }
};

template <class Law> class FrictionBrick : public PairedLawBrick<Law> {
  using Base = PairedLawBrick<Law>;

 public:
  // Parameters read from the model's constants; `normal` is the paired normal brick, for a law that reads
  // the contact pressure (and only for one).
  explicit FrictionBrick(std::string region = "contact", std::shared_ptr<const NormalPressure> normal = nullptr,
                         ContactFields fields = {}, ParameterNames names = {}) requires DeclaresParameters<Law>
      : FrictionBrick(BoundLaw<Law>(std::move(names)), std::move(region), std::move(normal), std::move(fields)) {}
  // A law that declares no parameters, with fixed values.
  explicit FrictionBrick(Law law, std::string region = "contact",
                         std::shared_ptr<const NormalPressure> normal = nullptr,
                         ContactFields fields = {}) requires(!DeclaresParameters<Law>)
      : FrictionBrick(BoundLaw<Law>(std::move(law)), std::move(region), std::move(normal), std::move(fields)) {}

  std::string name() const override { return "friction on " + this->region_; }
  // P J P with J = dp_tau/dv_tau is symmetric when J is; the pressure coupling p_tau' (dp_nu/dv) is not.
  bool symmetric() const override { return law_symmetric<Law> && !law_uses_normal_pressure<Law>; }
  // The slip is relative to a moving foundation, and a pressure it reads may be too.
  bool time_dependent() const override { return foundation_moves(motion_.get()) || Base::time_dependent(); }

 private:
  FrictionBrick(BoundLaw<Law> law, std::string region, std::shared_ptr<const NormalPressure> normal,
                ContactFields fields)
      : Base(std::move(law), std::move(region), std::move(normal)), motion_(fields.motion) {
    this->require_pairing_of(name());
    this->require_motion_of_pairing(name(), motion_.get());
    std::vector<FieldUse> uses = {{fields.velocity}};
    std::vector<Coupling> couplings = {{0, 0}};
    int pressure_argument = 0;
    if (this->normal_ && this->normal_->reads_displacement()) {
      uses.push_back({fields.displacement});
      couplings.push_back({0, 1});
      pressure_argument = 1;
    }
    this->term_ = std::make_shared<PointwiseTerm<FrictionKernel<Law>>>(
        name(), Integration::Faces, std::move(uses), std::vector<int>{0}, std::move(couplings),
        FrictionKernel<Law>{this->law_.shared(), this->normal_, pressure_argument, motion_});
  }

  std::shared_ptr<const FoundationMotion> motion_;
};

}  // namespace pc

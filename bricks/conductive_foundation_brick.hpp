#pragma once
// The electric contact term of paper (17): integral over Gamma_C of D.n(phi, p_nu) psi, with the flux of a
// foundation law (paper (10): k_e (phi - phi_f)) tested with phi's test function. A law that switches
// with the contact pressure holds its normal law (`law.normal`); the brick evaluates p_nu on v (or u)
// and adds the coupling (phi, v) (or (phi, u)), differentiated by Dual.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "assembly/pointwise_term.hpp"
#include "bricks/brick.hpp"
#include "bricks/contact_kinematics.hpp"
#include "bricks/laws/law_parameters.hpp"
#include "bricks/laws/law_traits.hpp"

namespace pc {

// Field 0 is the tested potential; field 1, if any, is the vector field the law's normal law reads.
template <class Law>
struct ConductiveFoundationKernel {
  Law law;

  template <class S>
  void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    S p_nu(0.0);
    if constexpr (law_uses_normal_pressure<Law>)
      p_nu = contact_pressure(law.normal, in.value[1].data(), in.normal, in.dim);
    out.f0[0][0] = law(in.value[0][0], p_nu);
  }
};

template <class Law>
class ConductiveFoundationBrick : public Brick {
  static constexpr bool kReadsPressure = law_uses_normal_pressure<Law>;
  using Kernel = ConductiveFoundationKernel<Law>;

 public:
  explicit ConductiveFoundationBrick(Law law, std::string region = "contact", ContactFields names = {})
      : region_(std::move(region)) {
    validate_law(law, name());
    std::vector<FieldUse> fields = {{names.potential}};
    std::vector<Coupling> couplings = {{0, 0}};
    if constexpr (kReadsPressure) {
      fields.push_back({normal_law_field<decltype(law.normal)>(names)});
      couplings.push_back({0, 1});
    }
    term_ = std::make_shared<PointwiseTerm<Kernel>>(name(), Integration::Faces, std::move(fields),
                                                     std::vector<int>{0}, std::move(couplings), Kernel{std::move(law)});
  }

  std::string name() const override { return "conductive foundation on " + region_; }
  std::vector<BrickTerm> terms() const override { return {{term_, region_}}; }
  bool linear() const override { return law_affine<Law>; }
  // k_e s(p) N_i N_j is symmetric; the (phi, v) block has no (v, phi) partner.
  bool symmetric() const override { return !kReadsPressure; }
  const Law& law() const { return term_->kernel().law; }

 private:
  std::string region_;
  std::shared_ptr<const PointwiseTerm<Kernel>> term_;
};

}  // namespace pc

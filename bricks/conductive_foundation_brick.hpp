#pragma once
// The electric contact term of paper (17): integral over Gamma_C of D.n(phi, p_nu) psi, with the flux of a
// foundation law (paper (10): k_e (phi - phi_f)) tested with phi's test function. A law that switches
// with the contact pressure reads it from the normal brick it is paired with, evaluated on v (or u), and
// the brick adds the coupling (phi, v) (or (phi, u)), differentiated by Dual:
//
//   auto foundation = std::make_shared<ConductiveFoundationBrick<LinearConductance>>("bottom");  // k_e, phi_f
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "assembly/pointwise_term.hpp"
#include "bricks/paired_law_brick.hpp"

namespace pc {

// Field 0 is the tested potential; field 1, if any, is the vector field the paired normal law reads.
template <class Law> struct ConductiveFoundationKernel {
  std::shared_ptr<const Law> law;
  std::shared_ptr<const NormalPressure> normal;  // null for a law that reads no pressure

  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    S p_nu(0.0);
    if constexpr (law_uses_normal_pressure<Law>) p_nu = normal->at(in.value[1].data(), in.normal, in.dim, in.time);
    out.f0[0][0] = (*law)(in.value[0][0], p_nu);
  }
};

template <class Law> class ConductiveFoundationBrick : public PairedLawBrick<Law> {
  using Base = PairedLawBrick<Law>;

 public:
  // Parameters read from the model's constants; `normal` is the paired normal brick, for a law that reads
  // the contact pressure (and only for one).
  explicit ConductiveFoundationBrick(std::string region = "contact",
                                     std::shared_ptr<const NormalPressure> normal = nullptr, ContactFields fields = {},
                                     ParameterNames names = {}) requires DeclaresParameters<Law>
      : ConductiveFoundationBrick(BoundLaw<Law>(std::move(names)), std::move(region), std::move(normal),
                                  std::move(fields)) {}
  // A law that declares no parameters, with fixed values.
  explicit ConductiveFoundationBrick(Law law, std::string region = "contact",
                                     std::shared_ptr<const NormalPressure> normal = nullptr,
                                     ContactFields fields = {}) requires(!DeclaresParameters<Law>)
      : ConductiveFoundationBrick(BoundLaw<Law>(std::move(law)), std::move(region), std::move(normal),
                                  std::move(fields)) {}

  std::string name() const override { return "conductive foundation on " + this->region_; }
  // k_e s(p) N_i N_j is symmetric; the (phi, v) block has no (v, phi) partner.
  bool symmetric() const override { return !law_uses_normal_pressure<Law>; }

 private:
  ConductiveFoundationBrick(BoundLaw<Law> law, std::string region, std::shared_ptr<const NormalPressure> normal,
                            ContactFields fields)
      : Base(std::move(law), std::move(region), std::move(normal)) {
    this->require_pairing_of(name());
    std::vector<FieldUse> uses = {{fields.potential}};
    std::vector<Coupling> couplings = {{0, 0}};
    if (this->normal_) {
      uses.push_back({this->normal_->argument_field(fields)});
      couplings.push_back({0, 1});
    }
    this->term_ = std::make_shared<PointwiseTerm<ConductiveFoundationKernel<Law>>>(
        name(), Integration::Faces, std::move(uses), std::vector<int>{0}, std::move(couplings),
        ConductiveFoundationKernel<Law>{this->law_.shared(), this->normal_});
  }
};

}  // namespace pc

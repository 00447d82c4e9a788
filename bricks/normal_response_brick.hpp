#pragma once
// The normal contact term of paper (16): integral over Gamma_C of p_nu(r) w_nu, i.e. the flux
// f0 = p_nu(r) n tested with w = v's test function, where r = v . n for damped responses and r = u . n for
// laws that read the displacement (the model maps u = k v + u_prev onto v's columns). Templated on the law,
// so the law is inlined at every quadrature point; its tangent comes from Dual.
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

// Field 0 is the tested velocity; `argument` is the field the law reads (0, or 1 for the displacement).
template <class Law>
struct NormalResponseKernel {
  Law law;
  int argument;

  template <class S>
  void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    const S p_nu = contact_pressure(law, in.value[argument].data(), in.normal, in.dim);
    for (int d = 0; d < in.dim; ++d) out.f0[0][d] = p_nu * in.normal[d];
  }
};

template <class Law>
class NormalResponseBrick : public Brick {
 public:
  explicit NormalResponseBrick(Law law, std::string region = "contact", ContactFields names = {})
      : region_(std::move(region)) {
    validate_law(law, name());
    const bool displacement = law_uses_displacement<Law>;
    std::vector<FieldUse> fields = {{names.velocity}};
    if (displacement) fields.push_back({names.displacement});
    const int argument = displacement ? 1 : 0;
    term_ = std::make_shared<PointwiseTerm<NormalResponseKernel<Law>>>(
        name(), Integration::Faces, std::move(fields), std::vector<int>{0}, std::vector<Coupling>{{0, argument}},
        NormalResponseKernel<Law>{std::move(law), argument});
  }

  std::string name() const override { return "normal response on " + region_; }
  std::vector<BrickTerm> terms() const override { return {{term_, region_}}; }
  bool linear() const override { return law_affine<Law>; }
  // The tangent p_nu' n n^T N_i N_j is symmetric; with the displacement it is a (v, u) block, which has no
  // (u, v) partner to be the transpose of.
  bool symmetric() const override { return !law_uses_displacement<Law>; }
  const Law& law() const { return term_->kernel().law; }

 private:
  std::string region_;
  std::shared_ptr<const PointwiseTerm<NormalResponseKernel<Law>>> term_;
};

}  // namespace pc

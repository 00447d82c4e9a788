#pragma once
// The normal contact term of paper (16): integral over Gamma_C of p_nu(r) w_nu, i.e. the flux
// f0 = p_nu(r) n tested with w = v's test function, where r = v . n for damped responses and r = u . n for
// laws that read the displacement (the model maps u = k v + u_prev onto v's columns). Templated on the law,
// so the law is inlined at every quadrature point; its tangent comes from Dual. The law's parameters are
// model constants (bound_law.hpp):
//
//   model.set_constants(law_values(LinearDampedResponse{1e12}));   // c_nu
//   auto normal = std::make_shared<NormalResponseBrick<LinearDampedResponse>>("bottom");
//
// The brick is also the NormalPressure that friction and foundation bricks on the same surface read.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "assembly/pointwise_term.hpp"
#include "bricks/bound_law.hpp"
#include "bricks/brick.hpp"
#include "bricks/laws/law_traits.hpp"
#include "bricks/normal_pressure.hpp"

namespace pc {

// Field 0 is the tested velocity; `argument` is the field the law reads (0, or 1 for the displacement).
template <class Law> struct NormalResponseKernel {
  std::shared_ptr<const Law> law;
  int argument;
  std::shared_ptr<const FoundationMotion> motion = nullptr;  // null: the foundation is at rest

  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    const auto r = relative_to_foundation(in.value[argument].data(), motion.get(), argument == 1, in.time, in.dim);
    const S p_nu = (*law)(normal_part(r.data(), in.normal, in.dim));
    for (int d = 0; d < in.dim; ++d) out.f0[0][d] = p_nu * in.normal[d];
  }
};

template <class Law> class NormalResponseBrick : public NormalContactBrick {
 public:
  // Parameters read from the model's constants (named by `names`).
  explicit NormalResponseBrick(std::string region = "contact", ContactFields fields = {},
                               ParameterNames names = {}) requires DeclaresParameters<Law>
      : NormalResponseBrick(BoundLaw<Law>(std::move(names)), std::move(region), std::move(fields)) {}
  // A law that declares no parameters, with fixed values.
  explicit NormalResponseBrick(Law law, std::string region = "contact",
                               ContactFields fields = {}) requires(!DeclaresParameters<Law>)
      : NormalResponseBrick(BoundLaw<Law>(std::move(law)), std::move(region), std::move(fields)) {}

  std::string name() const override { return "normal response on " + region_; }
  std::vector<std::string> data() const override { return law_.data(); }
  void update(const DataView& data) override { law_.update(data, name()); }
  std::vector<BrickTerm> terms() const override { return {{term_, region_}}; }
  bool linear() const override { return law_affine<Law>; }
  // A moving foundation makes the residual depend on the time, not only on the unknowns.
  bool time_dependent() const override { return foundation_moves(motion_.get()); }
  // The tangent p_nu' n n^T N_i N_j is symmetric; with the displacement it is a (v, u) block, which has no
  // (u, v) partner to be the transpose of.
  bool symmetric() const override { return !law_uses_displacement<Law>; }
  const Law& law() const { return *law_; }
  const std::string& region() const override { return region_; }

  double pressure(double r, double* slope) const override {
    require(law_.updated(), "brick '", name(),
            "': its pressure was read before update() read its law's parameters "
            "(add the normal brick to the model, or update it, before the bricks paired with it are assembled)");
    const Dual<1> p = (*law_)(Dual<1>::variable(r, 0));
    *slope = p.d[0];
    return p.v;
  }
  bool reads_displacement() const override { return law_uses_displacement<Law>; }
  const FoundationMotion* motion() const override { return motion_.get(); }
  std::vector<std::string> law_data() const override { return law_.data(); }

 private:
  NormalResponseBrick(BoundLaw<Law> law, std::string region, ContactFields fields)
      : region_(std::move(region)), law_(std::move(law)), motion_(fields.motion) {
    const bool displacement = law_uses_displacement<Law>;
    std::vector<FieldUse> uses = {{fields.velocity}};
    if (displacement) uses.push_back({fields.displacement});
    const int argument = displacement ? 1 : 0;
    term_ = std::make_shared<PointwiseTerm<NormalResponseKernel<Law>>>(
        name(), Integration::Faces, std::move(uses), std::vector<int>{0}, std::vector<Coupling>{{0, argument}},
        NormalResponseKernel<Law>{law_.shared(), argument, motion_});
  }

  std::string region_;
  BoundLaw<Law> law_;
  std::shared_ptr<const FoundationMotion> motion_;
  std::shared_ptr<const Term> term_;
};

}  // namespace pc

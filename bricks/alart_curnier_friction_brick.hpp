#pragma once
// Coulomb friction without regularisation: the friction stress is a multiplier lambda on the contact
// surface, an unknown of its own, and Coulomb's law -sigma_tau in mu p_nu d|s| (s the slip velocity
// relative to the foundation) is the Alart-Curnier fixed point
//   lambda = P_B(lambda_tau + r s),  B the disk of radius g = mu |p_nu|,  P_B the projection onto it,
// which holds exactly when the node sticks (s = 0, |lambda| <= g) or slips (lambda = g s / |s|): no
// eps, no creep under a load below the threshold. r > 0 (Pa s/m) scales the slip against the stress. The
// pointwise law does not depend on it; this integral (Galerkin) form of it does, weakly, where stick and
// slip share an element (on the motor: 0.7 % of the thrust over a decade of r); Newton's path depends on
// it strongly. g / r is the width of the "stick band" in slip
// speed that Newton's linearisation sees: wider than the slip speeds of a sticking contact and Newton
// stays on the stick branch (fast); much narrower and it hops between the two slip branches (a 2D slip
// branch has no tangent in the slip). Choose r = mu p / v with v of the order of the contact's speeds.
// The weak form, tested with w (velocity) and m (multiplier), as GetFEM's integral Alart-Curnier bricks:
//   integral lambda_tau . w_tau  +  integral (lambda - P_B(lambda_tau + r s)) . m
// The multiplier's rows are forces, as the velocity's are (Newton measures them by that block's scale).
// The normal component of lambda is held at 0 by the same row. P_B is piecewise smooth: Newton on it is a
// semismooth (generalised) Newton, its tangent from Dual numbers on the active branch.
//
// The multiplier is an unknown the brick brings (Brick::own_unknowns): a field in v's space whose dofs
// off the contact region are eliminated, so the system grows by the contact dofs only. The pressure is the
// paired normal brick's (normal compliance or damped response), exactly as for the regularised law.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "assembly/pointwise_term.hpp"
#include "bricks/laws/law_parameters.hpp"
#include "bricks/paired_law_brick.hpp"

namespace pc {

// The parameters of exact Coulomb friction.
struct AugmentedCoulomb {
  double mu = 0;
  double r = 0;

  static constexpr bool dissipative = true;
  static constexpr bool bounded = true;
  static constexpr bool uses_normal_pressure = true;

  static constexpr auto parameters() {
    return std::array{
        law_parameter("mu", &AugmentedCoulomb::mu, "1", "friction coefficient: slip threshold mu |p_nu|",
                      Range::at_least(0), Required::yes),
        law_parameter("r", &AugmentedCoulomb::r, "Pa s/m",
                      "augmentation: slip speed to stress; mu p / r of the order of the contact's speeds (Newton's "
                      "path depends on it, the solution barely)",
                      Range::positive(), Required::yes)};
  }

  // P_B(z) for the disk of radius g >= 0: z inside, else g z / |z| (0 when g = 0).
  template <class S> static void project(const S* z, int dim, const S& g, S* out) {
    using std::sqrt;
    S norm2 = z[0] * z[0];
    for (int d = 1; d < dim; ++d) norm2 += z[d] * z[d];
    if (norm2 < g * g) {
      for (int d = 0; d < dim; ++d) out[d] = z[d];
      return;
    }
    if (!(norm2 > 0.0)) {
      for (int d = 0; d < dim; ++d) out[d] = S(0.0);
      return;
    }
    const S scale = g / sqrt(norm2);
    for (int d = 0; d < dim; ++d) out[d] = scale * z[d];
  }
};

// Fields: 0 the multiplier (tested), 1 the velocity (tested), and at `pressure_argument` the field the
// paired normal law reads.
struct AlartCurnierKernel {
  std::shared_ptr<const AugmentedCoulomb> law;
  std::shared_ptr<const NormalPressure> normal;
  int pressure_argument;
  std::shared_ptr<const FoundationMotion> motion;

  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    const int dim = in.dim;
    const double r = law->r;
    S lambda_tau[3]{}, slip[3]{}, z[3]{}, projected[3]{};
    tangential_part(in.value[0].data(), in.normal, dim, lambda_tau);
    const auto relative = relative_to_foundation(in.value[1].data(), motion.get(), false, in.time, dim);
    tangential_part(relative.data(), in.normal, dim, slip);
    const S p_nu = normal->at(in.value[pressure_argument].data(), in.normal, dim, in.time);
    const S g = law->mu * (p_nu < 0.0 ? -p_nu : p_nu);
    for (int d = 0; d < dim; ++d) z[d] = lambda_tau[d] + r * slip[d];
    AugmentedCoulomb::project(z, dim, g, projected);
    for (int d = 0; d < dim; ++d) {
      out.f0[0][d] = in.value[0][d] - projected[d];
      out.f0[1][d] = lambda_tau[d];
    }
  }
};

template <class Law = AugmentedCoulomb> class AlartCurnierFrictionBrick : public PairedLawBrick<Law> {
  using Base = PairedLawBrick<Law>;

 public:
  static constexpr const char* kMultiplier = "lambda_tau";

  explicit AlartCurnierFrictionBrick(std::string region, std::shared_ptr<const NormalPressure> normal,
                                     ContactFields fields = {}, ParameterNames names = {})
      : Base(BoundLaw<Law>(std::move(names)), std::move(region), std::move(normal)),
        velocity_(fields.velocity),
        motion_(fields.motion) {
    this->require_pairing_of(name());
    this->require_motion_of_pairing(name(), motion_.get());
    std::vector<FieldUse> uses = {{kMultiplier}, {fields.velocity}};
    // Rows (lambda, v) x columns: the fixed point reads lambda, v and the pressure; the force lambda only.
    std::vector<Coupling> couplings = {{0, 0}, {0, 1}, {1, 0}};
    int pressure_argument = 1;
    if (this->normal_->reads_displacement()) {
      uses.push_back({fields.displacement});
      couplings.push_back({0, 2});
      pressure_argument = 2;
    }
    this->term_ = std::make_shared<PointwiseTerm<AlartCurnierKernel>>(
        name(), Integration::Faces, std::move(uses), std::vector<int>{0, 1}, std::move(couplings),
        AlartCurnierKernel{this->law_.shared(), this->normal_, pressure_argument, motion_});
  }

  std::string name() const override { return "Alart-Curnier Coulomb friction on " + this->region_; }
  bool linear() const override { return false; }
  bool time_dependent() const override { return foundation_moves(motion_.get()) || Base::time_dependent(); }
  std::vector<BrickUnknown> own_unknowns() const override { return {{kMultiplier, velocity_, this->region_}}; }

 private:
  std::string velocity_;
  std::shared_ptr<const FoundationMotion> motion_;
};

}  // namespace pc

#include "bricks/boundary_dashpot_brick.hpp"

#include <cmath>

#include "assembly/error.hpp"
#include "assembly/pointwise_term.hpp"
#include "bricks/brick_registry.hpp"

namespace pc {
namespace {

struct DashpotKernel {
  std::shared_ptr<const double> c_b;
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    for (int d = 0; d < in.dim; ++d) out.f0[0][d] = *c_b * in.value[0][d];
  }
};

}  // namespace

BoundaryDashpotBrick::BoundaryDashpotBrick(std::string region, std::string datum, std::string velocity)
    : region_(std::move(region)), datum_(std::move(datum)), c_b_(std::make_shared<double>(0.0)) {
  term_ = std::make_shared<PointwiseTerm<DashpotKernel>>(
      name(), Integration::Faces, std::vector<FieldUse>{{std::move(velocity)}}, std::vector<int>{0},
      std::vector<Coupling>{{0, 0}}, DashpotKernel{c_b_});
}

void BoundaryDashpotBrick::update(const DataView& data) {
  const double c_b = data.scalar(datum_);
  require_in_range(Range::at_least(0), c_b, message("brick '", name(), "': ", datum_));
  *c_b_ = c_b;
}

}  // namespace pc

PC_REGISTER_BRICK("boundary_dashpot", "c_b v . w on a face region: a viscous support or absorbing boundary",
                  {{"c_b", "Pa s/m", "dashpot coefficient: traction -c_b v", std::nullopt, pc::Range::at_least(0)}},
                  [](const std::string& region) -> std::shared_ptr<pc::Brick> {
                    return std::make_shared<pc::BoundaryDashpotBrick>(region);
                  })

#include "bricks/elasticity_brick.hpp"

#include <utility>

#include "assembly/error.hpp"
#include "bricks/voigt.hpp"

namespace pc {

ElasticityBrick::ElasticityBrick(std::string region, std::string datum, std::string velocity,
                                 std::string displacement)
    : region_(std::move(region)), datum_(std::move(datum)), velocity_(std::move(velocity)),
      displacement_(std::move(displacement)) {}

std::string ElasticityBrick::name() const { return "elasticity (" + datum_ + ") on " + region_; }

void ElasticityBrick::update(const DataView& data) {
  const Eigen::MatrixXd& B = data.constant(datum_);
  check_stiffness(datum_, B, stiffness_dimension(datum_, B));
  term_ = std::make_shared<const StrainStiffnessTerm>(name(), velocity_, displacement_, datum_, B);
}

std::vector<BrickTerm> ElasticityBrick::terms() const {
  require(term_ != nullptr, "brick '", name(), "': terms() asked before update()");
  return {{term_, region_}};
}

}  // namespace pc

#include "bricks/elasticity_brick.hpp"

#include <utility>

#include "assembly/error.hpp"
#include "bricks/voigt.hpp"

namespace pc {

ElasticityBrick::ElasticityBrick(std::string region, std::string datum, std::string velocity, std::string displacement)
    : MaterialBrick("elasticity", std::move(region), std::move(datum), true),
      velocity_(std::move(velocity)),
      displacement_(std::move(displacement)) {}

std::shared_ptr<const Term> ElasticityBrick::make_term(const Eigen::MatrixXd& B) const {
  check_stiffness(datum(), B, stiffness_dimension(datum(), B));
  return std::make_shared<const StrainStiffnessTerm>(name(), velocity_, displacement_, datum(), B);
}

}  // namespace pc

#include "bricks/viscosity_brick.hpp"

#include <utility>

#include "assembly/error.hpp"
#include "bricks/voigt.hpp"

namespace pc {

ViscosityBrick::ViscosityBrick(std::string region, std::string datum, std::string velocity)
    : MaterialBrick("viscosity", std::move(region), std::move(datum), true), velocity_(std::move(velocity)) {}

std::shared_ptr<const Term> ViscosityBrick::make_term(const Eigen::MatrixXd& A) const {
  check_stiffness(datum(), A, stiffness_dimension(datum(), A), /*allow_zero=*/true);
  return std::make_shared<const StrainStiffnessTerm>(name(), velocity_, velocity_, datum(), A);
}

}  // namespace pc

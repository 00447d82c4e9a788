#include "bricks/viscosity_brick.hpp"

#include <utility>

#include "assembly/error.hpp"
#include "bricks/voigt.hpp"

namespace pc {

ViscosityBrick::ViscosityBrick(std::string region, std::string datum, std::string velocity)
    : region_(std::move(region)), datum_(std::move(datum)), velocity_(std::move(velocity)) {}

std::string ViscosityBrick::name() const { return "viscosity (" + datum_ + ") on " + region_; }

void ViscosityBrick::update(const DataView& data) {
  const Eigen::MatrixXd& A = data.constant(datum_);
  check_stiffness(datum_, A, stiffness_dimension(datum_, A), /*allow_zero=*/true);
  term_ = std::make_shared<const StrainStiffnessTerm>(name(), velocity_, velocity_, datum_, A);
}

std::vector<BrickTerm> ViscosityBrick::terms() const {
  require(term_ != nullptr, "brick '", name(), "': terms() asked before update()");
  return {{term_, region_}};
}

}  // namespace pc

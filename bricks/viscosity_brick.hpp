#pragma once
// Kelvin-Voigt viscosity A eps(v) : eps(w) (paper eq. (1), (20)). A = 0 is allowed and means no viscosity.
#include <memory>
#include <string>

#include "bricks/material_brick.hpp"
#include "bricks/strain_stiffness_term.hpp"

namespace pc {

class ViscosityBrick : public MaterialBrick {
 public:
  explicit ViscosityBrick(std::string region = "all", std::string datum = "A", std::string velocity = "v");

 private:
  std::shared_ptr<const Term> make_term(const Eigen::MatrixXd& constant) const override;
  std::string velocity_;
};

}  // namespace pc

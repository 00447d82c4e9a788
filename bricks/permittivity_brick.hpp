#pragma once
// Permittivity beta grad phi . grad psi (paper eq. (2), (21)): the electric part of -div D = -q0 with
// D = E eps(u) - beta grad phi; the coupling part is in the piezoelectric brick.
#include <memory>
#include <string>

#include "bricks/material_brick.hpp"

namespace pc {

class PermittivityBrick : public MaterialBrick {
 public:
  explicit PermittivityBrick(std::string region = "all", std::string datum = "beta", std::string potential = "phi");

 private:
  std::shared_ptr<const Term> make_term(const Eigen::MatrixXd& constant) const override;
  std::string potential_;
};

}  // namespace pc

#pragma once
// Piezoelectric coupling (paper eq. (1), (2), (20), (21)), with E the dim x n Voigt tensor:
//   momentum rows (test w):   + (E^T grad phi) : eps(w)    from sigma = ... - E^T E_field, E_field = -grad phi
//   electric rows (test psi): - (E eps(u)) . grad psi      from D = E eps(u) - beta grad phi
// One term with the fields {v, phi, u} and the couplings (v, phi) and (phi, u). The blocks are not
// transposes of each other (opposite signs, and u = k v in the model), so the brick is not symmetric.
#include <memory>
#include <string>

#include "bricks/material_brick.hpp"

namespace pc {

class PiezoelectricCouplingBrick : public MaterialBrick {
 public:
  explicit PiezoelectricCouplingBrick(std::string region = "all", std::string datum = "E", std::string velocity = "v",
                                      std::string potential = "phi", std::string displacement = "u");

 private:
  std::shared_ptr<const Term> make_term(const Eigen::MatrixXd& constant) const override;
  std::string velocity_, potential_, displacement_;
};

}  // namespace pc

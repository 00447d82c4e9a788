#pragma once
// Piezoelectric coupling (paper eq. (1), (2), (20), (21)), with E the dim x n Voigt tensor:
//   momentum rows (test w):   + (E^T grad phi) : eps(w)    from sigma = ... - E^T E_field, E_field = -grad phi
//   electric rows (test psi): - (E eps(u)) . grad psi      from D = E eps(u) - beta grad phi
// One term with the fields {v, phi, u} and the couplings (v, phi) and (phi, u). The blocks are not
// transposes of each other (opposite signs, and u = k v in the model), so the brick is not symmetric.
#include <memory>
#include <string>

#include "bricks/brick.hpp"

namespace pc {

class PiezoelectricCouplingBrick : public Brick {
 public:
  explicit PiezoelectricCouplingBrick(std::string region = "all", std::string datum = "E", std::string velocity = "v",
                                      std::string potential = "phi", std::string displacement = "u");

  std::string name() const override;
  std::vector<std::string> data() const override { return {datum_}; }
  void update(const DataView& data) override;
  std::vector<BrickTerm> terms() const override;
  bool linear() const override { return true; }

 private:
  std::string region_, datum_, velocity_, potential_, displacement_;
  std::shared_ptr<const Term> term_;
};

}  // namespace pc

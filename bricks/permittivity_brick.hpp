#pragma once
// Permittivity beta grad phi . grad psi (paper eq. (2), (21)): the electric part of -div D = -q0 with
// D = E eps(u) - beta grad phi; the coupling part is in the piezoelectric brick.
#include <memory>
#include <string>

#include "bricks/brick.hpp"

namespace pc {

class PermittivityBrick : public Brick {
 public:
  explicit PermittivityBrick(std::string region = "all", std::string datum = "beta", std::string potential = "phi");

  std::string name() const override;
  std::vector<std::string> data() const override { return {datum_}; }
  void update(const DataView& data) override;
  std::vector<BrickTerm> terms() const override;
  bool linear() const override { return true; }
  bool symmetric() const override { return true; }

 private:
  std::string region_, datum_, potential_;
  std::shared_ptr<const Term> term_;
};

}  // namespace pc

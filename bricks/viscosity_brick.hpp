#pragma once
// Kelvin-Voigt viscosity A eps(v) : eps(w) (paper eq. (1), (20)). A = 0 is allowed and means no viscosity.
#include <memory>
#include <string>

#include "bricks/brick.hpp"
#include "bricks/strain_stiffness_term.hpp"

namespace pc {

class ViscosityBrick : public Brick {
 public:
  explicit ViscosityBrick(std::string region = "all", std::string datum = "A", std::string velocity = "v");

  std::string name() const override;
  std::vector<std::string> data() const override { return {datum_}; }
  void update(const DataView& data) override;
  std::vector<BrickTerm> terms() const override;
  bool linear() const override { return true; }
  bool symmetric() const override { return true; }

 private:
  std::string region_, datum_, velocity_;
  std::shared_ptr<const StrainStiffnessTerm> term_;
};

}  // namespace pc

#pragma once
// Inertia rho a . w (paper eq. (3), (20)) with a the model's affine acceleration field, so the tangent
// block is (v, a): the consistent mass matrix. A quasi-static model leaves this brick out.
#include <memory>
#include <string>

#include "bricks/brick.hpp"

namespace pc {

class InertiaBrick : public Brick {
 public:
  explicit InertiaBrick(std::string region = "all", std::string datum = "rho", std::string velocity = "v",
                        std::string acceleration = "a");

  std::string name() const override;
  std::vector<std::string> data() const override { return {datum_}; }
  void update(const DataView& data) override;
  std::vector<BrickTerm> terms() const override;
  bool linear() const override { return true; }
  bool symmetric() const override { return true; }

 private:
  std::string region_, datum_, velocity_, acceleration_;
  std::shared_ptr<const Term> term_;
};

}  // namespace pc

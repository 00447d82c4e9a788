#pragma once
// Inertia rho a . w (paper eq. (3), (20)) with a the model's affine acceleration field, so the tangent
// block is (v, a): the consistent mass matrix. A quasi-static model leaves this brick out.
#include <memory>
#include <string>

#include "bricks/material_brick.hpp"

namespace pc {

class InertiaBrick : public MaterialBrick {
 public:
  explicit InertiaBrick(std::string region = "all", std::string datum = "rho", std::string velocity = "v",
                        std::string acceleration = "a");

 private:
  std::shared_ptr<const Term> make_term(const Eigen::MatrixXd& constant) const override;
  std::string velocity_, acceleration_;
};

}  // namespace pc

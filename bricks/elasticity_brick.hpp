#pragma once
// Linear elasticity B eps(u) : eps(w) (paper eq. (1), (20)), tested with the velocity's test functions;
// u is the model's affine displacement field, so the tangent block is (v, u).
#include <memory>
#include <string>

#include "bricks/material_brick.hpp"
#include "bricks/strain_stiffness_term.hpp"

namespace pc {

class ElasticityBrick : public MaterialBrick {
 public:
  explicit ElasticityBrick(std::string region = "all", std::string datum = "B", std::string velocity = "v",
                           std::string displacement = "u");

 private:
  std::shared_ptr<const Term> make_term(const Eigen::MatrixXd& constant) const override;
  std::string velocity_, displacement_;
};

}  // namespace pc

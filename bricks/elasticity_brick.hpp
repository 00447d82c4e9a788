#pragma once
// Linear elasticity B eps(u) : eps(w) (paper eq. (1), (20)), tested with the velocity's test functions;
// u is the model's affine displacement field, so the tangent block is (v, u).
#include <memory>
#include <string>

#include "bricks/brick.hpp"
#include "bricks/strain_stiffness_term.hpp"

namespace pc {

class ElasticityBrick : public Brick {
 public:
  explicit ElasticityBrick(std::string region = "all", std::string datum = "B", std::string velocity = "v",
                           std::string displacement = "u");

  std::string name() const override;
  std::vector<std::string> data() const override { return {datum_}; }
  void update(const DataView& data) override;
  std::vector<BrickTerm> terms() const override;
  bool linear() const override { return true; }
  bool symmetric() const override { return true; }

 private:
  std::string region_, datum_, velocity_, displacement_;
  std::shared_ptr<const StrainStiffnessTerm> term_;
};

}  // namespace pc

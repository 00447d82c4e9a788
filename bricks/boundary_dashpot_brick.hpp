#pragma once
// A dashpot on a face region: the traction -c_b v, i.e. the term c_b v . w over the region (a viscous
// support, or the simplest absorbing boundary for waves leaving the body). The coefficient is the model
// constant "c_b" (renamable), read in update(); the term is linear and symmetric, so the model assembles it
// once per change of c_b. Registered as the brick "boundary_dashpot" that scenes add under "bricks".
#include <memory>
#include <string>

#include "bricks/brick.hpp"

namespace pc {

class BoundaryDashpotBrick : public Brick {
 public:
  explicit BoundaryDashpotBrick(std::string region, std::string datum = "c_b", std::string velocity = "v");
  std::string name() const override { return "boundary dashpot (" + datum_ + ") on " + region_; }
  std::vector<std::string> data() const override { return {datum_}; }
  void update(const DataView& data) override;
  std::vector<BrickTerm> terms() const override { return {{term_, region_}}; }
  bool linear() const override { return true; }
  bool symmetric() const override { return true; }

 private:
  std::string region_, datum_;
  std::shared_ptr<double> c_b_;  // read by the term's kernel: a new value keeps the term and its pattern
  std::shared_ptr<const Term> term_;
};

}  // namespace pc

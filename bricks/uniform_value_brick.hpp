#pragma once
// One unknown value of a field's component over a region: the potential of a floating electrode (a
// conductor connected to nothing, or to a given charge). The model ties the region's dofs to one
// unknown (DofLayout), so the region's residuals are summed into one equation: with no source there, the
// net charge -integral D . n over the region vanishes (an open circuit); a SurfaceChargeBrick on the
// region sets it to a given charge. Like DirichletBrick, the brick has no terms; it hands over its condition.
#include <string>
#include <vector>

#include "bricks/brick.hpp"

namespace pc {

class UniformValueBrick : public Brick {
 public:
  UniformValueBrick(std::string unknown, std::string region, int component = 0)
      : condition_{std::move(unknown), std::move(region), component} {}

  std::string name() const override { return "uniform value of " + condition_.unknown + " over " + condition_.region; }
  std::vector<BrickTerm> terms() const override { return {}; }
  std::vector<UniformValueCondition> uniform_value_conditions() const override { return {condition_}; }
  bool linear() const override { return true; }
  bool symmetric() const override { return true; }  // summing rows and columns alike keeps symmetry

 private:
  UniformValueCondition condition_;
};

}  // namespace pc

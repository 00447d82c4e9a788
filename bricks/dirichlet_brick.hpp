#pragma once
// Prescribed values of an unknown on a region (paper eq. (5), (7): u = 0 on Gamma_D, phi = 0 on Gamma_a),
// imposed by the model by elimination. The brick has no terms; it only hands over its condition.
// In the velocity formulation, a clamped displacement is prescribed as v = 0 (with u0 = 0 there).
#include <functional>
#include <string>
#include <vector>

#include "bricks/brick.hpp"

namespace pc {

class DirichletBrick : public Brick {
 public:
  using Value = std::function<void(const double* x, double t, double* out)>;

  // value(x, t, out) writes the field's components (out has room for 3); only those in `components`
  // (empty: all) are imposed. time_dependent: whether the values change with t.
  DirichletBrick(std::string unknown, std::string region, std::vector<int> components, Value value,
                 bool time_dependent);
  // The same constant on every imposed component.
  DirichletBrick(std::string unknown, std::string region, std::vector<int> components, double value);
  // Value zero, e.g. clamp("v", "left") or clamp("v", "bottom", {1}) for a roller.
  static DirichletBrick clamp(std::string unknown, std::string region, std::vector<int> components = {});

  std::string name() const override;
  std::vector<BrickTerm> terms() const override { return {}; }
  std::vector<DirichletCondition> dirichlet_conditions() const override { return {condition_}; }
  bool linear() const override { return true; }
  bool symmetric() const override { return true; }  // elimination keeps a symmetric system symmetric
  bool time_dependent() const override { return time_dependent_; }

 private:
  DirichletCondition condition_;
  bool time_dependent_;
};

}  // namespace pc

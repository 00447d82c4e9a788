#pragma once
// A brick: one piece of physics, stateless, that a Model stacks with others (GetFEM's design). It hands
// the engine point-wise terms over regions and declares what the model needs to assemble and cache it:
// which fields and data it reads, whether its residual is affine in the unknowns (then the model
// assembles its tangent once per change of its data and computes its residual by mat-vec), whether its
// tangent is symmetric, and whether it depends on time explicitly (sources).
//
// Fields are named as in the model: unknowns ("v", "phi"), affine fields ("u" = k v + u_prev,
// "a" = (v - v_prev) / k) and data fields. A term's test fields must be unknowns.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/term.hpp"

namespace pc {

// Read access to the model's named constants (material tensors, law parameters); implemented by Model.
class DataView {
 public:
  virtual ~DataView() = default;
  // Throws naming the datum if it does not exist.
  virtual const Eigen::MatrixXd& constant(const std::string& name) const = 0;
  double scalar(const std::string& name) const;  // a 1 x 1 constant
};

struct BrickTerm {
  std::shared_ptr<const Term> term;
  std::string region;
};

// Values prescribed on dofs of an unknown by elimination: value(x, t, out) writes the field's components
// (out has room for 3, so that a value need not know the field's component count).
struct DirichletCondition {
  std::string unknown;
  std::string region;
  std::vector<int> components;  // empty: all components
  std::function<void(const double* x, double t, double* out)> value;
};

// One unknown value of a component of an unknown over a region, e.g. the potential of a floating
// electrode: the region's dofs of that component share one global index (DofLayout), so the value is
// solved for and the region's residuals are summed (zero net charge, or the charge a source puts there).
struct UniformValueCondition {
  std::string unknown;
  std::string region;
  int component = 0;
};

// An unknown a brick brings with it, e.g. a contact multiplier: a field in the space of the field `like`,
// living on `region` only (its dofs off the region, and those where `like` is prescribed, are eliminated
// at 0, so the system grows by the region's free dofs). The model adds it when the brick is added. Its residual must be
// in the units of like's (a force, for a multiplier of v): Newton measures it at least by that block's scale.
struct BrickUnknown {
  std::string name;
  std::string like;
  std::string region;
};

class Brick {
 public:
  virtual ~Brick() = default;
  virtual std::string name() const = 0;

  // Names of model constants the brick reads; a change of any of them invalidates its cached assembly.
  virtual std::vector<std::string> data() const { return {}; }
  // (Re)builds the brick's terms from the model's constants. Called when the brick is added and whenever
  // a datum it reads changes; terms() is valid after it (a brick may build its
  // terms earlier and only change what they read here, so that a parameter change keeps its pattern).
  virtual void update(const DataView& data) { (void)data; }
  // The terms to integrate, each over a region of the model's mesh.
  virtual std::vector<BrickTerm> terms() const = 0;
  // Conditions eliminated from the system (Dirichlet bricks); most bricks have none.
  virtual std::vector<DirichletCondition> dirichlet_conditions() const { return {}; }
  // Unknowns the brick brings (multipliers); most bricks have none.
  virtual std::vector<BrickUnknown> own_unknowns() const { return {}; }
  // Regions where an unknown takes one value (UniformValueBrick); most bricks have none.
  virtual std::vector<UniformValueCondition> uniform_value_conditions() const { return {}; }

  // Residual affine in the unknowns: tangent cached, residual by mat-vec.
  virtual bool linear() const = 0;
  // Every tangent block is symmetric (K_ab = K_ba^T, in particular each diagonal block is symmetric).
  virtual bool symmetric() const { return false; }
  // The residual depends on time explicitly; its constant part is re-assembled when the time changes.
  virtual bool time_dependent() const { return false; }
};

}  // namespace pc

// The bricks that docs/bricks.md ("Writing a brick") shows, compiled and checked: the regions marked
// [snippet ...] are those blocks, kept equal by scripts/check_snippets.py.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "assembly/mesh_generators.hpp"
#include "assembly/pointwise_term.hpp"
#include "bricks/brick.hpp"
#include "bricks/testing/brick_checker.hpp"
#include "bricks/weak_form_brick.hpp"
#include "models/model.hpp"

namespace pc {
namespace {

// [snippet cubic_damping]
struct CubicDamping {  // f0 = k v^3 per component, tested with v
  double k;
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    for (int c = 0; c < in.dim; ++c) out.f0[0][c] = k * in.value[0][c] * in.value[0][c] * in.value[0][c];
  }
};
// [snippet cubic_damping end]

// The kernel of MassDampingBrick's term, as the text after that block describes it.
struct Damping {
  double c;
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    for (int k = 0; k < in.dim; ++k) out.f0[0][k] = c * in.value[0][k];
  }
};

// [snippet mass_damping]
class MassDampingBrick : public Brick {  // c v . w, with c the model constant "c"
 public:
  explicit MassDampingBrick(std::string region = "all") : region_(std::move(region)) {}
  std::string name() const override { return "mass damping on " + region_; }
  std::vector<std::string> data() const override { return {"c"}; }
  void update(const DataView& data) override {  // on add_brick, and when "c" changes
    term_ = std::make_shared<PointwiseTerm<Damping>>(name(), Integration::Cells, std::vector<FieldUse>{{"v"}},
                                                     std::vector<int>{0}, std::vector<Coupling>{{0, 0}},
                                                     Damping{data.scalar("c")});
  }
  std::vector<BrickTerm> terms() const override { return {{term_, region_}}; }
  bool linear() const override { return true; }
  bool symmetric() const override { return true; }

 private:
  std::string region_;
  std::shared_ptr<const Term> term_;
};
// [snippet mass_damping end]

// The unit square with v = (1, 0) everywhere: the x-components of a residual sum to the integral of its
// f0 (the test functions are a partition of unity), the y-components to 0.
std::pair<double, double> residual_sums_at_unit_velocity(Model& model) {
  model.finalize();
  Eigen::VectorXd v = Eigen::VectorXd::Zero(model.space("v").num_dofs());
  for (int i = 0; i < v.size(); i += 2) v[i] = 1.0;
  model.set_values("v", v);
  model.assemble(false);
  const Eigen::VectorXd& r = model.field_residual("v");
  double x = 0, y = 0;
  for (int i = 0; i < r.size(); i += 2) x += r[i], y += r[i + 1];
  return {x, y};
}

std::unique_ptr<Model> unit_square_model() {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 2, 2, Shape::Triangle));
  auto model = std::make_unique<Model>(mesh);
  model->add_unknown("v", std::make_shared<const FESpace>(mesh, 1, 2));
  return model;
}

// Its checks (tangent against finite differences, claims, extremes) on the harness's square.
void expect_brick_passes_the_checker(Brick& brick, const ConstantTable& constants) {
  const BrickCheckReport report = check_brick(brick, constants, BrickCheckSetup::square());
  EXPECT_TRUE(report.ok()) << report;
  EXPECT_GT(report.tangent_checks, 0) << brick.name();
}

// k v^3 on the bottom side (length 1) at |v| = 1: the x-residual sums to k = 2.
TEST(DocumentedBricks, CubicDampingOnTheBottomSideSumsToK) {
  const std::unique_ptr<Model> square = unit_square_model();
  Model& model = *square;
  // [snippet cubic_damping]
  const WeakForm form{.name = "cubic damping",
                      .fields = {{"v"}},
                      .tests = {"v"},
                      .couplings = {{"v", "v"}},
                      .region = "bottom",
                      .integration = Integration::Faces};
  model.add_brick(std::make_shared<WeakFormBrick<CubicDamping>>(form, CubicDamping{2.0}));
  // [snippet cubic_damping end]
  const auto [x, y] = residual_sums_at_unit_velocity(model);
  EXPECT_NEAR(x, 2.0, 1e-13);
  EXPECT_NEAR(y, 0.0, 1e-13);
  expect_brick_passes_the_checker(*model.bricks().back(), ConstantTable());
}

// c v on the square (area 1) at v = (1, 0): the x-residual sums to c = 3.
TEST(DocumentedBricks, MassDampingSumsToTheConstantC) {
  const std::unique_ptr<Model> square = unit_square_model();
  Model& model = *square;
  model.set_constant("c", 3.0);
  model.add_brick(std::make_shared<MassDampingBrick>());
  const auto [x, y] = residual_sums_at_unit_velocity(model);
  EXPECT_NEAR(x, 3.0, 1e-13);
  EXPECT_NEAR(y, 0.0, 1e-13);
  expect_brick_passes_the_checker(*model.bricks().back(), ConstantTable().set("c", 3.0));
}

}  // namespace
}  // namespace pc

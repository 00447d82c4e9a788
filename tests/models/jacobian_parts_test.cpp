// The parts of the Jacobian a Model gives its solvers (models/model.hpp): the linear part A, the
// nonlinear bricks' part J - A on the nonlinear rows (all the condensed solves read), and J itself,
// formed only when asked for. On the paper's conductive strip pressed into the foundation: the parts sum
// to J, J - A vanishes off the nonlinear rows and columns, and a Jacobian whose factors are gone (a step
// begun since the last tangent) is refused rather than formed from blocks of another step.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "assembly/error.hpp"
#include "models/scene/scene.hpp"

namespace pc {
namespace {

using ::testing::HasSubstr;

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";

struct PressedStrip {
  PressedStrip() {
    const Scene scene = load_scene_file(kScene, {"mesh.nx=15", "mesh.ny=5"});
    PiezoContactSpec spec = scene.spec;
    spec.foundation = find_foundation(scene, "conductive").law;
    built = build_piezo_contact_model(spec);
    Model& m = *built.model;
    built.scheme->begin_step(m, 0.01);
    // Moving down and sideways: the bottom nodes are in contact, and slide.
    Eigen::VectorXd v(m.space("v").num_dofs());
    for (int i = 0; i < v.size(); ++i) v[i] = i % 2 == 0 ? 1e-3 : -2e-3;
    m.set_values("v", v);
    m.apply_dirichlet();
    m.assemble(true);
  }
  PiezoContactModel built;
};

TEST(JacobianParts, TheNonlinearRowsAndTheLinearPartSumToTheJacobian) {
  PressedStrip strip;
  Model& m = *strip.built.model;
  std::vector<double> part;
  m.nonlinear_part(part);
  const CsrMatrix& A = m.linear_jacobian();
  const CsrMatrix& J = m.jacobian();
  ASSERT_EQ(J.nonZeros(), A.nonZeros());
  const std::vector<int>& rows = m.nonlinear_dofs();
  ASSERT_FALSE(rows.empty());
  std::vector<char> nonlinear(size_t(J.rows()), 0);
  for (int r : rows) nonlinear[size_t(r)] = 1;

  const double scale = Eigen::Map<const Eigen::VectorXd>(J.valuePtr(), J.nonZeros()).cwiseAbs().maxCoeff();
  size_t value = 0;
  double largest_part = 0, worst_mismatch = 0, off_rows = 0;
  for (int row = 0; row < J.rows(); ++row)
    for (int k = J.outerIndexPtr()[row]; k < J.outerIndexPtr()[row + 1]; ++k) {
      const double difference = J.valuePtr()[k] - A.valuePtr()[k];
      if (!nonlinear[size_t(row)] || !nonlinear[size_t(J.innerIndexPtr()[k])]) {
        off_rows = std::max(off_rows, std::abs(difference));
        if (!nonlinear[size_t(row)]) continue;
      }
      largest_part = std::max(largest_part, std::abs(part[value]));
      worst_mismatch = std::max(worst_mismatch, std::abs(part[value] - difference));
      ++value;
    }
  EXPECT_EQ(value, part.size()) << "one value per slot of the nonlinear rows";
  EXPECT_EQ(off_rows, 0.0) << "J - A vanishes outside the nonlinear rows and columns";
  EXPECT_GT(largest_part, 1e-6 * scale) << "the contact is active: its tangent is in the part";
  // J - A taken from J's values carries J's round-off; the part is summed alone.
  EXPECT_LT(worst_mismatch, 1e-13 * scale);
}

TEST(JacobianParts, AJacobianAskedForAfterTheNextStepBeganIsRefused) {
  PressedStrip strip;
  Model& m = *strip.built.model;
  strip.built.scheme->begin_step(m, 0.005);  // new factors; the nonlinear blocks are the old step's
  std::vector<double> part;
  EXPECT_THAT([&] { (void)m.jacobian(); },
              ::testing::ThrowsMessage<Error>(HasSubstr("factors changed since the last assemble(true)")));
  EXPECT_THAT([&] { m.nonlinear_part(part); },
              ::testing::ThrowsMessage<Error>(HasSubstr("factors changed since the last assemble(true)")));
  m.assemble(true);
  EXPECT_NO_THROW((void)m.jacobian());
}

}  // namespace
}  // namespace pc

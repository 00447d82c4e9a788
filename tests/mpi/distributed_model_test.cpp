// A Model distributed over the processes of `mpirun -np 2` (this executable is started so by ctest): its
// residual and reactions are the whole model's on every process, its Jacobian shares sum to the whole
// Jacobian, and an element that throws on one process stops every process with that process's message,
// rather than leaving the others waiting in the residual's sums.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"
#include "assembly/processes.hpp"
#include "bricks/weak_form_brick.hpp"
#include "models/model.hpp"
#include "support/nonlinear_terms.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

// Fails at the points left of x = 0.5: in the cells of one process of two.
struct FailsOnTheLeft {
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    if (in.x[0] < 0.5) fail("the kernel met x = ", in.x[0]);
    for (int c = 0; c < in.dim; ++c) out.f0[0][c] = in.value[0][c];
  }
};

template <class Kernel>
std::shared_ptr<Brick> brick_of(const std::string& region, Integration integration, Kernel kernel) {
  return std::make_shared<WeakFormBrick<Kernel>>(WeakForm{.name = region + " term",
                                                          .fields = {{"u", integration == Integration::Cells}},
                                                          .tests = {"u"},
                                                          .couplings = {{"u", "u"}},
                                                          .region = region,
                                                          .integration = integration},
                                                 kernel);
}

TEST(DistributedModel, RunsOnTwoProcesses) { ASSERT_EQ(processes::count(), 2) << "start it with mpirun -np 2"; }

TEST(DistributedModel, ResidualsAreTheWholeModelsAndJacobianSharesSumToTheWhole) {
  for (const Shape shape : {Shape::Triangle, Shape::Tetrahedron}) {
    auto mesh = std::make_shared<const Mesh>(shape == Shape::Triangle ? rectangle_mesh({0, 0}, {3, 1}, 24, 8, shape)
                                                                      : box_mesh({0, 0, 0}, {3, 1, 1}, 9, 3, 3, shape));
    auto space = std::make_shared<const FESpace>(mesh, 1, mesh->dim());
    Model model(mesh);
    model.add_unknown("u", space);
    model.add_brick(brick_of("all", Integration::Cells, testing::NonlinearDiffusion{}));
    model.add_brick(brick_of("boundary", Integration::Faces, testing::FaceReaction{}));
    model.finalize();
    int owned = 0;
    for (char c : model.owned_cells()) owned += c;
    EXPECT_GT(owned, 0);
    EXPECT_LT(owned, mesh->num_cells()) << "a process holds all cells";

    const Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(space->num_dofs(), -0.7, 1.3);
    model.set_values("u", u);
    model.assemble(true);
    // The whole model's terms, assembled here by one undivided element loop each.
    const auto cells = testing::assembled_term<testing::NonlinearDiffusion>(*space, Integration::Cells, "all");
    const auto faces = testing::assembled_term<testing::FaceReaction>(*space, Integration::Faces, "boundary");
    const Eigen::VectorXd whole = cells.first + faces.first;
    const double scale = whole.cwiseAbs().maxCoeff();
    EXPECT_LE((model.field_residual("u") - whole).cwiseAbs().maxCoeff(), 1e-13 * scale);
    // No Dirichlet condition: the free dofs are the dofs, in their order.
    ASSERT_EQ(model.jacobian().rows(), space->num_dofs());
    Eigen::MatrixXd sum = Eigen::MatrixXd(model.jacobian());
    const double share = sum.cwiseAbs().sum();
    processes::sum({sum.data(), size_t(sum.size())});
    const Eigen::MatrixXd expected = Eigen::MatrixXd(cells.second) + Eigen::MatrixXd(faces.second);
    EXPECT_LE((sum - expected).cwiseAbs().maxCoeff(), 1e-13 * expected.cwiseAbs().maxCoeff());
    EXPECT_LT(share, 0.9 * expected.cwiseAbs().sum()) << "this process's share is the whole Jacobian";
  }
}

TEST(DistributedModel, AnElementThatFailsOnOneProcessStopsEveryProcessWithItsMessage) {
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {3, 1}, 24, 8, Shape::Triangle));
  auto space = std::make_shared<const FESpace>(mesh, 1, 2);
  Model model(mesh);
  model.add_unknown("u", space);
  model.add_brick(brick_of("all", Integration::Cells, FailsOnTheLeft{}));
  model.finalize();
  // Does this process own a cell left of x = 0.5? (METIS splits the long strip across its length.)
  bool left = false;
  for (int c = 0; c < mesh->num_cells(); ++c)
    if (model.owned_cells()[size_t(c)] && mesh->node(mesh->cell(c)[0])[0] < 0.5) left = true;
  ASSERT_TRUE(processes::any(left) && processes::any(!left)) << "the failing cells are on every process";
  const std::string error = testing::error_of([&] { model.assemble(true); });
  if (left) {
    EXPECT_NE(error.find("the kernel met x = "), std::string::npos) << error;
  } else {
    EXPECT_NE(error.find("brick 'all term' failed on process "), std::string::npos) << error;
    EXPECT_NE(error.find("the kernel met x = "), std::string::npos) << error;
  }
  // The processes are still in step: a collective call after the failure completes.
  EXPECT_TRUE(processes::any(true));
}

}  // namespace
}  // namespace pc

// Threaded assembly (assembly/threads.hpp) is bitwise the serial one: a nonlinear term's residual and
// tangent over cells and faces, P1 and P2, 2D and 3D, on 1, 2 and 3 threads (more threads than this
// machine's cores included); an element that throws is reported as the first failing element, whatever
// the thread that met it; PIEZOCONTACT_THREADS is read and checked; Eigen's own products follow the count.
#include "assembly/threads.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <memory>

#include "assembly/error.hpp"
#include "assembly/mesh_generators.hpp"
#include "assembly/pointwise_term.hpp"
#include "assembly/term_assembly.hpp"
#include "support/nonlinear_terms.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

using testing::error_of;
using testing::FaceReaction;
using testing::NonlinearDiffusion;

// Restores the default thread count when a test ends.
struct ThreadsGuard {
  ~ThreadsGuard() { set_assembly_threads(0); }
};

// The term's residual and tangent values, assembled on `threads` threads.
template <class Kernel>
std::pair<Eigen::VectorXd, Eigen::VectorXd> assembled(const FESpace& space, Integration integration,
                                                      const std::string& region, int threads) {
  set_assembly_threads(threads);
  const auto [r, k] = testing::assembled_term<Kernel>(space, integration, region);
  return {r, Eigen::Map<const Eigen::VectorXd>(k.valuePtr(), k.nonZeros())};
}

bool bitwise_equal(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * size_t(a.size())) == 0;
}

TEST(Threads, AssemblyOnSeveralThreadsIsBitwiseTheSerialOne) {
  ThreadsGuard guard;
  struct Case {
    std::shared_ptr<const Mesh> mesh;
    int order;
  };
  // Above the 256 elements from which a loop is threaded, and past one chunk of 1024 elements.
  const Case cases[] = {
      {std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {3, 1}, 48, 16, Shape::Triangle)), 1},
      {std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {3, 1}, 30, 10, Shape::Quadrilateral)), 2},
      {std::make_shared<const Mesh>(box_mesh({0, 0, 0}, {3, 1, 1}, 12, 4, 4, Shape::Tetrahedron)), 1},
      {std::make_shared<const Mesh>(box_mesh({0, 0, 0}, {3, 1, 1}, 9, 3, 3, Shape::Hexahedron)), 2},
  };
  for (const Case& c : cases) {
    const FESpace space(c.mesh, c.order, c.mesh->dim());
    const auto serial = assembled<NonlinearDiffusion>(space, Integration::Cells, "all", 1);
    const auto faces_serial = assembled<FaceReaction>(space, Integration::Faces, "boundary", 1);
    ASSERT_GT(serial.second.cwiseAbs().maxCoeff(), 0);
    for (int threads : {2, 3}) {
      const auto threaded = assembled<NonlinearDiffusion>(space, Integration::Cells, "all", threads);
      EXPECT_TRUE(bitwise_equal(serial.first, threaded.first)) << c.mesh->num_cells() << " cells, " << threads;
      EXPECT_TRUE(bitwise_equal(serial.second, threaded.second)) << c.mesh->num_cells() << " cells, " << threads;
      const auto faces = assembled<FaceReaction>(space, Integration::Faces, "boundary", threads);
      EXPECT_TRUE(bitwise_equal(faces_serial.first, faces.first)) << threads;
      EXPECT_TRUE(bitwise_equal(faces_serial.second, faces.second)) << threads;
    }
  }
}

// A term that fails on some elements: the error of the first of them comes out of the threaded loop.
class FailingTerm : public Term {
 public:
  FailingTerm() : Term("failing", Integration::Cells, {{"u", false}}, {0}, {{0, 0}}) {}
  void assemble(const ElementData& e, LocalSystem&, bool, bool) const override {
    if (e.cell == 700 || e.cell == 1500 || e.cell == 300) fail("element ", e.cell, " failed");
  }
};

TEST(Threads, TheFirstFailingElementIsReportedWhateverTheThreads) {
  ThreadsGuard guard;
  auto mesh = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {3, 1}, 48, 16, Shape::Triangle));
  const FESpace space(mesh, 1, 1);
  TermAssembly assembly(std::make_shared<FailingTerm>(), "all", {&space});
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(space.num_dofs());
  const Eigen::VectorXd* values[] = {&u};
  Eigen::VectorXd* none[] = {nullptr};
  for (int threads : {1, 2, 3}) {
    set_assembly_threads(threads);
    EXPECT_EQ(error_of([&] { assembly.assemble(values, 0.0, none, true); }), "element 300 failed") << threads;
  }
}

TEST(Threads, TheEnvironmentVariableIsReadAndChecked) {
  ThreadsGuard guard;
  set_assembly_threads(0);
  ::setenv("PIEZOCONTACT_THREADS", "3", 1);
  EXPECT_EQ(assembly_threads(), 3);
  set_assembly_threads(2);
  EXPECT_EQ(assembly_threads(), 2) << "the program's own choice wins";
  set_assembly_threads(0);
  for (const char* bad : {"0", "two", "3x", "-1"}) {
    ::setenv("PIEZOCONTACT_THREADS", bad, 1);
    EXPECT_EQ(error_of([] { default_assembly_threads(); }),
              std::string("PIEZOCONTACT_THREADS must be an integer from 1 to 4096, got '") + bad + "'");
  }
  ::unsetenv("PIEZOCONTACT_THREADS");
  EXPECT_GE(assembly_threads(), 1);
  EXPECT_THROW(set_assembly_threads(-1), Error);
}

// Eigen's parallel products (a sparse matrix times a vector) take the same count: solver.threads = 1 runs
// on one thread.
TEST(Threads, EigensProductsFollowTheCount) {
  ThreadsGuard guard;
  for (int threads : {1, 3, 2}) {
    set_assembly_threads(threads);
    EXPECT_EQ(eigen_product_threads(), threads);
  }
  set_assembly_threads(0);
  EXPECT_EQ(eigen_product_threads(), default_assembly_threads());
}

}  // namespace
}  // namespace pc

// Terms over the same region and spaces share one geometry and one block pattern through a
// TermAssemblyCache, and assemble exactly what terms with copies of their own assemble (bit for bit): the
// cache changes where the data lives, not a digit of the results.
#include <gtest/gtest.h>

#include <memory>

#include "assembly/mesh_generators.hpp"
#include "assembly/pointwise_term.hpp"
#include "assembly/term_assembly.hpp"
#include "assembly/term_assembly_cache.hpp"

namespace pc {
namespace {

// Two kernels on one scalar field u: a diffusion (gradients) and a cubic reaction (values, a nonlinear
// tangent), over cells or faces.
struct Diffusion {
  double k;
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    for (int d = 0; d < in.dim; ++d) out.f1[0][0][d] = k * in.grad[0][0][d];
  }
};
struct Reaction {
  double c;
  template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
    out.f0[0][0] = c * in.value[0][0] * in.value[0][0] * in.value[0][0];
  }
};

template <class Kernel> std::shared_ptr<const Term> term(Integration integration, Kernel kernel) {
  const bool gradient = integration == Integration::Cells;  // faces have none
  return std::make_shared<PointwiseTerm<Kernel>>("test term", integration, std::vector<FieldUse>{{"u", gradient}},
                                                 std::vector<int>{0}, std::vector<Coupling>{{0, 0}}, kernel);
}

class TermAssemblyCacheTest : public ::testing::Test {
 protected:
  std::shared_ptr<const Mesh> mesh =
      std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {2, 1}, 6, 3, Shape::Triangle));
  FESpace space{mesh, 2, 1};
  FESpace p1_space{mesh, 1, 1};  // that no term of the tests uses
  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(space.num_dofs(), -1.0, 2.0);

  // Residual and tangent values of an assembly at u.
  static std::pair<Eigen::VectorXd, std::vector<double>> assembled(TermAssembly& a, const Eigen::VectorXd& u) {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(u.size());
    const Eigen::VectorXd* values[] = {&u};
    Eigen::VectorXd* residuals[] = {&r};
    a.assemble(values, 0.0, residuals, true);
    const CsrMatrix& K = a.block(0);
    return {r, std::vector<double>(K.valuePtr(), K.valuePtr() + K.nonZeros())};
  }
};

TEST_F(TermAssemblyCacheTest, TermsOverOneRegionAndSpaceShareOneGeometryAndPattern) {
  TermAssemblyCache cache(*mesh);
  TermAssembly diffusion(term(Integration::Cells, Diffusion{1.5}), "all", {&space}, cache);
  TermAssembly reaction(term(Integration::Cells, Reaction{0.5}), "all", {&space}, cache);
  // Both kernels ask for degree 2 * order: one geometry, one pattern, two blocks of values.
  EXPECT_EQ(&diffusion.geometry(), &reaction.geometry());
  EXPECT_EQ(cache.geometry("all", 4).get(), &diffusion.geometry());
  EXPECT_EQ(cache.pattern(cache.geometry("all", 4), space, space).get(),
            cache.pattern(cache.geometry("all", 4), space, space).get());
  EXPECT_NE(diffusion.block(0).valuePtr(), reaction.block(0).valuePtr());
  // The two blocks are their own values over one pattern's arrays.
  EXPECT_EQ(diffusion.block(0).innerIndexPtr(), reaction.block(0).innerIndexPtr());
  EXPECT_EQ(diffusion.block(0).outerIndexPtr(), reaction.block(0).outerIndexPtr());
  // A pattern is of the region's elements and the spaces: a geometry of another degree has the same one.
  const auto held = cache.pattern(cache.geometry("all", 4), space, space);
  EXPECT_EQ(cache.pattern(cache.geometry("all", 1), space, space).get(), held.get());
  // Held weakly: a pattern no one holds any more is freed, and made again, the same, when asked for.
  std::weak_ptr<const BlockPattern> weak;
  std::vector<int> outer, inner;
  {
    const auto lone = cache.pattern(cache.geometry("all", 4), space, p1_space);
    weak = lone;
    outer = lone->outer;
    inner = lone->inner;
  }
  EXPECT_TRUE(weak.expired());
  const auto again = cache.pattern(cache.geometry("all", 4), space, p1_space);
  EXPECT_EQ(again->outer, outer);
  EXPECT_EQ(again->inner, inner);
  TermAssembly bottom(term(Integration::Faces, Reaction{2.0}), "bottom", {&space}, cache);
  EXPECT_NE(&bottom.geometry(), &diffusion.geometry());
  EXPECT_EQ(&bottom.geometry().mesh(), mesh.get());
}

TEST_F(TermAssemblyCacheTest, SharedAndOwnCopiesAssembleTheSameBits) {
  TermAssemblyCache cache(*mesh);
  for (const auto& [t, region] : {std::pair{term(Integration::Cells, Diffusion{1.5}), "all"},
                                  std::pair{term(Integration::Cells, Reaction{0.5}), "all"},
                                  std::pair{term(Integration::Faces, Reaction{2.0}), "bottom"}}) {
    TermAssembly shared(t, region, {&space}, cache), own(t, region, {&space});
    const auto [r_shared, k_shared] = assembled(shared, u);
    const auto [r_own, k_own] = assembled(own, u);
    EXPECT_TRUE(r_shared == r_own) << region;
    EXPECT_EQ(k_shared, k_own) << region;
    EXPECT_TRUE(same_pattern(shared.block(0), own.block(0))) << region;
  }
}

// A term that releases its geometry (a linear term, once assembled) lets the cache free it when no other
// term holds it; assembled again, it makes the geometry again from the cache and gives the same bits.
TEST_F(TermAssemblyCacheTest, AReleasedGeometryIsFreedAndMadeAgainTheSame) {
  TermAssemblyCache cache(*mesh);
  TermAssembly diffusion(term(Integration::Cells, Diffusion{1.5}), "all", {&space}, cache);
  TermAssembly reaction(term(Integration::Cells, Reaction{0.5}), "all", {&space}, cache);
  const auto first = assembled(diffusion, u);
  std::weak_ptr<const RegionGeometry> held = cache.geometry("all", 4);
  diffusion.release_geometry();
  EXPECT_FALSE(held.expired()) << "the reaction still holds it";
  reaction.release_geometry();
  EXPECT_TRUE(held.expired()) << "no term holds it: freed";
  const auto again = assembled(diffusion, u);
  EXPECT_TRUE(again.first == first.first);
  EXPECT_EQ(again.second, first.second);
  // Made again, and kept from then on: a second release does nothing.
  const RegionGeometry* remade = &diffusion.geometry();
  diffusion.release_geometry();
  EXPECT_EQ(&diffusion.geometry(), remade);
  EXPECT_EQ(cache.geometry("all", 4).get(), remade);
  // A term with a geometry of its own (no cache) keeps it.
  TermAssembly own(term(Integration::Cells, Diffusion{1.5}), "all", {&space});
  const RegionGeometry* kept = &own.geometry();
  own.release_geometry();
  EXPECT_EQ(&own.geometry(), kept);
}

TEST_F(TermAssemblyCacheTest, RefusesAPatternOfAnotherMesh) {
  TermAssemblyCache cache(*mesh);
  const auto other = std::make_shared<const Mesh>(rectangle_mesh({0, 0}, {1, 1}, 2, 2, Shape::Triangle));
  const FESpace other_space(other, 1, 1);
  EXPECT_THROW(cache.pattern(cache.geometry("all", 2), other_space, other_space), Error);
}

}  // namespace
}  // namespace pc

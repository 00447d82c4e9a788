// "Model only what a scene requires": for the paper's strip (coarse mesh), each variant of the physics
// gets exactly the bricks and fields it needs, and nothing else.
//   (a) purely mechanical (no E, no beta)   (b) piezoelectric, insulated foundation
//   (c) conductive foundation               (d) quasi-static (rho = 0)
// plus: friction "none" -> no friction brick; no contact region -> no contact bricks; zero loads in a
// scene file -> no source bricks.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "models/scene/scene.hpp"

namespace pc {
namespace {

using ::testing::ElementsAre;
using ::testing::UnorderedElementsAreArray;

const std::string kScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";

Scene paper(std::vector<std::string> overrides = {}) {
  overrides.insert(overrides.begin(), {"mesh.nx=15", "mesh.ny=5"});
  return load_scene_file(kScene, overrides);
}

// The paper's spec with the foundation `name` ("insulated" or "conductive").
PiezoContactSpec paper_spec(const std::string& name = "insulated") {
  const Scene scene = paper();
  PiezoContactSpec spec = scene.spec;
  spec.foundation = find_foundation(scene, name).law;
  return spec;
}

std::vector<std::string> brick_names(const Model& m) {
  std::vector<std::string> names;
  for (const auto& b : m.bricks()) names.push_back(b->name());
  return names;
}

std::map<std::string, FieldKind> fields(const Model& m) {
  std::map<std::string, FieldKind> kinds;
  for (const std::string& f : m.field_names()) kinds[f] = m.field_kind(f);
  return kinds;
}

int total_dofs(const Model& m) {
  int n = 0;
  for (const std::string& u : m.unknowns()) n += m.space(u).num_dofs();
  return n;
}

// The bricks every variant of the paper's scene has: the mechanics, its boundary conditions and contact.
const std::vector<std::string> kMechanical = {
    "elasticity (B) on all", "viscosity (A) on all",      "Dirichlet condition on v over left",
    "traction on top",       "normal response on bottom", "friction on bottom"};
const std::vector<std::string> kElectric = {"piezoelectric coupling (E) on all", "permittivity (beta) on all",
                                            "Dirichlet condition on phi over top"};
const std::string kInertia = "inertia (rho) on all";
const std::string kFoundation = "conductive foundation on bottom";

std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

const auto U = FieldKind::Unknown;
const auto D = FieldKind::Data;
const auto A = FieldKind::Affine;

TEST(Recipe, PurelyMechanicalContactHasNoPotentialAndNoElectricBricks) {
  PiezoContactSpec spec = paper_spec();
  spec.E.resize(0, 0);
  spec.beta.resize(0, 0);
  const PiezoContactModel built = build_piezo_contact_model(spec);
  const Model& m = *built.model;
  EXPECT_FALSE(built.electric);
  EXPECT_THAT(brick_names(m), UnorderedElementsAreArray(kMechanical + std::vector<std::string>{kInertia}));
  EXPECT_EQ(fields(m), (std::map<std::string, FieldKind>{{"v", U}, {"u", A}, {"u_prev", D}, {"a", A}, {"v_prev", D}}));
  EXPECT_THAT(m.unknowns(), ElementsAre("v"));
  EXPECT_EQ(total_dofs(m), 2 * m.mesh().num_nodes());
}

TEST(Recipe, InsulatedFoundationAddsThePotentialButNoFoundationBrick) {
  const PiezoContactModel built = build_piezo_contact_model(paper_spec("insulated"));
  const Model& m = *built.model;
  EXPECT_TRUE(built.electric);
  EXPECT_THAT(brick_names(m), UnorderedElementsAreArray(kMechanical + kElectric + std::vector<std::string>{kInertia}));
  EXPECT_EQ(fields(m),
            (std::map<std::string, FieldKind>{{"v", U}, {"phi", U}, {"u", A}, {"u_prev", D}, {"a", A}, {"v_prev", D}}));
  EXPECT_THAT(m.unknowns(), ElementsAre("v", "phi"));
  EXPECT_EQ(total_dofs(m), 3 * m.mesh().num_nodes());
}

TEST(Recipe, ConductiveFoundationAddsExactlyOneFoundationBrick) {
  const PiezoContactModel built = build_piezo_contact_model(paper_spec("conductive"));
  const Model& m = *built.model;
  EXPECT_THAT(brick_names(m),
              UnorderedElementsAreArray(kMechanical + kElectric + std::vector<std::string>{kInertia, kFoundation}));
  EXPECT_EQ(fields(m),
            (std::map<std::string, FieldKind>{{"v", U}, {"phi", U}, {"u", A}, {"u_prev", D}, {"a", A}, {"v_prev", D}}));
  EXPECT_EQ(total_dofs(m), 3 * m.mesh().num_nodes());
}

TEST(Recipe, QuasiStaticModelHasNoInertiaBrickAndNoAccelerationFields) {
  PiezoContactSpec spec = paper_spec();
  spec.rho = 0;
  const PiezoContactModel built = build_piezo_contact_model(spec);
  const Model& m = *built.model;
  EXPECT_THAT(brick_names(m), UnorderedElementsAreArray(kMechanical + kElectric));
  EXPECT_EQ(fields(m), (std::map<std::string, FieldKind>{{"v", U}, {"phi", U}, {"u", A}, {"u_prev", D}}));
  EXPECT_FALSE(m.has_constant("rho"));
  EXPECT_EQ(total_dofs(m), 3 * m.mesh().num_nodes());
}

TEST(Recipe, FrictionNoneCreatesNoFrictionBrick) {
  PiezoContactSpec spec = paper_spec();
  spec.friction = {"none", {}};
  const PiezoContactModel built = build_piezo_contact_model(spec);
  const Model& m = *built.model;
  EXPECT_THAT(brick_names(m),
              UnorderedElementsAreArray(std::vector<std::string>{"elasticity (B) on all", "viscosity (A) on all",
                                                                 kInertia, "Dirichlet condition on v over left",
                                                                 "traction on top", "normal response on bottom"} +
                                        kElectric));
}

TEST(Recipe, NoContactRegionCreatesNoContactBricks) {
  PiezoContactSpec spec = paper_spec();
  spec.contact.clear();
  const PiezoContactModel built = build_piezo_contact_model(spec);
  const Model& m = *built.model;
  EXPECT_THAT(brick_names(m), UnorderedElementsAreArray(
                                  std::vector<std::string>{"elasticity (B) on all", "viscosity (A) on all", kInertia,
                                                           "Dirichlet condition on v over left", "traction on top"} +
                                  kElectric));
  EXPECT_TRUE(m.diagnostics().empty());
  EXPECT_EQ(built.normal, nullptr);
}

// The paper's scene has f0 = [0, 0] and q0 = q_b = 0: no body-force or charge brick. Non-zero values
// create exactly one body-force brick, one volume-charge brick and one surface-charge brick per
// region of regions.charge, so the absence above is the loader's decision and not a naming accident.
TEST(Recipe, ZeroLoadsInASceneCreateNoSourceBricks) {
  auto sources = [](const Scene& scene) {
    std::vector<std::string> found;
    for (const std::string& name : brick_names(*build_piezo_contact_model(scene.spec).model))
      for (const char* kind : {"body force", "volume charge", "surface charge"})
        if (name.rfind(kind, 0) == 0) found.push_back(name);
    return found;
  };
  const Scene zero = paper();
  ASSERT_EQ(zero.json.at("loads").at("f0").as_vector(2), (std::vector<double>{0.0, 0.0}));
  ASSERT_EQ(zero.json.at("loads").at("q0").as_number(), 0.0);
  ASSERT_EQ(zero.json.at("loads").at("q_b").as_number(), 0.0);
  EXPECT_TRUE(sources(zero).empty());

  const Scene loaded = paper({"loads.f0=[0, -1]", "loads.q0=1e-3", "loads.q_b=1e-4"});
  EXPECT_THAT(sources(loaded),
              UnorderedElementsAreArray(std::vector<std::string>{"body force on all", "volume charge on all",
                                                                 "surface charge on left", "surface charge on right"}));
}

}  // namespace
}  // namespace pc

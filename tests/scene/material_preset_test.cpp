// Scene materials by name: "material": {"preset": ..., "poling": ...} gives the tensors of the written-out
// scenes (paper2d.json in 2D, box3d.json's in 3D), keys given next to the preset override it, and an
// unknown preset, a missing or out-of-plane poling axis are refused with the scene path.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "assembly/error.hpp"
#include "models/scene/scene.hpp"
#include "support/shipped_scenes.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

using testing::error_of;

const std::string& kPaper = testing::kPaperScene;
const std::string& kBox = testing::kBoxScene;

// box3d.json on a generated mesh (its own is meshed by gmsh), with the generator's region names.
const std::vector<std::string> kGeneratedBox = [] {
  std::vector<std::string> overrides = testing::generated_box(3, 1, 1, "hexahedron");
  overrides.insert(overrides.end(),
                   {"output.probes.corner=[0.03, 0.01, 0.005]", "output.probes.center=[0.015, 0.005, 0.005]"});
  return overrides;
}();

std::vector<std::string> with(std::vector<std::string> overrides, const std::string& more) {
  overrides.push_back(more);
  return overrides;
}

// Entry by entry, relative to the largest entry of `expected` (the written scenes round to 5 or 6 digits).
void expect_close(const Eigen::MatrixXd& actual, const Eigen::MatrixXd& expected, double relative,
                  const std::string& what) {
  ASSERT_EQ(actual.rows(), expected.rows()) << what;
  ASSERT_EQ(actual.cols(), expected.cols()) << what;
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), relative * expected.cwiseAbs().maxCoeff())
      << what << ":\n"
      << actual << "\nexpected\n"
      << expected;
}

TEST(MaterialPreset, Pzt5hPoledAlongYGivesThePaperScenesTensors) {
  const Scene explicit_scene = load_scene_file(kPaper);
  const Scene preset = load_scene_file(
      kPaper, {R"(material={"preset": "PZT-5H", "poling": "y", "rho": 7800, "viscosity_tau_v": 0.01})"});
  const PiezoContactSpec &a = preset.spec, &b = explicit_scene.spec;
  EXPECT_EQ(a.rho, b.rho);
  // paper2d.json writes the six-digit constants, the permittivities to five digits.
  EXPECT_EQ(a.B, b.B);
  EXPECT_EQ(a.E, b.E);
  expect_close(a.beta, b.beta, 5e-5, "beta");
  expect_close(a.A, b.A, 1e-14, "A = tau_v B");
}

TEST(MaterialPreset, Pzt5hPoledAlongYIn3dGivesTheBoxScenesTensors) {
  const Scene explicit_scene = load_scene_file(kBox, kGeneratedBox);
  const Scene preset = load_scene_file(
      kBox,
      with(kGeneratedBox, R"(material={"preset": "PZT-5H", "poling": "y", "rho": 7800, "viscosity_tau_v": 0.01})"));
  const PiezoContactSpec &a = preset.spec, &b = explicit_scene.spec;
  ASSERT_EQ(a.B.rows(), 6);
  EXPECT_EQ(a.rho, b.rho);
  // box3d.json rounds the stiffnesses to five digits.
  expect_close(a.B, b.B, 5e-5, "B");
  EXPECT_EQ(a.E, b.E);
  expect_close(a.beta, b.beta, 5e-5, "beta");
  expect_close(a.A, b.A, 5e-5, "A");
}

TEST(MaterialPreset, KeysGivenNextToThePresetOverrideIt) {
  // Without rho, the preset's density (the data sheet's 7500, not the paper's 7800).
  const Scene plain = load_scene_file(kPaper, {R"(material={"preset": "PZT-5H", "poling": "y"})"});
  EXPECT_EQ(plain.spec.rho, 7500.0);
  EXPECT_EQ(plain.spec.A.size(), 0) << "no viscosity unless given";
  const Scene other = load_scene_file(
      kPaper, {R"(material={"preset": "PZT-5H", "poling": "y", "elasticity_B": [[2, 1, 0], [1, 2, 0], [0, 0, 1]],
                            "permittivity_beta": [[1, 0], [0, 2]], "viscosity_tau_v": 0.5})"});
  Eigen::MatrixXd B(3, 3), beta(2, 2);
  B << 2, 1, 0, 1, 2, 0, 0, 0, 1;
  beta << 1, 0, 0, 2;
  EXPECT_EQ(other.spec.B, B);
  EXPECT_EQ(other.spec.A, 0.5 * B) << "tau_v multiplies the B in force";
  EXPECT_EQ(other.spec.beta, beta);
  EXPECT_EQ(other.spec.E, plain.spec.E) << "the preset's piezo_E, as not given";
  // Poled along x, the coupling turns with it.
  const Scene x = load_scene_file(kPaper, {R"(material={"preset": "PZT-5H", "poling": "x"})"});
  EXPECT_EQ(x.spec.E(0, 0), plain.spec.E(1, 1));
  EXPECT_EQ(x.spec.beta(0, 0), plain.spec.beta(1, 1));
}

TEST(MaterialPreset, AnUnknownPresetIsRefusedNamingTheKnownOnesAndNothingElse) {
  EXPECT_EQ(error_of([] { load_scene_file(kPaper, {R"(material={"preset": "PZT-5X", "poling": "y"})"}); }),
            "scene 'paper2d' has 1 problem:\n"
            "  - 'material.preset': unknown piezoelectric material 'PZT-5X' (known: BaTiO3, PZT-4, PZT-5A, PZT-5H); "
            "did you mean 'PZT-5A' or 'PZT-5H'?");
}

TEST(MaterialPreset, ThePolingAxisIsRequiredKnownAndInThePlaneOfA2dModel) {
  const auto problem = [](const std::string& material) {
    return error_of([&] { load_scene_file(kPaper, {"material=" + material}); });
  };
  EXPECT_EQ(problem(R"({"preset": "PZT-4"})"),
            "scene 'paper2d' has 1 problem:\n  - 'material.poling' is required with 'material.preset': the poling "
            "axis, x, y or z (the preset's tables are poled along z)");
  EXPECT_EQ(problem(R"({"preset": "PZT-4", "poling": "w"})"),
            "scene 'paper2d' has 1 problem:\n  - 'material.poling': unknown axis 'w' (known: x, y, z)");
  EXPECT_EQ(problem(R"({"preset": "PZT-4", "poling": "z"})"),
            "scene 'paper2d' has 1 problem:\n  - 'material.poling' is z, but a 2D model (plane strain in x-y) is "
            "poled in its plane: x or y");
  const std::string no_preset =
      problem(R"({"rho": 1, "elasticity_B": [[2, 1, 0], [1, 2, 0], [0, 0, 1]], "poling": "y"})");
  EXPECT_NE(no_preset.find("'material.poling' goes with 'material.preset'"), std::string::npos) << no_preset;
  // 3D may be poled along z; the 3D box poled along z has c33 on zz.
  const Scene z = load_scene_file(kBox, with(kGeneratedBox, R"(material={"preset": "BaTiO3", "poling": "z"})"));
  EXPECT_EQ(z.spec.B(2, 2), 1.62e11);
  EXPECT_EQ(z.spec.rho, 5700.0);
}

}  // namespace
}  // namespace pc

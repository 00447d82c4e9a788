// One rule for keys (docs/scenes.md, "Keys: used or refused"): the walk over every key of a scene whose
// mesh is a gmsh script (tests/data/rectangle.geo); the generated scene's is scene_keys_rule_test.cpp.
#include <gtest/gtest.h>

#include "scene/scene_keys_walk.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

const std::string kGeo = std::string(PIEZOCONTACT_TEST_DATA) + "/rectangle.geo";

// The walk's scene on rectangle.geo: the paper's strip, its sides the script's groups.
Json gmsh_scene() {
  return testing::scene_with_every_object(
      {R"(mesh={"gmsh": ")" + kGeo + R"(", "order": 1})",
       R"(regions={"clamped": ["clamped"], "traction": ["top"], "contact": "contact", "grounded": ["top"], )"
       R"("charge": ["clamped"]})",
       "loads.traction[0].region=top"},
      "clamped");
}

TEST(SceneKeysRuleGmsh, EveryKeyOfAGmshSceneIsReadOrRefusedSayingWhy) {
  std::vector<testing::KeyAnswer> answers = testing::answers_beyond_the_mesh("clamped");
  const std::string generated = "applies to generated meshes (mesh.generator); this scene reads the gmsh file '" + kGeo;
  answers.insert(answers.end(), {{"mesh.generator", "rectangle", "gives both generator and gmsh"},
                                 {"mesh.gmsh", kGeo, ""},
                                 {"mesh.x", "[0, 0.03]", generated},
                                 {"mesh.y", "[0, 0.01]", generated},
                                 {"mesh.z", "[0, 0.01]", generated},
                                 {"mesh.nx", "30", generated},
                                 {"mesh.ny", "10", generated},
                                 {"mesh.nz", "4", generated},
                                 {"mesh.cell", "quadrilateral", generated},
                                 {"mesh.order", "2", ""},
                                 {"mesh.size_factor", "1.5", ""},
                                 {"mesh.max_seconds", "60", ""},
                                 {"target_error", "0.1", "chooses the mesh size of a generated mesh"}});
  testing::walk_every_key(gmsh_scene(), answers);
}

TEST(SceneKeysRuleGmsh, TheKeysOfAGmshMeshAreRead) {
  const auto cells = [](const std::string& size_factor) {
    Json json = gmsh_scene();
    apply_overrides(json, {"mesh.size_factor=" + size_factor, "mesh.max_seconds=60"});
    return load_scene(json, PIEZOCONTACT_SCENES).spec.mesh->num_cells();
  };
  EXPECT_GT(cells("1"), 2 * cells("2")) << "a coarser script mesh";
}

}  // namespace
}  // namespace pc

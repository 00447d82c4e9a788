#pragma once
// The shipped scenes the tests run, and box3d.json's overrides for a generated box mesh in its place
// (its own is meshed by gmsh): the generator's region names for the scene's regions and loads.
#include <string>
#include <vector>

namespace pc::testing {

inline const std::string kPaperScene = std::string(PIEZOCONTACT_SCENES) + "/paper2d.json";
inline const std::string kBoxScene = std::string(PIEZOCONTACT_SCENES) + "/box3d.json";

// box3d.json's box (0, 0.03) x (0, 0.01) x (0, 0.01) as nx x ny x nz generated cells of the shape, P1.
inline std::vector<std::string> generated_box(int nx, int ny, int nz, const std::string& cell) {
  return {R"(mesh={"generator": "box", "x": [0, 0.03], "y": [0, 0.01], "z": [0, 0.01], "nx": )" + std::to_string(nx) +
              R"(, "ny": )" + std::to_string(ny) + R"(, "nz": )" + std::to_string(nz) + R"(, "cell": ")" + cell +
              R"(", "order": 1})",
          R"(regions={"clamped": ["xmin"], "traction": ["ymax"], "contact": "ymin", "grounded": ["ymax"], )"
          R"("charge": ["xmax"]})",
          "loads.traction[0].region=ymax"};
}

}  // namespace pc::testing

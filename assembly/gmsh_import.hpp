#pragma once
// Meshes from gmsh through its C++ API: a .msh file, or a .geo script that is meshed on the fly.
// Physical groups of the highest dimension become cell regions, those of one dimension lower face
// regions, each named by the group's name (or "physical_<tag>" when it has none).
#include <string>

#include "assembly/mesh.hpp"

namespace pc {

struct GmshOptions {
  double mesh_size_factor = 1.0;  // scales the characteristic lengths of a .geo script
  int verbosity = 0;              // gmsh's General.Verbosity
};

// Throws when the file does not exist, gmsh cannot read it, it holds no cells, mixes cell shapes, or
// has second-order geometry. Each call initializes and finalizes gmsh itself: do not call it while the
// caller's own code holds gmsh initialized.
Mesh import_gmsh(const std::string& path, const GmshOptions& options = {});

}  // namespace pc

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
  // Budgets of meshing a .geo script (0: none): a mesh size far too small would otherwise mesh for hours
  // or until the memory is gone.
  double max_seconds = 0;
  double max_memory_bytes = 0;
};

// gmsh reads the file, and runs and meshes a .geo script, in a child process of its own, so that
// whatever the input does (an `Exit;` in a script, a malformed .msh that crashes libgmsh's reader, a mesh
// past a budget, gmsh's terminal output) cannot end, hang or clutter the caller; the child hands back
// the mesh as a binary .msh file that gmsh itself wrote, which this process reads.
//
// Throws when the file does not exist, gmsh cannot read it, it holds no cells, mixes cell shapes, or
// has second-order geometry, or when meshing a script ends early or exceeds a budget. Each call initializes and
// finalizes gmsh itself: do not call it while the caller's own code holds gmsh initialized.
Mesh import_gmsh(const std::string& path, const GmshOptions& options = {});

}  // namespace pc
